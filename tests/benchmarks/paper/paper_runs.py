"""Shared by run_table1.py and run_interplay.py: running `envdesign design` on a spec and
reading its JSON result (SPEC.md, "JSON result of design"), small statistics, and the tables
they write."""
import csv
import datetime
import json
import math
import os
import platform
import re
import resource
import statistics
import subprocess
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))))
DATA = os.path.join(ROOT, "tests", "data", "paper")
RESULTS = os.path.join(ROOT, "docs", "results")
ENVDESIGN = os.path.join(ROOT, "build", "bin", "envdesign")
DOMAINS = ("blocksworld", "grid", "driverlog")
DOMAIN_TITLES = {"blocksworld": "Blocksworld", "grid": "IPC-Grid", "driverlog": "Driverlog"}


def number(value):
    """A JSON number of the result; "inf" (SPEC.md) becomes math.inf."""
    return math.inf if value == "inf" else float(value)


def run_design(binary, spec, time_limit, extra=(), nice=10):
    """Runs `envdesign design SPEC --json` (one planner thread) and returns its JSON result
    with "wall" (seconds of the whole process) and "exit_code" added."""
    command = ["nice", "-n", str(nice), binary, "--log-level", "warn", "design", spec, "--json",
               "--workers", "1", "--time-limit", str(time_limit), *extra]
    start = time.perf_counter()
    proc = subprocess.run(command, capture_output=True, text=True)
    wall = time.perf_counter() - start
    if proc.returncode not in (0, 4) or not proc.stdout.strip():
        raise RuntimeError(f"{' '.join(command)} exited {proc.returncode}: {proc.stderr.strip()}")
    result = json.loads(proc.stdout)
    result["wall"] = wall
    result["exit_code"] = proc.returncode
    return result


def run_measured(binary, spec, time_limit, nice=10):
    """run_design with "cpu" (user + system seconds of the process) and "load" (the 1-minute
    load average as it started) added: on a shared machine the wall time mostly measures
    the others."""
    load = os.getloadavg()[0]
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    result = run_design(binary, spec, time_limit, nice=nice)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    result["cpu"] = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    result["load"] = load
    return result


def target_line(label, runs, target_s=10):
    """One sentence: how many of `runs` (dicts with status, wall, cpu, load) were proven
    optimal, their median and max wall and CPU seconds against `target_s`, the load range."""
    walls = [r["wall"] for r in runs]
    cpus = [r["cpu"] for r in runs if "cpu" in r]
    loads = [r["load"] for r in runs if "load" in r]
    optimal = sum(r["status"] == "optimal" for r in runs)
    text = (f"{label}: {optimal}/{len(runs)} proven optimal; wall median "
            f"{fmt(quantile(walls, 0.5))} s, max {fmt(max(walls))} s "
            f"({sum(w > target_s for w in walls)} over {target_s} s)")
    if cpus:
        text += (f"; CPU median {fmt(quantile(cpus, 0.5))} s, max {fmt(max(cpus))} s "
                 f"({sum(c > target_s for c in cpus)} over {target_s} s)")
    if loads:
        text += f"; load average {fmt(min(loads), 1)} to {fmt(max(loads), 1)} as runs started"
    return text + "."


def derived_spec(spec, directory, **fields):
    """A copy of `spec` in `directory` with scalar `fields` (alpha=0.5, horizon=20, ...)
    replaced or added and the PDDL paths made absolute, so it runs from anywhere."""
    with open(spec) as f:
        text = f.read()
    base = os.path.dirname(os.path.abspath(spec))
    text = re.sub(r'\b(robot_domain|human_domain|problem|human_problem): "([^"]+)"',
                  lambda m: f'{m.group(1)}: "{os.path.join(base, m.group(2))}"', text)
    for name, value in fields.items():
        pattern = rf"\b{name}: [^\s#]+"
        if re.search(pattern, text):
            text = re.sub(pattern, f"{name}: {value}", text)
        else:
            text += f"{name}: {value}\n"
    handle, path = tempfile.mkstemp(suffix=".textproto", dir=directory)
    with os.fdopen(handle, "w") as f:
        f.write(text)
    return path


def mean(values):
    return statistics.fmean(values) if values else math.nan


def sd(values):
    """Sample standard deviation (n - 1); 0 for one value."""
    return statistics.stdev(values) if len(values) > 1 else 0.0


def percent_change(before, after):
    return (after - before) / before * 100 if before else math.nan


def quantile(values, q):
    """The q-quantile by linear interpolation between order statistics."""
    ordered = sorted(values)
    position = q * (len(ordered) - 1)
    low = math.floor(position)
    high = min(low + 1, len(ordered) - 1)
    return ordered[low] + (ordered[high] - ordered[low]) * (position - low)


def fmt(value, digits=2):
    if isinstance(value, str):
        return value
    if value is None or (isinstance(value, float) and math.isnan(value)):
        return "-"
    if math.isinf(value):
        return "inf"
    return f"{value:.{digits}f}"


def markdown_table(header, rows):
    lines = ["| " + " | ".join(header) + " |", "|" + "|".join("---" for _ in header) + "|"]
    lines += ["| " + " | ".join(str(c) for c in row) + " |" for row in rows]
    return "\n".join(lines)


def write_csv(path, header, rows):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w", newline="") as f:
        writer = csv.writer(f, lineterminator="\n")
        writer.writerow(header)
        writer.writerows(rows)


def environment_note(binary, commit=None):
    """Where and with what the numbers were measured; `commit`: the one the binary was built
    from (default: this repository's HEAD)."""
    def git(*args):
        proc = subprocess.run(["git", "-C", ROOT, *args], capture_output=True, text=True)
        return proc.stdout.strip()
    cpu = "unknown CPU"
    try:
        with open("/proc/cpuinfo") as f:
            cpu = next(line.split(":", 1)[1].strip() for line in f if line.startswith("model name"))
    except (OSError, StopIteration):
        pass
    commit = commit or git("rev-parse", "--short", "HEAD")
    return (f"Measured {datetime.date.today().isoformat()} on {platform.node() or 'this machine'}: "
            f"{os.cpu_count()} cores ({cpu}), shared with other jobs; every run `nice -n 10`, one "
            f"planner thread (`--workers 1`), runs one after another. Binary `"
            f"{os.path.basename(binary)}` built from commit {commit} (Release).")
