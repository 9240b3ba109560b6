#!/usr/bin/env python3
"""The paper's Table 1 (Section VI, "Performance on IPC domains"), with our engine.

  python3 tests/benchmarks/paper/run_table1.py [--envdesign build/bin/envdesign]
      [--domain blocksworld|grid|driverlog ...] [--horizon 1 --horizon 10]
      [--time-limit 1800] [--out docs/results] [--from-runs]

Runs `envdesign design SPEC --json --workers 1` on every design problem of
tests/data/paper/<domain>/<nn>/design-t<T>.textproto (generate_design_problems.py: 20 per
domain, alpha 1, beta 0.25, kappa 0.25, gamma 0.9), one after another under `nice -n 10`,
and writes to --out:
  table1-runs.jsonl  every engine result, with the wall time of the process;
  table1-runs.csv    one row per run;
  table1.csv         Table 1's columns per domain and horizon (mean and SD);
  table1.md          the same as Markdown, with the time distribution and where it goes.
--from-runs rebuilds the tables from table1-runs.jsonl without running anything.

Columns as in the paper (its numbers satisfy these identities): inexplicability is the
objective's term f_T(E[IE]); plan cost is E[c_R] (the term divided by T); total cost is the
objective; "% diff" compares the means (with - without) / without. SD is the sample SD.
"""
import argparse
import json
import math
import os
import sys

from paper_runs import (DATA, DOMAINS, DOMAIN_TITLES, ENVDESIGN, RESULTS, environment_note,
                        fmt, markdown_table, mean, number, percent_change, quantile, run_design,
                        sd, write_csv)

RUN_FIELDS = ["domain", "problem", "horizon", "status", "design_size", "design",
              "ie_without", "ie_with", "plan_cost_without", "plan_cost_with",
              "total_without", "total_with", "wall_s", "engine_s", "planner_s", "planner_runs",
              "cache_hits", "configurations_total", "configurations_evaluated",
              "configurations_abandoned", "configurations_skipped"]


def run_row(domain, problem, horizon, r):
    """One CSV row of a run from the engine's JSON result `r`."""
    base = r["baseline"]
    return {
        "domain": domain, "problem": problem, "horizon": horizon, "status": r["status"],
        "design_size": len(r["design"]), "design": "+".join(r["design"]),
        "ie_without": number(base["terms"]["inexplicability"]),
        "ie_with": number(r["terms"]["inexplicability"]),
        "plan_cost_without": number(base["terms"]["robot_cost"]) / horizon,
        "plan_cost_with": number(r["terms"]["robot_cost"]) / horizon,
        "total_without": number(base["objective"]), "total_with": number(r["objective"]),
        "wall_s": r["wall"], "engine_s": r["seconds"], "planner_s": r["planner_seconds"],
        "planner_runs": r["planner_runs"], "cache_hits": r["cache_hits"],
        "configurations_total": r["configurations_total"],
        "configurations_evaluated": r["configurations_evaluated"],
        "configurations_abandoned": r["configurations_abandoned"],
        "configurations_skipped": r["configurations_skipped"],
    }


def run_all(args, runs_path):
    problems = [(d, p) for d in args.domain for p in sorted(os.listdir(os.path.join(DATA, d)))
                if p.isdigit()]
    total = len(problems) * len(args.horizon)
    with open(runs_path + ".partial", "w") as out:
        for i, (horizon, (domain, problem)) in enumerate(
                (h, dp) for h in args.horizon for dp in problems):
            spec = os.path.join(DATA, domain, problem, f"design-t{horizon}.textproto")
            r = run_design(args.envdesign, spec, args.time_limit)
            r.update(domain=domain, problem=problem, horizon=horizon)
            out.write(json.dumps(r) + "\n")
            out.flush()
            print(f"[{i + 1}/{total}] {domain} {problem} T={horizon}: {r['status']} "
                  f"{r['design']} in {r['wall']:.2f} s", file=sys.stderr)
    os.replace(runs_path + ".partial", runs_path)


