#!/usr/bin/env python3
"""Helper of tests/benchmarks/soak/run.sh (issue 11's 1-hour soak).

  soak.py replay OUT.csv --minutes M --drift-minutes D --rate R --seed S [--profile P]
      the arrivals: R a second, the task mix changing every D minutes (MIXES, in turn;
      --profile ramps: moving linearly from one phase's mix to the next)
  soak.py request-spec OUT.textproto --seed S
      one client request: a variant of the drift spec (weights, mix, modifications)
  soak.py check DIR --drift-minutes D [--envdesign BIN]
      after a run: the design check, the log check, the bound check, the plot; writes
      DIR/summary.md and DIR/check.json; exit code 0 when every clause passed

The design check is independent of the bridge: for every distinct estimate the bridge
published, `envdesign design --search exhaustive --ranking 64` runs locally on the drift
spec with the task probabilities set to that estimate (a separate process, the exhaustive
enumeration instead of the bridge's witness search over its stored evaluations).
"""

import argparse
import collections
import csv
import json
import math
import os
import random
import re
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
SOURCE = os.path.abspath(os.path.join(HERE, "..", "..", ".."))
EXAMPLE = os.path.join(SOURCE, "examples", "restaurant")
DRIFT_SPEC = os.path.join(SOURCE, "tests", "arrivals", "data", "restaurant-drift.textproto")

# P(serve-g1) of each drift phase, in turn. The drift spec's optimum is {} from about 0.8 up
# and {barrier-00-01} from 0.7 down, so the design changes between most neighbours; the
# phases stay away from the boundary by more than 2 standard deviations of a window of 200
# random arrivals (0.035), but an estimate may still cross it now and then.
MIXES = [0.9, 0.3, 0.95, 0.6, 0.88, 0.1, 0.92, 0.5, 0.2, 0.95, 0.4, 0.9]

TASKS = ["serve-g1", "serve-g2"]

# The restaurant's corridors (examples/restaurant/*-human.pddl), each a possible barrier.
EDGES = [("c00", "c10"), ("c00", "c01"), ("c01", "c11"), ("c01", "c02"), ("c02", "c12"),
         ("c10", "c20"), ("c10", "c11"), ("c11", "c21"), ("c11", "c12"), ("c12", "c22"),
         ("c20", "c21"), ("c21", "c22")]

# Tie rule of the design check: designs whose objective is within this of the least are
# all optimal (the bridge may hold any of them).
TIE = 1e-6


def mix_of_phase(phase):
    return MIXES[phase % len(MIXES)]


