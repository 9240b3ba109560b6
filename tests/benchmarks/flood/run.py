#!/usr/bin/env python3
"""run.py [--runs N] [--build BUILD_DIR]: a well-behaved client's request under issue 21's flood.

Runs `e2e_tests Starvation.AFloodOfNeverEndingRequestsDoesNotStarveAnotherClient` N times
(each: a keyed cluster of one coordinator and two planners; three requests each of the
restaurant and of a fresh copy of blocksworld 14 quiet, then forty never-ending requests from
forty names in one process, then the same six requests again) and prints, for both sizes,
each test run's medians and ratio, and the medians over every request of every run, with
the load average before and after (the VM is shared: other builds change the numbers).
Results: docs/results/robustness.md.

    python3 tests/benchmarks/flood/run.py --runs 6
"""
import argparse
import os
import re
import statistics
import subprocess
import sys

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "..", ".."))
TEST = "Starvation.AFloodOfNeverEndingRequestsDoesNotStarveAnotherClient"
LINE = re.compile(r"^(restaurant|blocksworld 14): quiet ([0-9. e-]+) s \(median [^)]*\), "
                  r"under the flood ([0-9. e-]+) s \(median")


def one_run(binary):
    """The quiet and flooded seconds of each size in one test run, and whether it passed."""
    out = subprocess.run([binary, "--gtest_filter=" + TEST], capture_output=True, text=True,
                         timeout=600).stdout
    times = {}
    for line in out.splitlines():
        m = LINE.match(line)
        if m:
            times[m[1]] = ([float(x) for x in m[2].split()], [float(x) for x in m[3].split()])
    return times, "[  PASSED  ] 1 test" in out


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--runs", type=int, default=6)
    parser.add_argument("--build", default=os.path.join(ROOT, "build"))
    args = parser.parse_args()
    binary = os.path.join(args.build, "bin", "e2e_tests")
    pooled = {}
    load_before = os.getloadavg()
    passed = 0
    for run in range(args.runs):
        times, ok = one_run(binary)
        passed += ok
        row = []
        for size, (quiet, flooded) in times.items():
            q, f = statistics.median(quiet), statistics.median(flooded)
            row.append(f"{size} {q:.3f} -> {f:.3f} s ({f / q:.2f}x)")
            pooled.setdefault(size, ([], []))
            pooled[size][0].extend(quiet)
            pooled[size][1].extend(flooded)
        print(f"run {run + 1}: {'; '.join(row)}{'' if ok else ' (test failed)'}", flush=True)
    load_after = os.getloadavg()
    print(f"load average (1, 5, 15 min) before {load_before[0]:.2f} {load_before[1]:.2f} "
          f"{load_before[2]:.2f}, after {load_after[0]:.2f} {load_after[1]:.2f} "
          f"{load_after[2]:.2f}; {passed}/{args.runs} test runs passed")
    for size, (quiet, flooded) in pooled.items():
        q, f = statistics.median(quiet), statistics.median(flooded)
        print(f"{size}: {len(quiet)} requests each; quiet median {q:.3f} s "
              f"({min(quiet):.3f}-{max(quiet):.3f}), flooded median {f:.3f} s "
              f"({min(flooded):.3f}-{max(flooded):.3f}): {f / q:.2f}x")
    return 0 if pooled else 1


if __name__ == "__main__":
    sys.exit(main())