def summary(rows):
    """Table 1's line for the runs `rows` of one domain and horizon."""
    col = lambda name: [row[name] for row in rows]
    out = {"runs": len(rows), "optimal": sum(row["status"] == "optimal" for row in rows)}
    for name in ("design_size", "ie_without", "ie_with", "plan_cost_without", "plan_cost_with",
                 "total_without", "total_with", "wall_s"):
        out[name + "_mean"], out[name + "_sd"] = mean(col(name)), sd(col(name))
    for what in ("ie", "plan_cost", "total"):
        out[what + "_diff"] = percent_change(out[what + "_without_mean"], out[what + "_with_mean"])
    times = col("wall_s")
    out.update(wall_median=quantile(times, 0.5), wall_p90=quantile(times, 0.9),
               wall_max=max(times))
    for name in ("engine_s", "planner_s", "planner_runs", "cache_hits", "configurations_total",
                 "configurations_evaluated", "configurations_abandoned",
                 "configurations_skipped"):
        out[name + "_sum"] = sum(col(name))
    designed = [row for row in rows if row["design_size"] > 0]
    out["designed"] = len(designed)
    out["ie_dropped"] = sum(row["ie_with"] < row["ie_without"] for row in designed)
    out["plan_cost_rose"] = sum(row["plan_cost_with"] > row["plan_cost_without"] + 1e-9
                                for row in designed)
    out["plan_cost_same"] = sum(abs(row["plan_cost_with"] - row["plan_cost_without"]) <= 1e-9
                                for row in designed)
    return out


SUMMARY_FIELDS = ["domain", "horizon", "metric", "design_size", "ie_without", "ie_with",
                  "ie_diff_pct", "plan_cost_without", "plan_cost_with", "plan_cost_diff_pct",
                  "total_without", "total_with", "total_diff_pct", "time_s"]


def table1_lines(groups):
    """Per domain and horizon, a Mean and an SD line in Table 1's column order."""
    lines = []
    for (domain, horizon), s in groups:
        values = lambda stat: [s[f"design_size_{stat}"], s[f"ie_without_{stat}"],
                               s[f"ie_with_{stat}"], s["ie_diff"] if stat == "mean" else None,
                               s[f"plan_cost_without_{stat}"], s[f"plan_cost_with_{stat}"],
                               s["plan_cost_diff"] if stat == "mean" else None,
                               s[f"total_without_{stat}"], s[f"total_with_{stat}"],
                               s["total_diff"] if stat == "mean" else None, s[f"wall_s_{stat}"]]
        for stat, label in (("mean", "Mean"), ("sd", "SD")):
            lines.append([DOMAIN_TITLES[domain], horizon, label] + values(stat))
    return lines


