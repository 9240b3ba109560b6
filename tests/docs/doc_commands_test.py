#!/usr/bin/env python3
"""doc_commands_test.py BUILD_DIR: every command in README.md and docs/**/*.md, as written.

Commands are the lines of indented code blocks (and of ```sh / ```bash fences) that start
with a program (build/bin/..., bash, python3, cmake, ...), continuation lines joined.
Synopses (`envdesign plan DOMAIN PROBLEM [--json]`: placeholders in capitals, [options],
a|b) are not commands. Every command either runs here, offline, in a scratch directory that
mirrors the repository (build/ is BUILD_DIR), with the exit code asserted (0 unless EXIT
says otherwise), or is listed in ELSEWHERE with the test or CI step that runs it, or why it
is a benchmark command that CI does not run. A command that is neither and does not run
fails the test, so a new command in the docs is run from the day it is written. The complete
spec files shown in docs/spec-reference.md (text and JSON) are designed as written too.

    python3 tests/docs/doc_commands_test.py build            # --list: print the table only
"""
import os
import re
import subprocess
import sys
import tempfile

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
PROGRAMS = ("build/bin/", "bash ", "python3 ", "cmake ", "ctest ", "envdesign", "export ",
            "sudo ", "ENVDESIGN_", "CC=", "/tmp/", "pip ", "lcm-spy")

# Command prefixes run by another test or by CI, or benchmark commands (minutes, not CI).
ELSEWHERE = [
    ("bash deploy/build.sh", "CI: .ci/run runs deploy/build.sh, then ctest"),
    ("bash deploy/cluster.sh", "e2e.PythonClient and e2e.InstalledClientLibrary start and stop "
                               "deploy/cluster.sh clusters"),
    ("build/bin/envdesign design examples/restaurant/c-two-tasks-t10.textproto --connect",
     "e2e_tests EndToEnd.CliConnectGivesTheSelfContainedResult"),
    ("build/bin/envdesign status", "e2e_tests Status.CommandListsTheServices"),
    ("build/bin/envdesign watch", "e2e_tests Watch.* (envdesign watch on a local cluster)"),
    ("bash deploy/lcm-spy.sh", "e2e.LcmToolsDecodeRecordAndReplay (lcm-spy on our traffic)"),
    ("export CYCLONEDDS_URI", "bridge_tests (the bridge and arrivals on DDS loopback)"),
    ("build/bin/envdesign-bridge", "bridge_tests (the bridge and arrivals on DDS loopback)"),
    ("build/bin/envdesign-arrivals", "bridge_tests (the bridge and arrivals on DDS loopback)"),
    ("bash clients/python/install.sh", "e2e.PythonClientInstalled (runs it exactly as "
                                       "clients/python/README.md writes it)"),
    ("python3 -m venv", "e2e.PythonClientInstalled"),
    ("/tmp/envdesign-venv/bin/pip install", "e2e.PythonClientInstalled "
                                            "test_installed_package_runs_the_readme_example"),
    ("cmake --install", "e2e.InstalledClientLibrary (tests/e2e/install_test.sh)"),
    ("CC=clang CXX=clang++ cmake", "a second compiler's full build: not CI"),
    ("bash tests/fuzz/", "fuzzing (minutes per target); ctest replays the corpora"),
    ("ctest --test-dir build", "CI: .ci/run"),
    ("python3 tests/e2e/lan/lan_test.py", "lan.SiteSurvivesLossPartitionAndCoordinatorKill "
                                          "(ctest -L lan; needs root)"),
    ("python3 tests/benchmarks/", "benchmark command (minutes), not CI; results in docs/results"),
    ("bash tests/benchmarks/", "benchmark or picture command (needs tools deploy/install-deps.sh "
                               "does not install, or minutes), not CI; results in docs/results"),
    ("ENVDESIGN_AGREEMENT_SEEDS=3000", "benchmark run; ctest runs WitnessAgreement with 40 seeds"),
    ("build/bin/cluster_benchmark", "benchmark command (~1 min), not CI"),
    ("build/bin/bridge_benchmark", "benchmark command (~15 s), not CI"),
    ("build/bin/durable_benchmark", "benchmark command, not CI"),
    ("cmake --build build -j2 --target durable_benchmark", "builds the benchmark above"),
    ("bash tests/benchmarks/soak/run.sh", "the 1-hour soak (a command, not CI): "
                                          "docs/results/soak.md"),
    ("cmake --build build -j2 --target envdesign envdesign-coordinator",
     "builds the soak's binaries (docs/results/soak.md)"),
    ("sudo ", "installs system files (systemd, sysctl): deploy/LAN.md, by hand"),
    ("envdesign-bridge --problem warehouse=/tmp/warehouse-floor",
     "FloorLive.ArrivalsOfFloorTasksChangeTheDesign (the bridge on an imported floor)"),
    ("envdesign-arrivals --replay trips.csv --floor",
     "FloorLive.ArrivalsOfFloorTasksChangeTheDesign (trips of an imported floor)"),
    ("envdesign floor import rmf_demos_maps/", "needs a checkout of open-rmf/rmf_demos, never "
                                              "committed: tests/benchmarks/floors/rmf_demos.sh"),
    ("envdesign report /tmp/triple_H/", "follows the rmf_demos import above: not CI"),
]
# Commands the docs show failing on purpose, with the exit code they give.
EXIT = {
    "build/bin/envdesign plan tests/data/bad/undefined-predicate.pddl "
    "tests/data/bad/ok-problem.pddl --json": 2,
    # every design's objective is infinite (docs/cli.md, "Warnings")
    "build/bin/envdesign design tests/data/usability/unsolvable-tasks.textproto --json": 3,
}
TIMEOUT_S = 60


