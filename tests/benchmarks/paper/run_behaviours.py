#!/usr/bin/env python3
"""The paper's Table 1 problems with robots that are not explicable planners (issue 14).

  python3 tests/benchmarks/paper/run_behaviours.py [--envdesign build/bin/envdesign]
      [--behaviour COST_OPTIMAL ...] [--domain blocksworld|grid|driverlog ...]
      [--horizon 1 --horizon 10] [--time-limit 1800] [--out docs/results] [--from-runs]

Runs `envdesign design SPEC --json --workers 1` on every design problem of Table 1
(tests/data/paper/<domain>/<nn>/design-t<T>.textproto), each copied with
`robot_behaviour: <B>` added (paper_runs.derived_spec), one after another under `nice -n 10`,
and writes to --out:
  behaviours-runs.jsonl  every engine result, with its behaviour and the process wall time;
  behaviours-runs.csv    one row per run;
  behaviours.md          Table 1's columns per behaviour, domain and horizon, beside the
                         EXPLICABLE rows of table1-runs.csv (run_table1.py), and how often
                         the chosen design differs from the EXPLICABLE one.
--from-runs rebuilds the tables from behaviours-runs.jsonl without running anything.
"""
import argparse
import csv
import json
import os
import sys
import tempfile

from paper_runs import (DATA, DOMAINS, DOMAIN_TITLES, ENVDESIGN, RESULTS, derived_spec,
                        environment_note, fmt, markdown_table, mean, number, percent_change,
                        quantile, run_measured, sd, target_line, write_csv)

FIELDS = ["behaviour", "domain", "problem", "horizon", "status", "design_size", "design",
          "ie_without", "ie_with", "plan_cost_without", "plan_cost_with", "total_without",
          "total_with", "wall_s", "cpu_s", "configurations_evaluated"]


def row_of(r):
    base, h = r["baseline"], r["horizon"]
    return {
        "behaviour": r["behaviour"], "domain": r["domain"], "problem": r["problem"],
        "horizon": h, "status": r["status"], "design_size": len(r["design"]),
        "design": "+".join(r["design"]),
        "ie_without": number(base["terms"]["inexplicability"]),
        "ie_with": number(r["terms"]["inexplicability"]),
        "plan_cost_without": number(base["terms"]["robot_cost"]) / h,
        "plan_cost_with": number(r["terms"]["robot_cost"]) / h,
        "total_without": number(base["objective"]), "total_with": number(r["objective"]),
        "wall_s": r["wall"], "cpu_s": r.get("cpu", float("nan")),
        "configurations_evaluated": r["configurations_evaluated"],
    }


def run_all(args, runs_path):
    problems = [(d, p) for d in args.domain for p in sorted(os.listdir(os.path.join(DATA, d)))
                if p.isdigit()]
    jobs = [(b, h, d, p) for b in args.behaviour for h in args.horizon for d, p in problems]
    with tempfile.TemporaryDirectory() as scratch, open(runs_path + ".partial", "w") as out:
        for i, (behaviour, horizon, domain, problem) in enumerate(jobs):
            spec = derived_spec(os.path.join(DATA, domain, problem, f"design-t{horizon}.textproto"),
                                scratch, robot_behaviour=behaviour)
            r = run_measured(args.envdesign, spec, args.time_limit, nice=args.nice)
            cpu = r["cpu"]
            r.update(behaviour=behaviour, domain=domain, problem=problem, horizon=horizon)
            out.write(json.dumps(r) + "\n")
            out.flush()
            print(f"[{i + 1}/{len(jobs)}] {behaviour} {domain} {problem} T={horizon}: "
                  f"{r['status']} {r['design']} in {r['wall']:.2f} s ({cpu:.2f} s CPU)",
                  file=sys.stderr)
    os.replace(runs_path + ".partial", runs_path)


def explicable_rows(out_dir):
    """The EXPLICABLE runs of run_table1.py, by (domain, problem, horizon)."""
    path = os.path.join(out_dir, "table1-runs.csv")
    rows = {}
    with open(path) as f:
        for row in csv.DictReader(f):
            rows[(row["domain"], row["problem"], int(row["horizon"]))] = row
    return rows


def group_line(label, domain, horizon, rows):
    pm = lambda values: f"{fmt(mean(values))} ± {fmt(sd(values))}"
    col = lambda name: [float(r.get(name, "nan")) for r in rows]
    optimal = sum(r["status"] == "optimal" for r in rows)
    times, cpu = col("wall_s"), col("cpu_s")
    return [DOMAIN_TITLES[domain], horizon, label, pm(col("design_size")), pm(col("ie_without")),
            pm(col("ie_with")), fmt(percent_change(mean(col("ie_without")), mean(col("ie_with"))), 1),
            pm(col("plan_cost_without")), pm(col("plan_cost_with")), pm(col("total_without")),
            pm(col("total_with")), f"{fmt(mean(times))} (max {fmt(max(times))})",
            f"{fmt(mean(cpu))} (max {fmt(max(cpu))})",
            f"{optimal}/{len(rows)}"]


