#!/usr/bin/env python3
"""Our PDDL reader and planner over a checkout of the public benchmark collection (issue 12).

  python3 tests/benchmarks/ipc_collection.py /tmp/ipc/bench --csv RESULTS.csv \
      [--read] [--ours] [--fd /tmp/fd/fast-downward.py] [--rerun-limit 120] \
      [--time-limit 10] [--skip-after 3] [--per-domain N] [--markdown OUT.md]

The collection is github.com/aibasel/downward-benchmarks (the search tool's `fetch`
brings it; never commit it). Every domain is run. A domain belongs to our fragment when
its declared requirements are among STRIPS, typing, negative preconditions, equality and
action costs (domains that declare none too); the others are reported apart: the reader
accepts a declaration beyond the fragment and refuses what is outside it where it is used,
so a domain that declares :adl but uses only STRIPS is compared as any other.

Every instance gets one CSV row, so runs can be stopped, resumed and merged: a run only
does what the CSV does not hold yet.
  --read   the reader's verdict: `envdesign validate DOMAIN PROBLEM EMPTY_PLAN` (exit 2:
           refused, its first line is the reason; no grounding, no search).
  --fd     Fast Downward's astar(lmcut()) (--overall-time-limit: CPU seconds); its plan is
           checked with our validator too (a plan it finds that we call invalid is our bug).
  --ours   `envdesign plan`, limited to the same CPU seconds (RLIMIT_CPU set here, so the
           load of a shared machine counts against neither planner); solved plans are
           checked with our validator.
  --ours-where-fd-solved   ours only where Fast Downward solved (when time is short).
  --rerun-limit S   ours again with S CPU seconds on every instance Fast Downward solved
           and ours did not solve within the first limit.
The work goes breadth-first: instance 1 (by problem file name) of every domain, then
instance 2, and so on, so that coverage is even when the run is stopped. Within a domain,
a planner skips the rest after --skip-after consecutive instances it did not solve (ours
still runs on every instance Fast Downward solved). Fast Downward does not run on instances
our reader refuses (constructs outside the fragment: nothing to compare). Problems whose
domain file is absent (a checkout that lacks blobs) are rows with verdict `missing`.

Prints and writes (--markdown) one row per domain and a summary line per group of
domains, from the whole CSV.
"""
import argparse
import csv
import glob
import os
import re
import resource
import signal
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from ipc_benchmark import ROOT, validate  # noqa: E402  (one home for the validator call)

FRAGMENT = {":strips", ":typing", ":negative-preconditions", ":equality", ":action-costs"}
COLUMNS = ["domain", "problem", "verdict", "reason", "our_status", "our_limit", "our_cost",
           "our_cpu", "our_wall", "valid", "fd_status", "fd_cost", "fd_cpu", "fd_wall",
           "fd_plan_valid"]
MEMORY_MB = 2048


def requirements(domain_file):
    text = open(domain_file, errors="replace").read().lower()
    text = re.sub(r";[^\n]*", "", text)
    m = re.search(r"\(:requirements([^)]*)\)", text)
    return set(m.group(1).split()) if m else set()


def natural_order(path):
    """probBLOCKS-4-0 before probBLOCKS-10-0: the numbers in a name compare as numbers, so the
    instances run from small to large as the collection numbers them (the skip rule needs it)."""
    return [int(part) if part.isdigit() else part for part in re.split(r"(\d+)", path)]


def instances(directory):
    """(domain file or None, problem file) pairs, with the collection's naming conventions.
    None: the problem's own domain file (domain_NAME) is absent from the checkout."""
    pairs = []
    for problem in sorted(glob.glob(os.path.join(directory, "*.pddl")), key=natural_order):
        name = os.path.basename(problem)
        if "domain" in name:
            continue
        own = os.path.join(directory, "domain_" + name)
        candidates = (own, os.path.join(directory, name.replace(".pddl", "-domain.pddl")),
                      os.path.join(directory, "domain.pddl"))
        found = next((d for d in candidates if os.path.exists(d)), None)
        per_problem = glob.glob(os.path.join(directory, "domain_*.pddl"))
        if found is None and per_problem:
            pairs.append((None, problem))
        elif found is not None:
            pairs.append((found, problem))
    return pairs


