#!/usr/bin/env bash
# The floor import on real maps (issue 22; not CI): every building map of an rmf_demos
# checkout, every level, then `design` with 1 worker on office and triple_H (default tasks)
# and on the largest fleet graph (airport_terminal L1, graph 2) with a file of 40 tasks.
# Prints the table of docs/results/floors.md. rmf_demos' files stay where they are.
#
#   bash tests/benchmarks/floors/rmf_demos.sh RMF_DEMOS_DIR [BUILD_DIR] [SECONDS]
set -euo pipefail
demos=$1
build=${2:-build}
limit=${3:-60}
envdesign="$build/bin/envdesign"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

echo "| map | level | graph | places | robot edges | human-only edges | tasks | candidates |"
echo "|---|---|---|---|---|---|---|---|"
for map in "$demos"/rmf_demos_maps/maps/*/*.building.yaml; do
    name=$(basename "$map" .building.yaml)
    for level in L1 L2 L3; do
        for graph in 0 1 2 3 4 5; do
            out=$("$envdesign" floor import "$map" --level "$level" --graph "$graph" \
                -o "$work/$name-$level-$graph" 2>&1 | grep -v "dropped" | head -1) || true
            case "$out" in
            wrote*)
                echo "$out" | sed -E "s/^wrote [^:]*: ([0-9]+) places, ([0-9]+) robot edges, ([0-9]+) human-only edges, ([0-9]+) tasks, ([0-9]+) candidates/| $name | $level | $graph | \1 | \2 | \3 | \4 | \5 |/"
                ;;
            *"not supported"*)
                [ "$level$graph" = L10 ] && echo "| $name | | | refused: ${out#*error: } | | | | |"
                ;;
            esac
        done
    done
done

# 40 tasks of the largest graph, every k-th default pair, weights 1, 2, 3 in turn.
python3 - "$work/airport_terminal-L1-2/floor.json" "$work/airport-40.csv" <<'PY'
import json, sys
tasks = json.load(open(sys.argv[1]))["tasks"]
pick = tasks[:: len(tasks) // 40][:40]
with open(sys.argv[2], "w") as f:
    f.write("from,to,weight\n")
    for i, t in enumerate(pick):
        f.write(f"{t['from']},{t['to']},{1 + i % 3}\n")
PY
"$envdesign" floor import "$demos/rmf_demos_maps/maps/airport_terminal/airport_terminal.building.yaml" \
    --graph 2 --tasks "$work/airport-40.csv" --candidates tape,lane -o "$work/airport-40" >/dev/null 2>&1

echo
echo "| design | candidates | status | objective | designs evaluated | seconds | CPU seconds |"
echo "|---|---|---|---|---|---|---|"
# CPU seconds beside the wall clock: on a machine busy with other work the wall clock of one
# worker stretches, its CPU time does not (and is what a quiet machine's wall clock is).
run() { # NAME SPEC
    python3 - "$1" "$2" "$envdesign" "$limit" <<'PY'
import json, resource, subprocess, sys
name, spec, envdesign, limit = sys.argv[1:5]
out = subprocess.run([envdesign, "design", spec + "/design.textproto", "--workers", "1",
                      "--time-limit", limit, "--json"], capture_output=True, text=True).stdout
usage = resource.getrusage(resource.RUSAGE_CHILDREN)
r = json.loads(out)
candidates = open(spec + "/design.textproto").read().count("modification {")
print(f"| {name} | {candidates} | {r['status']} | {r['objective']:.2f} | "
      f"{r['configurations_evaluated']} | {r['seconds']:.1f} | "
      f"{usage.ru_utime + usage.ru_stime:.1f} |")
PY
}
run "triple_H L1 graph 0, default tasks" "$work/triple_H-L1-0"
run "office L1 graph 0, default tasks" "$work/office-L1-0"
"$envdesign" floor import "$demos/rmf_demos_maps/maps/office/office.building.yaml" \
    --candidates tape -o "$work/office-tape" >/dev/null 2>&1
run "office L1 graph 0, default tasks, tapes only" "$work/office-tape"
run "airport_terminal L1 graph 2, 40 tasks" "$work/airport-40"
