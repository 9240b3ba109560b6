#!/usr/bin/env python3
"""The design search at scale (issue 9): generated problems, witness vs exhaustive search.

  python3 tests/benchmarks/design_scale/run.py [--runs 3] [--time-limit 120]
      [--sizes warehouse:64x10,rules:8x3] [--exhaustive-max N] [--seed 1]
      [--csv OUT.csv] [--markdown docs/results/design-scale.md] [--keep DIR] [--ranking N]

For each size KIND:N[xTASKS] it generates a problem with generate.py (N candidate
modifications, TASKS tasks, default 10 for the warehouse and 3 for rules) and runs
`envdesign design SPEC --json --workers 1 --time-limit L --search witness`, then the same with
`--search exhaustive` where N is at most the kind's cap (warehouse 18, rules 12; or
--exhaustive-max). Each run is repeated --runs times; seconds are the median wall time of the
process (loading, grounding and search). Prints per problem: configurations evaluated
(`configurations_evaluated`) and visited (`configurations_visited`, when the binary reports
it), planner runs, seconds, status, the proven gap when a limit stopped it, the objective and
the design's size (with --ranking N, the witness search lists the N best: `ranked` says how
many it listed, `ranked_last` the last one's objective); beside them the exhaustive search's figures, the time ratio exhaustive /
witness, and whether both chose the same design and objective.
"""
import argparse
import csv
import datetime
import json
import math
import os
import platform
import statistics
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(os.path.dirname(HERE)))
DEFAULT_SIZES = ",".join([f"warehouse:{n}x10" for n in (12, 16, 24, 32, 48, 64, 128, 256)] +
                         [f"warehouse:{n}x3" for n in (12, 16, 24)] +
                         [f"rules:{n}x3" for n in (6, 8, 10)])
EXHAUSTIVE_MAX = {"warehouse": 18, "rules": 12}
COLUMNS = ["kind", "n", "tasks", "evaluated", "visited", "planner_runs", "seconds", "status",
           "gap", "objective", "design_size", "exh_evaluated", "exh_planner_runs", "exh_seconds",
           "exh_status", "ratio", "same_design", "same_objective", "ranked", "ranked_last"]


def parse_size(text):
    kind, _, rest = text.strip().partition(":")
    mods, _, tasks = rest.partition("x")
    if kind not in EXHAUSTIVE_MAX or not mods.isdigit() or (tasks and not tasks.isdigit()):
        raise argparse.ArgumentTypeError(f"bad size {text!r}: KIND:N[xTASKS], KIND "
                                         f"{' or '.join(EXHAUSTIVE_MAX)}")
    return kind, int(mods), int(tasks) if tasks else (10 if kind == "warehouse" else 3)


def generate(kind, mods, tasks, seed, out):
    subprocess.run([sys.executable, os.path.join(HERE, "generate.py"), "--kind", kind,
                    "--mods", str(mods), "--tasks", str(tasks), "--seed", str(seed),
                    "--out", out], check=True)
    return os.path.join(out, "spec.textproto")


def design(binary, spec, search, time_limit, ranking=0):
    """One run: the JSON result with "wall" added, or {"status": "error N", ...}."""
    command = [binary, "--log-level", "warn", "design", spec, "--json", "--workers", "1",
               "--time-limit", str(time_limit), "--search", search]
    if ranking:
        command += ["--ranking", str(ranking)]
    start = time.perf_counter()
    proc = subprocess.run(command, capture_output=True, text=True)
    wall = time.perf_counter() - start
    if proc.returncode not in (0, 4) or not proc.stdout.strip():
        last = (proc.stderr.strip().splitlines() or [""])[-1]
        print(f"  {search}: exit {proc.returncode}: {last}", file=sys.stderr)
        return {"status": f"error {proc.returncode}", "wall": wall}
    result = json.loads(proc.stdout)
    result["wall"] = wall
    return result


def repeated(binary, spec, search, args):
    """--runs runs; the first run's counters and design, the median wall time."""
    ranking = args.ranking if search == "witness" else 0
    results = [design(binary, spec, search, args.time_limit, ranking) for _ in range(args.runs)]
    first = dict(results[0])
    first["wall"] = statistics.median(r["wall"] for r in results)
    statuses = sorted({r["status"] for r in results})
    first["status"] = "/".join(statuses)
    return first


def number(value):
    return math.inf if value == "inf" else float(value)


def same_objective(a, b):
    x, y = number(a), number(b)
    return x == y or abs(x - y) <= 1e-6 * max(1.0, abs(x), abs(y))