def timed(command, cpu_limit, cwd=None):
    """Runs command with a CPU-second limit (0: none); returns (process, cpu s, wall s)."""
    def limit():
        if cpu_limit:
            resource.setrlimit(resource.RLIMIT_CPU, (int(cpu_limit), int(cpu_limit) + 1))
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    try:
        proc = subprocess.run(command, capture_output=True, text=True, cwd=cwd,
                              preexec_fn=limit, timeout=max(60, 20 * (cpu_limit or 60)))
    except subprocess.TimeoutExpired as e:
        proc = subprocess.CompletedProcess(command, -signal.SIGKILL, e.stdout or "", "")
    wall = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return proc, cpu, wall


def read_verdict(binary, collection, domain, problem, work):
    empty = os.path.join(work, "empty_plan")
    open(empty, "w").close()
    proc = subprocess.run([binary, "validate", domain, problem, empty],
                          capture_output=True, text=True)
    if proc.returncode == 2:
        lines = (proc.stderr or proc.stdout).strip().splitlines()
        reason = (lines[0] if lines else "exit 2").replace("|", "/")
        return "refused", reason.replace(os.path.join(collection, ""), "")
    return "accepted", ""


def run_ours(binary, domain, problem, limit, work):
    plan_file = os.path.join(work, "plan")
    if os.path.exists(plan_file):
        os.remove(plan_file)
    # Our own --time-limit (wall clock) is only a guard here; the CPU limit decides.
    proc, cpu, wall = timed([binary, "--log-level", "warn", "plan", domain, problem, "--json",
                             "--time-limit", str(20 * limit), "--memory-limit", str(MEMORY_MB),
                             "--plan-file", plan_file], limit)
    row = {"our_limit": f"{limit:g}", "our_cpu": f"{cpu:.2f}", "our_wall": f"{wall:.2f}",
           "our_cost": "", "valid": ""}
    cost = re.search(r'"cost":\s*([0-9.]+)', proc.stdout)
    if proc.returncode == 2:
        row["our_status"] = "refused"
    elif proc.returncode == 0 and cost and os.path.exists(plan_file):
        row["our_status"] = "solved"
        row["our_cost"] = cost.group(1)
        ok, _ = validate(binary, domain, problem, plan_file)
        row["valid"] = "yes" if ok else "no"
    elif proc.returncode == 3:
        row["our_status"] = "unsolvable"
    elif proc.returncode in (4, -signal.SIGXCPU, -signal.SIGKILL):
        row["our_status"] = "limit"
    else:
        row["our_status"] = f"error {proc.returncode}"
    return row


def run_fd(fd, binary, domain, problem, limit, work):
    plan = os.path.join(work, "fd_plan")
    if os.path.exists(plan):
        os.remove(plan)
    proc, cpu, wall = timed([sys.executable, fd, "--overall-time-limit", f"{int(limit)}s",
                             "--overall-memory-limit", f"{MEMORY_MB}M", "--plan-file", plan,
                             domain, problem, "--search", "astar(lmcut())"], 0, cwd=work)
    row = {"fd_cpu": f"{cpu:.2f}", "fd_wall": f"{wall:.2f}", "fd_cost": "", "fd_plan_valid": ""}
    m = re.search(r"; cost = (\d+)", open(plan).read()) if os.path.exists(plan) else None
    if proc.returncode == 0 and m:
        row["fd_status"] = "solved"
        row["fd_cost"] = m.group(1)
        ok, _ = validate(binary, domain, problem, plan)
        row["fd_plan_valid"] = "yes" if ok else "no"
    else:
        row["fd_status"] = f"failed {proc.returncode}"
    return row


