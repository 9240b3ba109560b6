#!/usr/bin/env python3
"""The planner benchmark: every IPC instance with a reference cost in
../shared/benchmarks/ipc/optimal-costs.csv, solved by `envdesign plan` (median of --runs),
checked for optimal cost and a valid plan, optionally timed beside Fast Downward's
astar(lmcut()) in the same run (--fd PATH/TO/fast-downward.py, built outside the repo).

  python3 tests/benchmarks/ipc_benchmark.py --runs 3 [--fd /tmp/fd/fast-downward.py]

Prints one Markdown row per instance and a summary; --csv FILE writes the rows too.
"""
import argparse
import csv
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def read_reference(ipc_dir, domains):
    with open(os.path.join(ipc_dir, "optimal-costs.csv")) as f:
        rows = [r for r in csv.DictReader(f) if r["solved"] == "yes"]
    return [r for r in rows if not domains or r["domain"] in domains]


def run_ours(binary, domain, problem, time_limit, plan_file):
    start = time.perf_counter()
    proc = subprocess.run([binary, "--log-level", "warn", "plan", domain, problem, "--json",
                           "--time-limit", str(time_limit), "--plan-file", plan_file],
                          capture_output=True, text=True)
    wall = time.perf_counter() - start
    if proc.returncode not in (0, 3, 4):
        raise RuntimeError(f"envdesign failed on {problem}: {proc.stderr.strip()}")
    result = json.loads(proc.stdout)
    result["wall"] = wall
    return result


def validate(binary, domain, problem, plan_file):
    proc = subprocess.run([binary, "validate", domain, problem, plan_file],
                          capture_output=True, text=True)
    return proc.returncode == 0, proc.stdout.strip()


def run_fd(fd, domain, problem, time_limit, workdir):
    start = time.perf_counter()
    proc = subprocess.run([sys.executable, fd, "--overall-time-limit", f"{int(time_limit)}s",
                           "--plan-file", os.path.join(workdir, "fd_plan"), domain, problem,
                           "--search", "astar(lmcut())"],
                          capture_output=True, text=True, cwd=workdir)
    wall = time.perf_counter() - start
    return wall if proc.returncode == 0 else None


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--shared", default=os.path.join(ROOT, "..", "shared"))
    parser.add_argument("--binary", default=os.path.join(ROOT, "build", "bin", "envdesign"))
    parser.add_argument("--runs", type=int, default=3)
    parser.add_argument("--time-limit", type=float, default=300)
    parser.add_argument("--domains", nargs="*", default=[])
    parser.add_argument("--fd", help="fast-downward.py to time side by side")
    parser.add_argument("--csv", help="also write the rows to this CSV file")
    args = parser.parse_args()

    ipc_dir = os.path.join(args.shared, "benchmarks", "ipc")
    rows = []
    header = ["domain", "problem", "ref_cost", "cost", "valid", "expansions", "ref_expansions",
              "exp_ratio", "parse_ground_s", "search_s", "total_s", "fd_total_s", "speedup"]
    print("| " + " | ".join(header) + " |")
    print("|" + "---|" * len(header))
    with tempfile.TemporaryDirectory() as workdir:
        plan_file = os.path.join(workdir, "sas_plan")
        for ref in read_reference(ipc_dir, args.domains):
            domain = os.path.join(ipc_dir, ref["domain"], "domain.pddl")
            problem = os.path.join(ipc_dir, ref["domain"], ref["problem"])
            runs = [run_ours(args.binary, domain, problem, args.time_limit, plan_file)
                    for _ in range(args.runs)]
            first = runs[0]
            solved = first["status"] == "solved"
            valid = solved and validate(args.binary, domain, problem, plan_file)[0]
            fd_wall = None
            if args.fd:
                times = [run_fd(args.fd, domain, problem, args.time_limit, workdir)
                         for _ in range(args.runs)]
                fd_wall = statistics.median(times) if None not in times else None
            total = statistics.median(r["wall"] for r in runs)
            row = {
                "domain": ref["domain"], "problem": ref["problem"],
                "ref_cost": int(ref["cost"]), "cost": first.get("cost"), "valid": valid,
                "expansions": first.get("expansions"),
                "ref_expansions": int(ref["expansions"]),
                "exp_ratio": round(first["expansions"] / max(1, int(ref["expansions"])), 3),
                "parse_ground_s": round(statistics.median(r.get("parse_ground_seconds", 0)
                                                          for r in runs), 4),
                "search_s": round(statistics.median(r.get("search_seconds", 0) for r in runs), 4),
                "total_s": round(total, 4),
                "fd_total_s": round(fd_wall, 4) if fd_wall else "",
                "speedup": round(fd_wall / total, 2) if fd_wall else "",
            }
            rows.append(row)
            print("| " + " | ".join(str(row[h]) for h in header) + " |", flush=True)
    summarize(rows, args.runs)
    if args.csv:
        with open(args.csv, "w", newline="") as f:
            writer = csv.DictWriter(f, fieldnames=header)
            writer.writeheader()
            writer.writerows(rows)


def summarize(rows, runs):
    optimal = sum(1 for r in rows if r["cost"] == r["ref_cost"])
    valid = sum(1 for r in rows if r["valid"])
    within = sum(1 for r in rows if abs(r["exp_ratio"] - 1) <= 0.10)
    below = sum(1 for r in rows if r["exp_ratio"] < 0.90)
    print(f"\nSummary over {len(rows)} instances ({runs} runs each, medians):")
    print(f"- optimal cost equal to the reference: {optimal}/{len(rows)}; plans valid: {valid}")
    print(f"- expansions within 10% of the reference: {within}; more than 10% fewer: {below}; "
          f"median ratio {statistics.median(r['exp_ratio'] for r in rows):.3f}")
    print(f"- total time: median {statistics.median(r['total_s'] for r in rows):.4f} s, "
          f"sum {sum(r['total_s'] for r in rows):.2f} s")
    speedups = [r["speedup"] for r in rows if r["speedup"] != ""]
    if speedups:
        print(f"- Fast Downward total / ours: median {statistics.median(speedups):.2f}x, "
              f"min {min(speedups):.2f}x, max {max(speedups):.2f}x "
              f"(sum FD {sum(r['fd_total_s'] for r in rows if r['fd_total_s'] != ''):.2f} s)")


if __name__ == "__main__":
    main()
