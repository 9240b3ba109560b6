#!/usr/bin/env python3
"""Our PDDL reader over a checkout of the public benchmark collection (issue 12).

  python3 tests/benchmarks/ipc_collection.py /tmp/ipc/bench [--time-limit 10]
      [--per-domain N] [--fd /tmp/fd/fast-downward.py] [--markdown OUT.md]

The collection is github.com/aibasel/downward-benchmarks (the search tool's `fetch`
brings it; never commit it). For every domain whose declared requirements fall in our
fragment (STRIPS, typing, negative preconditions, equality, action costs), each instance
goes through `envdesign plan --json`: exit code 2 is a refusal (its first line is the
reason); anything else means the files were read. Solved plans are checked with our
validator. With --fd, Fast Downward's astar(lmcut()) runs on the same instance with the
same time limit, and its cost is compared with ours. Prints one Markdown row per domain
and a summary line.
"""
import argparse
import glob
import os
import re
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from ipc_benchmark import ROOT, validate  # noqa: E402  (one home for the validator call)

FRAGMENT = {":strips", ":typing", ":negative-preconditions", ":equality", ":action-costs"}


def requirements(domain_file):
    text = open(domain_file, errors="replace").read().lower()
    text = re.sub(r";[^\n]*", "", text)
    m = re.search(r"\(:requirements([^)]*)\)", text)
    return set(m.group(1).split()) if m else set()


def instances(directory):
    """(domain file, problem file) pairs, with the collection's naming conventions."""
    pairs = []
    for problem in sorted(glob.glob(os.path.join(directory, "*.pddl"))):
        name = os.path.basename(problem)
        if "domain" in name:
            continue
        for domain in (os.path.join(directory, "domain_" + name),
                       os.path.join(directory, name.replace(".pddl", "-domain.pddl")),
                       os.path.join(directory, "domain.pddl")):
            if os.path.exists(domain):
                pairs.append((domain, problem))
                break
    return pairs


def run_ours(binary, domain, problem, time_limit, plan_file):
    proc = subprocess.run([binary, "--log-level", "warn", "plan", domain, problem, "--json",
                           "--time-limit", str(time_limit), "--plan-file", plan_file],
                          capture_output=True, text=True)
    if proc.returncode == 2:
        lines = (proc.stderr or proc.stdout).strip().splitlines()
        return {"refused": lines[0] if lines else "exit 2"}
    cost = re.search(r'"cost":\s*([0-9.]+)', proc.stdout)
    solved = proc.returncode == 0 and cost is not None
    return {"refused": None, "solved": solved, "cost": float(cost.group(1)) if solved else None}


def run_fd(fd, domain, problem, time_limit, workdir):
    plan = os.path.join(workdir, "fd_plan")
    if os.path.exists(plan):
        os.remove(plan)
    proc = subprocess.run([sys.executable, fd, "--overall-time-limit", f"{int(time_limit)}s",
                           "--plan-file", plan, domain, problem, "--search", "astar(lmcut())"],
                          capture_output=True, text=True, cwd=workdir)
    if proc.returncode != 0 or not os.path.exists(plan):
        return None
    m = re.search(r"; cost = (\d+)", open(plan).read())
    return float(m.group(1)) if m else None


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("collection")
    parser.add_argument("--time-limit", type=float, default=10)
    parser.add_argument("--per-domain", type=int, default=0, help="instances per domain (0: all)")
    parser.add_argument("--domains", default="", help="comma-separated names (default: all)")
    parser.add_argument("--fd", help="fast-downward.py of a build outside the repository")
    parser.add_argument("--binary", default=os.path.join(ROOT, "build", "bin", "envdesign"))
    parser.add_argument("--markdown", help="also write the table here")
    args = parser.parse_args()
    wanted = set(filter(None, args.domains.split(",")))

    header = ("| domain | instances | accepted | refused | first refusal | solved | "
              "FD solved | cost equal to FD | invalid plans |\n|---|---|---|---|---|---|---|---|---|")
    rows, outside = [], []
    totals = dict(instances=0, accepted=0, refused=0, solved=0, fd=0, equal=0, invalid=0)
    with tempfile.TemporaryDirectory() as work:
        plan_file = os.path.join(work, "plan")
        for name in sorted(os.listdir(args.collection)):
            directory = os.path.join(args.collection, name)
            pairs = instances(directory) if os.path.isdir(directory) else []
            if not pairs or (wanted and name not in wanted):
                continue
            reqs = requirements(pairs[0][0])
            if not reqs <= FRAGMENT:
                outside.append(f"{name} ({' '.join(sorted(reqs - FRAGMENT))})")
                continue
            if args.per_domain:
                pairs = pairs[:args.per_domain]
            c = dict(instances=0, accepted=0, refused=0, solved=0, fd=0, equal=0, invalid=0)
            first_refusal = ""
            for domain, problem in pairs:
                c["instances"] += 1
                if os.path.exists(plan_file):
                    os.remove(plan_file)
                ours = run_ours(args.binary, domain, problem, args.time_limit, plan_file)
                if ours["refused"]:
                    c["refused"] += 1
                    first_refusal = first_refusal or ours["refused"].replace("|", "/")
                    continue
                c["accepted"] += 1
                if ours["solved"]:
                    c["solved"] += 1
                    ok, _ = validate(args.binary, domain, problem, plan_file)
                    c["invalid"] += not ok
                if args.fd:
                    reference = run_fd(args.fd, domain, problem, args.time_limit, work)
                    if reference is not None:
                        c["fd"] += 1
                        c["equal"] += ours["solved"] and abs(ours["cost"] - reference) < 1e-9
            fd = (lambda k: str(c[k])) if args.fd else (lambda k: "-")
            rows.append(f"| {name} | {c['instances']} | {c['accepted']} | {c['refused']} | "
                        f"{first_refusal} | {c['solved']} | {fd('fd')} | {fd('equal')} | "
                        f"{c['invalid']} |")
            print(rows[-1], flush=True)
            for k in totals:
                totals[k] += c[k]
    summary = (f"{len(rows)} domains of the fragment, {totals['instances']} instances: "
               f"{totals['accepted']} accepted, {totals['refused']} refused, "
               f"{totals['solved']} solved in {args.time_limit:g} s, "
               f"{totals['invalid']} invalid plans" +
               (f"; Fast Downward solved {totals['fd']}, same cost on {totals['equal']}"
                if args.fd else "") +
               f". Outside the fragment (by requirements): {len(outside)} domains.")
    print(summary)
    if args.markdown:
        with open(args.markdown, "w") as f:
            f.write(header + "\n" + "\n".join(rows) + "\n\n" + summary + "\n\nOutside: " +
                    ", ".join(outside) + "\n")


if __name__ == "__main__":
    main()
