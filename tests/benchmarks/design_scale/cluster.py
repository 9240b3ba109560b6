#!/usr/bin/env python3
"""The witness search through the coordinator and 2 planner processes (issue 9).

  python3 tests/benchmarks/design_scale/cluster.py [--sizes 48,64] [--tasks 10] [--seed 1]
      [--time-limit 120] [--binary-dir build/bin]

Starts a local cluster (deploy/cluster.sh, 2 planners, a private udpm port on loopback). For
each generated warehouse floor (generate.py) it runs `envdesign design --json` in-process and
`--connect` through the cluster, and checks they give the same status, design and objective.
Then it sends the same spec again (every evaluation stored on the coordinator), and a spec
whose task distribution drifted (the two likeliest tasks swap their probabilities), checked
against an in-process run of the drifted spec. It prints the coordinator's search seconds and
the client's wall time (process start, spec upload and answer included) of each request.
"""
import argparse
import json
import os
import re
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(os.path.dirname(HERE)))


def design(binary_dir, spec, time_limit, url=None):
    command = [os.path.join(binary_dir, "envdesign"), "design", spec, "--json", "--workers", "1",
               "--time-limit", str(time_limit)]
    if url:
        command += ["--connect", url]
    start = time.monotonic()
    done = subprocess.run(command, capture_output=True, text=True)
    wall = time.monotonic() - start
    if done.returncode not in (0, 4):
        sys.exit(f"{' '.join(command)}: exit {done.returncode}\n{done.stderr}")
    return json.loads(done.stdout), wall


def drifted(spec):
    """The spec with its two likeliest tasks' probabilities swapped."""
    text = open(spec).read()
    found = re.findall(r"probability: ([0-9.]+)", text)
    ranked = sorted(set(found), key=float, reverse=True)
    a, b = ranked[0], ranked[1]
    text = text.replace(f"probability: {a}", "probability: @").replace(
        f"probability: {b}", f"probability: {a}").replace("probability: @", f"probability: {b}")
    path = spec.replace("spec.textproto", "drifted.textproto")
    open(path, "w").write(text)
    return path


def same(a, b):
    return all(a[k] == b[k] for k in ("status", "design")) and \
        abs(a["objective"] - b["objective"]) <= 1e-9 * max(1.0, abs(a["objective"]))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--sizes", default="48,64")
    parser.add_argument("--tasks", type=int, default=10)
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--time-limit", type=float, default=120)
    parser.add_argument("--binary-dir", default=os.path.join(ROOT, "build", "bin"))
    args = parser.parse_args()
    work = tempfile.mkdtemp(prefix="envdesign-cluster-bench-")
    sys.path.insert(0, os.path.join(ROOT, "tests", "support"))
    from test_ports import claim_udp_port, udpm_test_url
    url = udpm_test_url(claim_udp_port())
    cluster = ["bash", os.path.join(ROOT, "deploy", "cluster.sh")]
    env = dict(os.environ, ENVDESIGN_BIN=args.binary_dir)
    where = ["--lcm-url", url, "--dir", os.path.join(work, "cluster")]
    subprocess.run(cluster + ["start", "--planners", "2"] + where, check=True, env=env)
    try:
        print("n tasks request status objective same coordinator_s client_s jobs stored")
        for n in (int(s) for s in args.sizes.split(",")):
            out = os.path.join(work, f"warehouse-{n}")
            subprocess.run([sys.executable, os.path.join(HERE, "generate.py"), "--kind",
                            "warehouse", "--mods", str(n), "--tasks", str(args.tasks), "--seed",
                            str(args.seed), "--out", out], check=True, capture_output=True)
            spec = os.path.join(out, "spec.textproto")
            moved = drifted(spec)
            for label, path in (("first", spec), ("repeat", spec), ("drift", moved)):
                local, _ = design(args.binary_dir, path, args.time_limit)
                remote, wall = design(args.binary_dir, path, args.time_limit, url)
                c = remote["cluster"]
                print(f"{n} {args.tasks} {label} {remote['status']} {remote['objective']:.6f} "
                      f"{same(local, remote)} {remote['seconds']:.3f} {wall:.3f} "
                      f"{c['jobs_sent']} {c['stored_answers']}", flush=True)
    finally:
        subprocess.run(cluster + ["stop"] + where, env=env)


if __name__ == "__main__":
    main()