def markdown(groups, rows, note):
    header = ["Domain", "T", "", "Design size", "IE w/o", "IE with", "IE % diff", "Plan cost w/o",
              "Plan cost with", "Plan cost % diff", "Total w/o", "Total with", "Total % diff",
              "Time (s)"]
    table = [[c if isinstance(c, (str, int)) else fmt(c) for c in line]
             for line in table1_lines(groups)]
    proven = [[DOMAIN_TITLES[d], h, f"{s['optimal']}/{s['runs']}", s["designed"],
               s["ie_dropped"], s["plan_cost_rose"], s["plan_cost_same"], fmt(s["wall_median"]),
               fmt(s["wall_p90"]), fmt(s["wall_max"])] for (d, h), s in groups]
    where = [[DOMAIN_TITLES[d], h, fmt(s["wall_s_mean"] * s["runs"], 1), fmt(s["engine_s_sum"], 1),
              fmt(s["planner_s_sum"], 1), fmt(100 * s["planner_s_sum"] / s["engine_s_sum"], 0),
              s["planner_runs_sum"], s["cache_hits_sum"],
              f"{s['configurations_evaluated_sum']} / {s['configurations_abandoned_sum']} / "
              f"{s['configurations_skipped_sum']} of {s['configurations_total_sum']}"]
             for (d, h), s in groups]
    times = [row["wall_s"] for row in rows]
    buckets = [(0, 0.1), (0.1, 1), (1, 10), (10, 60), (60, 300), (300, math.inf)]
    histogram = [[f"[{lo:g}, {hi:g}) s", sum(lo <= t < hi for t in times)] for lo, hi in buckets]
    parts = [
        "# Table 1, reproduced", "", note, "",
        "Generated by `python3 tests/benchmarks/paper/run_table1.py`; per-run rows in "
        "`table1-runs.csv`, engine output in `table1-runs.jsonl`.", "",
        markdown_table(header, table), "",
        "IE: the objective's term f_T(E[IE]); plan cost: E[c_R]; total: the objective; % diff "
        "of the means; SD: sample SD; time: wall seconds of one `envdesign design` process.", "",
        "## Optimality and time", "",
        markdown_table(["Domain", "T", "Proven optimal", "With a design", "IE dropped",
                        "Plan cost rose", "Plan cost same", "Median (s)", "p90 (s)", "Max (s)"],
                       proven), "",
        "The middle columns count the runs whose optimal design is not empty (the others keep "
        "the unmodified environment, so nothing changes).", "",
        f"All {len(rows)} runs: {sum(r['status'] == 'optimal' for r in rows)} proven optimal; "
        f"median {fmt(quantile(times, 0.5))} s, p90 {fmt(quantile(times, 0.9))} s, max "
        f"{fmt(max(times))} s.", "",
        markdown_table(["Wall time", "Runs"], histogram), "",
        "## Where the time goes", "",
        markdown_table(["Domain", "T", "Wall (s)", "Search (s)", "Planner (s)", "Planner %",
                        "Planner runs", "Cache hits",
                        "Configurations evaluated / abandoned / skipped of total"], where), "",
        "Wall: the processes, spec loading and grounding of the unmodified models included; "
        "search: the design search; planner: the A*/LM-cut runs inside it. A configuration is "
        "abandoned once the tasks evaluated so far prove it cannot win, skipped when its "
        "design cost alone proves it.",
    ]
    return "\n".join(parts) + "\n"


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--envdesign", default=ENVDESIGN)
    parser.add_argument("--build-commit", help="the commit the binary was built from, for the "
                        "notes (default: this repository's HEAD)")
    parser.add_argument("--domain", action="append", choices=DOMAINS)
    parser.add_argument("--horizon", action="append", type=int)
    parser.add_argument("--time-limit", type=float, default=1800)
    parser.add_argument("--out", default=RESULTS)
    parser.add_argument("--from-runs", action="store_true")
    args = parser.parse_args()
    args.domain = args.domain or list(DOMAINS)
    args.horizon = args.horizon or [1, 10]
    runs_path = os.path.join(args.out, "table1-runs.jsonl")
    os.makedirs(args.out, exist_ok=True)
    if not args.from_runs:
        run_all(args, runs_path)
    with open(runs_path) as f:
        results = [json.loads(line) for line in f]
    rows = [run_row(r["domain"], r["problem"], r["horizon"], r) for r in results]
    write_csv(os.path.join(args.out, "table1-runs.csv"), RUN_FIELDS,
              [[row[k] for k in RUN_FIELDS] for row in rows])
    keys = sorted({(row["domain"], row["horizon"]) for row in rows},
                  key=lambda k: (DOMAINS.index(k[0]), k[1]))
    groups = [(k, summary([row for row in rows if (row["domain"], row["horizon"]) == k]))
              for k in keys]
    write_csv(os.path.join(args.out, "table1.csv"), SUMMARY_FIELDS + ["proven_optimal", "runs"],
              [line + [s["optimal"], s["runs"]] for line, s in zip(
                  table1_lines(groups), [s for _, s in groups for _ in (0, 1)])])
    text = markdown(groups, rows, environment_note(args.envdesign, args.build_commit))
    with open(os.path.join(args.out, "table1.md"), "w") as f:
        f.write(text)
    print(text)


if __name__ == "__main__":
    main()