def documents():
    paths = [os.path.join(ROOT, "README.md")]
    for folder, _, files in os.walk(os.path.join(ROOT, "docs")):
        paths += [os.path.join(folder, f) for f in sorted(files) if f.endswith(".md")]
    return sorted(paths)


def is_synopsis(command):
    command = re.sub(r"\s{2,}#.*$", "", command)  # a trailing comment is not the command
    if "[" in command or "..." in command or re.search(r"\w\|\w", command):
        return True
    # A placeholder: a word in capitals (DOMAIN, FILE.csv, HZ) that is not an assignment.
    return any(re.fullmatch(r"[A-Z][A-Z_]*(\.\w+)?", word) for word in command.split()[1:])


def commands_in(path):
    """[(line number, command)] of one Markdown file."""
    found, fence, pending = [], None, None
    lines = open(path).read().splitlines()
    for number, line in enumerate(lines, 1):
        if line.startswith("```"):
            fence = None if fence is not None else line[3:].strip()
            continue
        in_shell_fence = fence in ("sh", "bash", "shell")
        indented = fence is None and line.startswith("    ") and not line.startswith("     |")
        if not (in_shell_fence or indented):
            pending = None
            continue
        text = line.strip()
        if pending is not None:
            pending[1] += " " + text.rstrip("\\").strip()
            if not text.endswith("\\"):
                pending = None
            continue
        if not text.startswith(PROGRAMS):
            continue
        entry = [number, text.rstrip("\\").strip()]
        found.append(entry)
        if text.endswith("\\"):
            pending = entry
    return [(n, c) for n, c in found if not is_synopsis(c)]


def where_run(command):
    for prefix, reason in ELSEWHERE:
        if command.startswith(prefix):
            return reason
    return None


def mirror(build):
    """A scratch directory that looks like the repository with build/ = `build`."""
    work = tempfile.mkdtemp(prefix="envdesign-docs-")
    for name in os.listdir(ROOT):
        if name not in ("build", ".git"):
            os.symlink(os.path.join(ROOT, name), os.path.join(work, name))
    os.symlink(os.path.abspath(build), os.path.join(work, "build"))
    return work


def spec_examples():
    """[(where, suffix, text)]: the complete spec files shown in docs/spec-reference.md (the
    fenced blocks that begin with robot_domain), to be designed as they are written."""
    path = os.path.join(ROOT, "docs", "spec-reference.md")
    found, block, start = [], None, 0
    for number, line in enumerate(open(path).read().splitlines(), 1):
        if line.startswith("```"):
            if block is None:
                block, start = [], number
                continue
            text = "\n".join(block) + "\n"
            if text.startswith("robot_domain"):
                found.append((f"docs/spec-reference.md:{start}", ".textproto", text))
            elif text.startswith('{"robot_domain"'):
                found.append((f"docs/spec-reference.md:{start}", ".json", text))
            block = None
        elif block is not None:
            block.append(line)
    return found


def check_spec_examples(build):
    """Each complete example of the spec reference, beside the restaurant's PDDL files: exit 0."""
    failures = []
    work = tempfile.mkdtemp(prefix="envdesign-spec-examples-")
    for name in os.listdir(os.path.join(ROOT, "examples", "restaurant")):
        if name.endswith(".pddl"):
            os.symlink(os.path.join(ROOT, "examples", "restaurant", name), os.path.join(work, name))
    examples = spec_examples()
    for i, (where, suffix, text) in enumerate(examples):
        spec = os.path.join(work, f"example-{i}{suffix}")
        with open(spec, "w") as f:
            f.write(text)
        done = subprocess.run([os.path.join(build, "bin", "envdesign"), "design", spec, "--json"],
                              capture_output=True, text=True, timeout=TIMEOUT_S)
        print(f"spec      {where}: exit {done.returncode}")
        if done.returncode != 0:
            failures.append(f"{where}: the example spec does not design:\n{done.stderr}")
    if len(examples) < 2:
        failures.append("docs/spec-reference.md: the text and JSON examples were not found")
    return failures


def main(argv):
    build = argv[1]
    listing = "--list" in argv
    work = mirror(build)
    # Bare `envdesign ...` lines mean the installed binaries: build/bin stands in for them.
    env = dict(os.environ, PATH=os.path.join(work, "build", "bin") + os.pathsep +
               os.environ.get("PATH", ""))
    failures, ran, elsewhere = [], 0, 0
    for path in documents():
        for number, command in commands_in(path):
            where = f"{os.path.relpath(path, ROOT)}:{number}"
            reason = where_run(command)
            if reason:
                elsewhere += 1
                print(f"elsewhere {where}: {command}\n    -> {reason}")
                continue
            if listing:
                print(f"run       {where}: {command}")
                continue
            want = EXIT.get(command, 0)
            try:
                done = subprocess.run(["bash", "-c", command], cwd=work, env=env,
                                      capture_output=True, text=True, timeout=TIMEOUT_S)
                code, output = done.returncode, done.stdout + done.stderr
            except subprocess.TimeoutExpired:
                code, output = "timeout", f"no exit within {TIMEOUT_S} s"
            ran += 1
            print(f"run       {where}: {command}\n    -> exit {code}")
            if code != want:
                failures.append(f"{where}: `{command}` exited {code}, not {want}\n{output[-2000:]}")
    print(f"{ran} commands run, {elsewhere} run elsewhere (listed above)")
    if not listing:
        failures += check_spec_examples(build)
    for failure in failures:
        print("FAIL " + failure, file=sys.stderr)
    if not listing and ran == 0:
        print("FAIL no command found to run: the extraction is broken", file=sys.stderr)
        return 1
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