def row_of(kind, mods, tasks, witness, exhaustive):
    row = {"kind": kind, "n": mods, "tasks": tasks,
           "evaluated": witness.get("configurations_evaluated", ""),
           "visited": witness.get("configurations_visited", witness.get("configurations_total", "")),
           "planner_runs": witness.get("planner_runs", ""),
           "seconds": f"{witness['wall']:.2f}", "status": witness["status"],
           "gap": witness.get("gap", ""),
           "objective": witness.get("objective", ""),
           "design_size": len(witness["design"]) if "design" in witness else "",
           "design": " ".join(witness.get("design", []))}
    if witness.get("ranking"):
        row.update({"ranked": len(witness["ranking"]),
                    "ranked_last": witness["ranking"][-1]["objective"]})
    if exhaustive:
        both = "design" in witness and "design" in exhaustive
        row.update({"exh_evaluated": exhaustive.get("configurations_evaluated", ""),
                    "exh_planner_runs": exhaustive.get("planner_runs", ""),
                    "exh_seconds": f"{exhaustive['wall']:.2f}",
                    "exh_status": exhaustive["status"],
                    "ratio": f"{exhaustive['wall'] / witness['wall']:.1f}",
                    "same_design": both and witness["design"] == exhaustive["design"],
                    "same_objective": both and same_objective(witness["objective"],
                                                              exhaustive["objective"])})
    return row


def cells(row):
    values = [row.get(c, "") for c in COLUMNS]
    return [("yes" if v else "NO") if isinstance(v, bool) else
            (f"{v:.4g}" if isinstance(v, float) else str(v)) for v in values]


def print_table(rows):
    table = [COLUMNS] + [cells(r) for r in rows]
    widths = [max(len(line[i]) for line in table) for i in range(len(COLUMNS))]
    for line in table:
        print("  ".join(v.rjust(w) for v, w in zip(line, widths)))


def source_state():
    """The commit of the tree and whether it has uncommitted changes, as text."""
    commit = subprocess.run(["git", "-C", ROOT, "rev-parse", "--short", "HEAD"],
                            capture_output=True, text=True).stdout.strip()
    if subprocess.run(["git", "-C", ROOT, "diff", "--quiet", "HEAD"]).returncode:
        commit += " with uncommitted changes"
    return commit


def write_markdown(path, rows, args, binary, commit):
    built = datetime.datetime.fromtimestamp(os.path.getmtime(os.path.realpath(binary)))
    shown = os.path.relpath(binary, ROOT)
    shown = binary if shown.startswith("..") else shown
    lines = ["# The design search at scale (issue 9)", "",
             "Made by (from the repository's root):", "",
             "    python3 tests/benchmarks/design_scale/run.py " + " ".join(sys.argv[1:]), "",
             f"{datetime.date.today()}, commit {commit} at the start, {platform.platform()}, "
             f"{os.cpu_count()} CPUs, 1 worker, binary `{shown}` "
             f"(modified {built:%Y-%m-%d %H:%M}). "
             f"Median of {args.runs} runs, time limit {args.time_limit} s, seed {args.seed}. "
             "`evaluated`: configurations_evaluated, `visited`: configurations_visited; "
             "`exh_*`: `--search exhaustive`; ratio: its seconds / the witness search's. "
             "The problems: tests/benchmarks/design_scale/generate.py (its top comment).", "",
             "| " + " | ".join(COLUMNS) + " |", "|" + "---|" * len(COLUMNS)]
    lines += ["| " + " | ".join(cells(r)) + " |" for r in rows]
    lines += ["", "Designs chosen by the witness search:", ""]
    lines += [f"- {r['kind']} n={r['n']} tasks={r['tasks']}: {r['design'] or '(empty)'}"
              for r in rows]
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--runs", type=int, default=3)
    parser.add_argument("--time-limit", type=float, default=120)
    parser.add_argument("--sizes", default=DEFAULT_SIZES,
                        help="comma-separated KIND:N[xTASKS] (default: %(default)s)")
    parser.add_argument("--exhaustive-max", type=int,
                        help="run --search exhaustive up to this n (default: warehouse 18, "
                             "rules 12; 0: never)")
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--binary", default=os.path.join(ROOT, "build", "bin", "envdesign"))
    parser.add_argument("--keep", help="write the problems here instead of a temp dir")
    parser.add_argument("--csv")
    parser.add_argument("--markdown")
    parser.add_argument("--ranking", type=int, default=0,
                        help="the witness search lists the N best designs (--ranking N)")
    args = parser.parse_args()
    try:
        sizes = [parse_size(s) for s in args.sizes.split(",") if s.strip()]
    except argparse.ArgumentTypeError as error:
        parser.error(str(error))
    rows, commit = [], source_state()
    with tempfile.TemporaryDirectory(prefix="design-scale-") as temp:
        for kind, mods, tasks in sizes:
            out = os.path.join(args.keep or temp, f"{kind}-{mods}x{tasks}-s{args.seed}")
            spec = generate(kind, mods, tasks, args.seed, out)
            print(f"{kind} n={mods} tasks={tasks}: {spec}", file=sys.stderr)
            witness = repeated(args.binary, spec, "witness", args)
            cap = EXHAUSTIVE_MAX[kind] if args.exhaustive_max is None else args.exhaustive_max
            exhaustive = repeated(args.binary, spec, "exhaustive", args) if mods <= cap else None
            rows.append(row_of(kind, mods, tasks, witness, exhaustive))
    print_table(rows)
    if args.csv:
        with open(args.csv, "w", newline="") as f:
            writer = csv.DictWriter(f, fieldnames=COLUMNS + ["design"])
            writer.writeheader()
            writer.writerows(rows)
    if args.markdown:
        write_markdown(args.markdown, rows, args, args.binary, commit)


if __name__ == "__main__":
    main()