def streak_broken(rows, key, skip_after):
    """True when the last skip_after instances the planner ran (key: its status column) in
    this domain, before this one, were all not solved."""
    ran = [r[key] for r in rows if r.get(key)]
    tail = ran[-skip_after:]
    return skip_after > 0 and len(tail) == skip_after and all(s != "solved" for s in tail)


def load(path):
    if not path or not os.path.exists(path):
        return {}
    with open(path) as f:
        return {(r["domain"], r["problem"]): r for r in csv.DictReader(f)}


def save(path, table):
    if not path:
        return
    with open(path + ".tmp", "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=COLUMNS)
        writer.writeheader()
        for key in sorted(table):
            writer.writerow({c: table[key].get(c, "") for c in COLUMNS})
    os.replace(path + ".tmp", path)


def domains_of(collection, wanted, per_domain):
    """{name: instances} of the domains declared within the fragment, and of the others
    ({name: (instances, the requirements beyond the fragment)})."""
    inside, beyond = {}, {}
    for name in sorted(os.listdir(collection)):
        directory = os.path.join(collection, name)
        pairs = instances(directory) if os.path.isdir(directory) else []
        if not pairs or (wanted and name not in wanted):
            continue
        pairs = pairs[:per_domain] if per_domain else pairs
        reqs = requirements(next(d for d, _ in pairs if d))
        if reqs <= FRAGMENT:
            inside[name] = pairs
        else:
            beyond[name] = (pairs, " ".join(sorted(reqs - FRAGMENT)))
    return inside, beyond


def run(args, domains, table):
    rounds = max(len(p) for p in domains.values())
    with tempfile.TemporaryDirectory() as work:
        for i in range(rounds):
            for name, pairs in domains.items():
                if i >= len(pairs):
                    continue
                domain, problem = pairs[i]
                key = (name, os.path.basename(problem))
                row = table.setdefault(key, {"domain": name, "problem": key[1]})
                before = [table.get((name, os.path.basename(p)), {}) for _, p in pairs[:i]]
                if domain is None:
                    row.update(verdict="missing", reason="domain file absent from the checkout")
                    continue
                if args.read and not row.get("verdict"):
                    row["verdict"], row["reason"] = read_verdict(args.binary, args.collection,
                                                                 domain, problem, work)
                if args.fd and not row.get("fd_status") and row.get("verdict") != "refused" \
                        and not streak_broken(before, "fd_status", args.skip_after):
                    row.update(run_fd(args.fd, args.binary, domain, problem, args.time_limit,
                                      work))
                fd_solved = row.get("fd_status") == "solved"
                if args.ours and not row.get("our_status") and row.get("verdict") != "refused" \
                        and (fd_solved or (not args.ours_where_fd_solved and
                                           not streak_broken(before, "our_status",
                                                             args.skip_after))):
                    row.update(run_ours(args.binary, domain, problem, args.time_limit, work))
                if args.rerun_limit and fd_solved and row.get("our_status") == "limit" and \
                        float(row.get("our_limit") or 0) < args.rerun_limit:
                    row.update(run_ours(args.binary, domain, problem, args.rerun_limit, work))
                save(args.csv, table)
                print(",".join(row.get(c, "") for c in COLUMNS), flush=True)


def summarize(domains, table, time_limit, group, beyond=None):
    """The table and summary line of one group of domains; `beyond`: {name: requirements
    declared beyond the fragment}, a column of its own."""
    extra = "declared beyond the fragment | " if beyond else ""
    header = (f"| domain | {extra}instances | missing from the checkout | accepted | refused | "
              "first refusal | FD solved | we solved | FD solved, we solved, cost equal | "
              "cost differs | invalid plans |\n|" + "---|" * (11 + bool(beyond)))
    rows, totals = [], {}
    for name, pairs in domains.items():
        rs = [table.get((name, os.path.basename(p)), {}) for _, p in pairs]
        c = {"instances": len(rs),
             "missing": sum(r.get("verdict") == "missing" for r in rs),
             "accepted": sum(r.get("verdict") == "accepted" for r in rs),
             "refused": sum(r.get("verdict") == "refused" for r in rs),
             "fd": sum(r.get("fd_status") == "solved" for r in rs),
             "solved": sum(r.get("our_status") == "solved" for r in rs),
             "equal": sum(r.get("fd_status") == "solved" and r.get("our_status") == "solved"
                          and float(r["our_cost"]) == float(r["fd_cost"]) for r in rs),
             "differ": sum(r.get("fd_status") == "solved" and r.get("our_status") == "solved"
                           and float(r["our_cost"]) != float(r["fd_cost"]) for r in rs),
             "invalid": sum(r.get("valid") == "no" or r.get("fd_plan_valid") == "no"
                            for r in rs),
             "fd_ran": sum(r.get("verdict") == "accepted" and bool(r.get("fd_status"))
                           for r in rs)}
        refusal = next((r["reason"] for r in rs if r.get("verdict") == "refused"), "")
        declared = f"{beyond[name]} | " if beyond else ""
        rows.append(f"| {name} | {declared}{c['instances']} | {c['missing']} | {c['accepted']} | "
                    f"{c['refused']} | {refusal} | {c['fd']} | {c['solved']} | {c['equal']} | "
                    f"{c['differ']} | {c['invalid']} |")
        for k, v in c.items():
            totals[k] = totals.get(k, 0) + v
    t = lambda k: totals.get(k, 0)  # noqa: E731
    summary = (f"{len(rows)} domains {group}, {t('instances')} instances ({t('missing')} "
               f"missing from the checkout): {t('accepted')} accepted, {t('refused')} refused; "
               f"Fast Downward ran on {t('fd_ran')} of the accepted and solved {t('fd')} "
               f"within {time_limit:g} s, we solved {t('equal') + t('differ')} of those, same "
               f"cost on {t('equal')}, different on {t('differ')}; we solved {t('solved')} in "
               f"all; {t('invalid')} invalid plans.")
    return header + "\n" + "\n".join(rows) + "\n\n" + summary + "\n"


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("collection")
    parser.add_argument("--csv", help="one row per instance; read first, so runs resume")
    parser.add_argument("--read", action="store_true", help="the reader's verdict")
    parser.add_argument("--ours", action="store_true", help="our planner")
    parser.add_argument("--fd", help="fast-downward.py of a build outside the repository")
    parser.add_argument("--ours-where-fd-solved", action="store_true",
                        help="ours only on instances Fast Downward solved")
    parser.add_argument("--rerun-limit", type=float, default=0)
    parser.add_argument("--time-limit", type=float, default=10, help="CPU seconds")
    parser.add_argument("--skip-after", type=int, default=3)
    parser.add_argument("--per-domain", type=int, default=0, help="instances per domain (0: all)")
    parser.add_argument("--domains", default="", help="comma-separated names (default: all)")
    parser.add_argument("--binary", default=os.path.join(ROOT, "build", "bin", "envdesign"))
    parser.add_argument("--markdown", help="also write the table here")
    args = parser.parse_args()

    inside, beyond = domains_of(args.collection, set(filter(None, args.domains.split(","))),
                                args.per_domain)
    table = load(args.csv)
    if args.read or args.ours or args.fd or args.rerun_limit:
        run(args, {**inside, **{name: pairs for name, (pairs, _) in beyond.items()}}, table)
    text = summarize(inside, table, args.time_limit, "declared within the fragment")
    if beyond:
        text += "\n" + summarize({name: pairs for name, (pairs, _) in beyond.items()}, table,
                                  args.time_limit, "declaring requirements beyond the fragment",
                                  {name: reqs for name, (_, reqs) in beyond.items()})
    print(text)
    if args.markdown:
        with open(args.markdown, "w") as f:
            f.write(text)


if __name__ == "__main__":
    main()