def write_tables(args, runs_path):
    with open(runs_path) as f:
        runs = [json.loads(line) for line in f if line.strip()]
    rows = [row_of(r) for r in runs]
    write_csv(os.path.join(args.out, "behaviours-runs.csv"), FIELDS,
              [[row[k] for k in FIELDS] for row in rows])
    explicable = explicable_rows(args.out)
    header = ["Domain", "T", "Behaviour", "Design size", "IE w/o", "IE with", "IE %",
              "Plan cost w/o", "Plan cost with", "Total w/o", "Total with", "Wall (s)", "CPU (s)",
              "Proven optimal"]
    lines, differ_lines = [], []
    for domain in DOMAINS:
        for horizon in sorted({r["horizon"] for r in rows}):
            base = [explicable[k] for k in sorted(explicable)
                    if k[0] == domain and k[2] == horizon]
            if base:
                lines.append(group_line("EXPLICABLE (Table 1)", domain, horizon, base))
            for behaviour in args.behaviour:
                group = [r for r in rows if r["domain"] == domain and r["horizon"] == horizon
                         and r["behaviour"] == behaviour]
                if not group:
                    continue
                lines.append(group_line(behaviour, domain, horizon, group))
                other = [r for r in group if (domain, r["problem"], horizon) in explicable and
                         explicable[(domain, r["problem"], horizon)]["design"] != r["design"]]
                differ_lines.append([DOMAIN_TITLES[domain], horizon, behaviour,
                                     f"{len(other)}/{len(group)}",
                                     ", ".join(f"{r['problem']}: {r['design'] or '-'} (EXPLICABLE "
                                               f"{explicable[(domain, r['problem'], horizon)]['design'] or '-'})"
                                               for r in other[:4]) + (" ..." if len(other) > 4 else "")])
    times, cpu = [r["wall_s"] for r in rows], [r["cpu_s"] for r in rows]
    optimal = sum(r["status"] == "optimal" for r in rows)
    text = ["# Table 1 with robots that are not explicable planners", "",
            environment_note(args.envdesign, args.commit).replace(
                "`nice -n 10`", f"`nice -n {args.nice}`"), "",
            "Generated by `python3 tests/benchmarks/paper/run_behaviours.py`; per-run rows in "
            "`behaviours-runs.csv`, engine output in `behaviours-runs.jsonl`. The EXPLICABLE rows "
            "are Table 1's (`table1-runs.csv`, run_table1.py).", "",
            "COST_OPTIMAL: the robot runs some cost-optimal plan of its own model and the design "
            "must serve the worst of them (IE = the largest over all optimal plans; "
            "`docs/behaviours.md`). Robot cost is then c_R*.", "",
            markdown_table(header, lines), "",
            "Mean ± SD over the problems; IE is the objective's term f_T(E[IE]), plan cost "
            "E[c_R], total the objective; wall and CPU (user + system) seconds of one "
            "`envdesign design` process. Table 1's rows give its wall times, measured on a "
            "quieter machine; with other jobs loading both cores, our wall times here are "
            "several times our CPU times.", "",
            "## Where the chosen design differs from the explicable robot's", "",
            markdown_table(["Domain", "T", "Behaviour", "Differs", "Examples"], differ_lines), "",
            f"All {len(rows)} runs: {optimal} proven optimal; wall median "
            f"{fmt(quantile(times, 0.5))} s, p90 {fmt(quantile(times, 0.9))} s, max "
            f"{fmt(max(times))} s; CPU median {fmt(quantile(cpu, 0.5))} s, p90 "
            f"{fmt(quantile(cpu, 0.9))} s, max {fmt(max(cpu))} s.", "",
            "Against issue 24's target (every run within 10 s):", ""] + [
                "- " + target_line(b, [r for r in runs if r["behaviour"] == b])
                for b in sorted({r["behaviour"] for r in runs})] + [""]
    with open(os.path.join(args.out, "behaviours.md"), "w") as f:
        f.write("\n".join(text))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--envdesign", default=ENVDESIGN)
    parser.add_argument("--behaviour", action="append")
    parser.add_argument("--domain", action="append", choices=DOMAINS)
    parser.add_argument("--horizon", action="append", type=int)
    parser.add_argument("--time-limit", type=float, default=1800)
    parser.add_argument("--out", default=RESULTS)
    parser.add_argument("--from-runs", action="store_true")
    parser.add_argument("--commit", help="the commit the binary was built from (default HEAD)")
    parser.add_argument("--nice", type=int, default=10, help="niceness of each run (nice -n)")
    args = parser.parse_args()
    args.behaviour = args.behaviour or ["COST_OPTIMAL"]
    args.domain = args.domain or list(DOMAINS)
    args.horizon = args.horizon or [1, 10]
    runs_path = os.path.join(args.out, "behaviours-runs.jsonl")
    if not args.from_runs:
        run_all(args, runs_path)
    write_tables(args, runs_path)


if __name__ == "__main__":
    main()