def cmd_replay(a):
    rng = random.Random(a.seed)
    total = int(round(a.minutes * 60 * a.rate))
    per_phase = int(round(a.drift_minutes * 60 * a.rate))
    with open(a.out, "w") as out:
        out.write("# soak arrivals: %g/s, mix of serve-g1 per phase %s, every %g min\n" %
                  (a.rate, MIXES, a.drift_minutes))
        out.write("task\n")
        for i in range(total):
            p = mix_of_phase(i // per_phase)
            if a.profile == "ramps":  # from this phase's mix to the next one's, linearly
                p += (mix_of_phase(i // per_phase + 1) - p) * (i % per_phase) / per_phase
            out.write((TASKS[0] if rng.random() < p else TASKS[1]) + "\n")


def spec_text(tasks, modifications, alpha=1, beta=30, kappa=0.25, distance="EXP_COST_DIFF"):
    lines = ['robot_domain: "%s"' % os.path.join(EXAMPLE, "domain.pddl")]
    for name, p in tasks:
        lines.append('task { name: "%s" problem: "%s" human_problem: "%s" probability: %r }' %
                     (name, os.path.join(EXAMPLE, name + ".pddl"),
                      os.path.join(EXAMPLE, name + "-human.pddl"), p))
    for a_, b_ in modifications:
        lines.append('modification { name: "barrier-%s-%s" cost: 1 '
                     'edit { model: HUMAN remove_init: "(connected %s %s)" } '
                     'edit { model: HUMAN remove_init: "(connected %s %s)" } }' %
                     (a_[1:], b_[1:], a_, b_, b_, a_))
    lines.append("alpha: %r beta: %r kappa: %r gamma: 0.9 horizon: 3" % (alpha, beta, kappa))
    lines.append("distance: %s" % distance)
    return "\n".join(lines) + "\n"


# The drift spec's six modifications, in its order.
DRIFT_MODS = [("c00", "c01"), ("c01", "c02"), ("c01", "c11"), ("c10", "c11"), ("c11", "c12"),
              ("c11", "c21")]


def cmd_request_spec(a):
    """Half the requests use the drift spec's models with another mix and weights (the
    coordinator's stored evaluations answer them: a re-weighting); half take 5 of the 12
    corridors as modifications (792 sets: mostly new planner work, some repeats)."""
    rng = random.Random(a.seed)
    p = rng.choice([0.1, 0.3, 0.5, 0.7, 0.9])
    tasks = [("serve-g1", p), ("serve-g2", round(1 - p, 3))]
    beta = rng.choice([20, 30, 40])
    if rng.random() < 0.5:
        kind, mods = "reweigh", DRIFT_MODS
    else:
        kind, mods = "new", sorted(rng.sample(EDGES, 5), key=EDGES.index)
    with open(a.out, "w") as out:
        out.write(spec_text(tasks, mods, beta=beta))
    print(kind)


# ---------------------------------------------------------------- the check, after a run


def read_watch(path):
    """The bridge's estimates (kind distribution) and results, in bus order."""
    estimates, results, bad = [], [], 0
    with open(path, errors="replace") as f:
        for line in f:
            try:
                m = json.loads(line)
            except ValueError:
                bad += 1
                continue
            if m.get("kind") == "distribution" and m.get("problem_id") == "restaurant":
                probs = tuple(float(m["probabilities"].get(t, 0)) for t in TASKS)
                if sum(probs) <= 0:  # no arrival yet: no estimate to check against
                    continue
                estimates.append((m["utime"] / 1e6, probs, tuple(m["design"]), m["samples"]))
            elif m.get("kind") == "result":
                results.append(m)
    return estimates, results, bad


def key_of(probs):
    return tuple(round(p, 9) for p in probs)


def drift_spec_with(probs):
    """The bridge's spec file itself, its paths made absolute and its probabilities set."""
    text = open(DRIFT_SPEC).read()
    text = re.sub(r'"([^"]+\.pddl)"',
                  lambda m: '"%s"' % os.path.normpath(os.path.join(os.path.dirname(DRIFT_SPEC),
                                                                   m.group(1))), text)
    for name, p in zip(TASKS, probs):
        text, n = re.subn(r'(task \{ name: "%s" .*probability: )[0-9.eE+-]+' % re.escape(name),
                          lambda m: m.group(1) + repr(p), text)
        if n != 1:
            raise SystemExit("%s: no task %s with a probability" % (DRIFT_SPEC, name))
    return text


def optimal_set(envdesign, probs, workdir, cache):
    """The designs optimal for `probs` (objective within TIE of the least), computed by a
    separate `envdesign design --search exhaustive` on the drift spec with these
    probabilities; cached by the estimate."""
    k = key_of(probs)
    if k in cache:
        return cache[k]
    spec = os.path.join(workdir, "optimum.textproto")
    with open(spec, "w") as out:
        out.write(drift_spec_with(probs))
    run = subprocess.run([envdesign, "design", spec, "--json", "--search", "exhaustive",
                          "--ranking", "64", "--workers", "1", "--log-level", "error"],
                         capture_output=True, text=True, timeout=600)
    if run.returncode != 0:
        raise SystemExit("envdesign design failed for %s: %s" % (probs, run.stderr))
    ranking = json.loads(run.stdout)["ranking"]
    best = min(r["objective"] for r in ranking)
    designs = frozenset(tuple(r["design"]) for r in ranking if r["objective"] <= best + TIE)
    cache[k] = {"best": best, "designs": designs}
    return cache[k]


def load_cache(path):
    cache = {}
    if os.path.exists(path):
        with open(path) as f:
            for row in json.load(f):
                cache[tuple(row["probs"])] = {"best": row["best"],
                                              "designs": frozenset(map(tuple, row["designs"]))}
    return cache


def save_cache(path, cache):
    with open(path, "w") as f:
        json.dump([{"probs": list(k), "best": v["best"], "designs": sorted(map(list, v["designs"]))}
                   for k, v in sorted(cache.items())], f, indent=0)


def design_check(estimates, envdesign, workdir, drift_minutes, window_s=1.0):
    """Three views of "the design in force is always the optimal one for the current
    estimate within 1 s":
    - always: at every published message (time T), the design in force is optimal for an
      estimate published in [T - 1 s, T] (or the one in force at T - 1 s);
    - samples (every 15 s and the first 5 s after each drift, every message): the design in
      force 1 s after the estimate E was published is optimal for E, or E was superseded
      within that second by an estimate whose optimum the design is;
    - delays: after each estimate whose optimal set differs from the design in force, the
      time until a message shows an optimal design for it (unless superseded first)."""
    cache_path = os.path.join(workdir, "optima.json")
    cache = load_cache(cache_path)
    times = [e[0] for e in estimates]
    for e in estimates:
        optimal_set(envdesign, e[1], workdir, cache)
    save_cache(cache_path, cache)
    opt = lambda probs: cache[key_of(probs)]["designs"]

    import bisect

    def index_at(t):  # last message at or before t
        return bisect.bisect_right(times, t) - 1

    always = {"checks": 0, "passes": 0, "fails": []}
    started = next((i for i, e in enumerate(estimates) if e[3] >= 1), None)
    for i in range(started or 0, len(estimates)):
        t, probs, design, _ = estimates[i]
        lo = max(index_at(t - window_s), started or 0)
        ok = any(design in opt(estimates[j][1]) for j in range(lo, i + 1))
        always["checks"] += 1
        if ok:
            always["passes"] += 1
        else:
            always["fails"].append({"t": t, "estimate": probs, "design": design})

    # Samples: every 15 s, and every message in the 5 s after each nominal drift.
    samples = {"checks": 0, "passes": 0, "superseded_passes": 0, "fails": [], "worst_delay_s": 0}
    if started is not None:
        t0 = estimates[started][0]
        end = estimates[-1][0] - window_s
        picks = set()
        grid = t0
        while grid <= end:
            picks.add(max(index_at(grid), started))
            grid += 15
        drift = t0 + drift_minutes * 60
        while drift <= end:
            i = index_at(drift) + 1
            while i < len(estimates) and estimates[i][0] <= drift + 5:
                picks.add(i)
                i += 1
            drift += drift_minutes * 60
        for i in sorted(picks):
            t, probs, _, _ = estimates[i]
            if t > end:
                continue
            j = index_at(t + window_s)
            in_force = estimates[j][2]
            samples["checks"] += 1
            if in_force in opt(probs):
                samples["passes"] += 1
            elif any(in_force in opt(estimates[k][1]) for k in range(i + 1, j + 1)):
                samples["superseded_passes"] += 1
            else:
                samples["fails"].append({"t": t, "estimate": probs, "in_force": in_force})

    # Delays: an estimate whose optimum excludes the design shown with it.
    delays = []
    superseded = 0
    for i in range(started or 0, len(estimates)):
        t, probs, design, _ = estimates[i]
        if design in opt(probs):
            continue
        want = opt(probs)
        for j in range(i + 1, len(estimates)):
            if estimates[j][2] in want:
                delays.append(estimates[j][0] - t)
                break
            if want.isdisjoint(opt(estimates[j][1])):  # the target moved away
                superseded += 1
                break
    # Every change of the design in force, beside the estimate and its independent optimum.
    with open(os.path.join(workdir, "design-changes.csv"), "w") as out:
        out.write("seconds,p_serve_g1,design_before,design_after,optimal_for_estimate\n")
        t0 = estimates[started][0] if started is not None else 0
        for i in range(max(started or 0, 1), len(estimates)):
            before, after = estimates[i - 1][2], estimates[i][2]
            if before != after:
                out.write("%.3f,%.3f,{%s},{%s},%s\n" % (
                    estimates[i][0] - t0, estimates[i][1][0], " ".join(before), " ".join(after),
                    " | ".join("{%s}" % " ".join(d) for d in sorted(opt(estimates[i][1])))))
    return {
        "messages": len(estimates),
        "distinct_estimates": len({key_of(e[1]) for e in estimates}),
        "always": {"checks": always["checks"], "passes": always["passes"],
                   "fails": len(always["fails"]), "first_fails": always["fails"][:10]},
        "samples": {"checks": samples["checks"], "passes": samples["passes"],
                    "superseded_passes": samples["superseded_passes"],
                    "fails": len(samples["fails"]), "first_fails": samples["fails"][:10]},
        "changes": {"count": len(delays), "superseded": superseded,
                    "worst_delay_s": max(delays) if delays else 0.0,
                    "mean_delay_s": sum(delays) / len(delays) if delays else 0.0},
        "designs_seen": sorted({" ".join(e[2]) or "{}" for e in estimates}),
    }


ERROR_LINE = re.compile(r"\[(error|critical|fatal)\]|\berror\b|\bfatal\b|terminate called|"
                        r"Segmentation|Aborted|AddressSanitizer", re.IGNORECASE)


def log_check(directory):
    hits = []
    logs = sorted(f for f in os.listdir(os.path.join(directory, "logs")) if f.endswith(".log"))
    for name in logs:
        with open(os.path.join(directory, "logs", name), errors="replace") as f:
            for n, line in enumerate(f, 1):
                if ERROR_LINE.search(line):
                    hits.append("%s:%d: %s" % (name, n, line.rstrip()[:300]))
    return {"logs": logs, "error_lines": len(hits), "first": hits[:40]}


def bound_check(samples_csv, minutes):
    """Per process role: RSS and fds over the second half of the run against the first.
    Criterion: the largest RSS of the second half <= 1.10 x the largest of minutes
    [M/4, M/2] + 4 MiB, and the most fds of the second half <= the most of the first half + 2.
    A restarted planner is the same role (its new process is measured from its own start)."""
    rows = collections.defaultdict(list)
    with open(samples_csv) as f:
        for r in csv.DictReader(f):
            if r["rss_kb"]:
                rows[r["role"]].append((float(r["minute"]), int(r["rss_kb"]), int(r["fds"])))
    out = {}
    half, quarter = minutes / 2, minutes / 4
    for role, vals in sorted(rows.items()):
        warm = [v for v in vals if quarter <= v[0] <= half]
        first = [v for v in vals if v[0] <= half]
        second = [v for v in vals if v[0] > half]
        if not warm or not second:
            out[role] = {"verdict": "too few samples"}
            continue
        rss_ref = max(v[1] for v in warm)
        rss_late = max(v[1] for v in second)
        fd_ref = max(v[2] for v in first)
        fd_late = max(v[2] for v in second)
        rss_ok = rss_late <= 1.10 * rss_ref + 4096
        fd_ok = fd_late <= fd_ref + 2
        out[role] = {"rss_first_kb": vals[0][1], "rss_ref_kb": rss_ref, "rss_late_max_kb": rss_late,
                     "rss_last_kb": vals[-1][1], "fds_first_half_max": fd_ref,
                     "fds_second_half_max": fd_late, "rss_ok": rss_ok, "fds_ok": fd_ok}
    return out


def plot(directory):
    samples_csv = os.path.join(directory, "samples.csv")
    roles = sorted({r["role"] for r in csv.DictReader(open(samples_csv))})
    for role in roles:
        with open(os.path.join(directory, "plot-%s.dat" % role), "w") as out:
            for r in csv.DictReader(open(samples_csv)):
                if r["role"] == role and r["rss_kb"]:
                    out.write("%s %.1f %s\n" % (r["minute"], int(r["rss_kb"]) / 1024, r["fds"]))
    rss = ", ".join("'plot-%s.dat' using 1:2 with linespoints title '%s'" % (r, r) for r in roles)
    fds = ", ".join("'plot-%s.dat' using 1:3 with linespoints title '%s'" % (r, r) for r in roles)
    script = """set terminal pngcairo size 1000,800 font ',10'
set output 'soak.png'
set multiplot layout 2,1 title 'envdesign soak: every process, sampled each minute'
set key outside right
set grid
set yrange [0:*]
set xlabel 'minute'
set ylabel 'RSS (MiB)'
plot %s
set ylabel 'open fds'
plot %s
unset multiplot
""" % (rss, fds)
    with open(os.path.join(directory, "soak.gnuplot"), "w") as f:
        f.write(script)
    run = subprocess.run(["gnuplot", "soak.gnuplot"], cwd=directory, capture_output=True, text=True)
    if run.returncode != 0:
        # pngcairo may be missing; the plain png terminal then.
        script = script.replace("pngcairo size 1000,800 font ',10'", "png size 1000,800")
        with open(os.path.join(directory, "soak.gnuplot"), "w") as f:
            f.write(script)
        subprocess.run(["gnuplot", "soak.gnuplot"], cwd=directory, check=True)
    for role in roles:
        os.remove(os.path.join(directory, "plot-%s.dat" % role))


def requests_summary(path):
    out = collections.Counter()
    with open(path) as f:
        for r in csv.DictReader(f):
            out["requests"] += 1
            out["kind_" + r["kind"]] += 1
            out["rc_" + r["rc"]] += 1
            if r["jobs_sent"] not in ("", "None"):
                out["jobs_sent"] += int(r["jobs_sent"])
                out["stored_answers"] += int(r["stored_answers"])
                if int(r["jobs_sent"]) == 0:
                    out["answered_without_jobs"] += 1
    return dict(out)


def cmd_check(a):
    d = os.path.abspath(a.dir)
    estimates, results, bad = read_watch(os.path.join(d, "logs", "watch.jsonl"))
    with open(os.path.join(d, "run.json")) as f:
        run = json.load(f)
    design = design_check(estimates, a.envdesign, d, a.drift_minutes)
    design["bridge_results"] = sum(1 for r in results if r.get("client", "").startswith("bridge"))
    design["undecodable_watch_lines"] = bad
    logs = log_check(d)
    bounds = bound_check(os.path.join(d, "samples.csv"), run["minutes"])
    reqs = requests_summary(os.path.join(d, "requests.csv"))
    plot(d)
    ok = {
        "design_always": design["always"]["fails"] == 0 and design["always"]["checks"] > 0,
        "design_samples": design["samples"]["fails"] == 0 and design["samples"]["checks"] > 0,
        "worst_delay_within_1s": design["changes"]["worst_delay_s"] <= 1.0,
        "no_error_lines": logs["error_lines"] == 0,
        "bounded": all(v.get("rss_ok") and v.get("fds_ok") for v in bounds.values()),
        "requests_all_answered": reqs.get("requests", 0) > 0 and reqs.get("rc_0", 0) == reqs["requests"],
    }
    report = {"run": run, "design": design, "logs": logs, "bounds": bounds, "requests": reqs,
              "ok": ok}
    with open(os.path.join(d, "check.json"), "w") as f:
        json.dump(report, f, indent=1, default=list)
    write_summary(d, report)
    print(json.dumps(ok))
    return 0 if all(ok.values()) else 1


def write_summary(d, r):
    run, dz, logs, bounds, reqs = r["run"], r["design"], r["logs"], r["bounds"], r["requests"]
    L = ["# Soak run %s" % run["started"], "",
         "Command: `%s`  " % run["command"],
         "Commit: %s; machine: %s  " % (run["commit"], run["machine"]),
         "Minutes: %s (drift every %s min, a planner SIGKILLed and restarted every %s min, "
         "arrivals %s/s, a request every %s s)" % (run["minutes"], run["drift_minutes"],
                                                   run["kill_minutes"], run["rate"],
                                                   run["request_every"]), "",
         "## Verdicts", ""]
    for k, v in r["ok"].items():
        L.append("- %s: %s" % (k, "PASS" if v else "FAIL"))
    L += ["", "## Design in force vs the independent optimum", "",
          "Estimates published by the bridge: %d messages, %d distinct estimates (each "
          "solved by `envdesign design --search exhaustive`). Designs seen: %s." %
          (dz["messages"], dz["distinct_estimates"], ", ".join(dz["designs_seen"])), "",
          "- always (every message T: design optimal for an estimate of [T-1 s, T]): "
          "%d checks, %d passes, %d fails" % (dz["always"]["checks"], dz["always"]["passes"],
                                             dz["always"]["fails"]),
          "- sampled (every 15 s and every message 5 s after each drift; the design in force "
          "1 s later): %d checks, %d passes, %d passes by a newer estimate within the second, "
          "%d fails" % (dz["samples"]["checks"], dz["samples"]["passes"],
                        dz["samples"]["superseded_passes"], dz["samples"]["fails"]),
          "- estimates whose optimum was not yet in force: %d, put in force after at most "
          "%.3f s (mean %.3f s); %d superseded before" %
          (dz["changes"]["count"], dz["changes"]["worst_delay_s"], dz["changes"]["mean_delay_s"],
           dz["changes"]["superseded"]),
          "- bridge results (designs published): %d" % dz["bridge_results"], ""]
    for f in dz["always"]["first_fails"] + dz["samples"]["first_fails"]:
        L.append("  - fail: %s" % json.dumps(f, default=list))
    L += ["## Logs", "", "%d error lines in %s" % (logs["error_lines"], ", ".join(logs["logs"]))]
    L += ["    " + h for h in logs["first"]]
    L += ["", "## RSS and open files (samples.csv, soak.png)", "",
          "| role | RSS first (MiB) | ref max (MiB) | 2nd half max (MiB) | last (MiB) | fds 1st half max | fds 2nd half max | ok |",
          "|---|---|---|---|---|---|---|---|"]
    for role, b in bounds.items():
        if "rss_ref_kb" not in b:
            L.append("| %s | %s |" % (role, b["verdict"]))
            continue
        L.append("| %s | %.1f | %.1f | %.1f | %.1f | %d | %d | %s |" %
                 (role, b["rss_first_kb"] / 1024, b["rss_ref_kb"] / 1024,
                  b["rss_late_max_kb"] / 1024, b["rss_last_kb"] / 1024, b["fds_first_half_max"],
                  b["fds_second_half_max"], "yes" if b["rss_ok"] and b["fds_ok"] else "NO"))
    L += ["", "Criterion: second-half max RSS <= 1.10 x max over minutes [M/4, M/2] + 4 MiB; "
          "second-half max fds <= first-half max + 2.", "", "## Requests", ""]
    L += ["- %s: %s" % (k, v) for k, v in sorted(reqs.items())]
    with open(os.path.join(d, "summary.md"), "w") as f:
        f.write("\n".join(L) + "\n")


def main():
    p = argparse.ArgumentParser()
    sub = p.add_subparsers(dest="cmd", required=True)
    r = sub.add_parser("replay")
    r.add_argument("out")
    r.add_argument("--minutes", type=float, required=True)
    r.add_argument("--drift-minutes", type=float, required=True)
    r.add_argument("--rate", type=float, default=50)
    r.add_argument("--seed", type=int, default=11)
    r.add_argument("--profile", choices=["steps", "ramps"], default="steps",
                   help="steps: the mix jumps at each drift; ramps: it moves linearly to the "
                   "next phase's mix over each phase (a slow drift)")
    s = sub.add_parser("request-spec")
    s.add_argument("out")
    s.add_argument("--seed", type=int, required=True)
    c = sub.add_parser("check")
    c.add_argument("dir")
    c.add_argument("--drift-minutes", type=float, required=True)
    c.add_argument("--envdesign", required=True)
    a = p.parse_args()
    if a.cmd == "replay":
        cmd_replay(a)
    elif a.cmd == "request-spec":
        cmd_request_spec(a)
    else:
        sys.exit(cmd_check(a))


if __name__ == "__main__":
    main()
