#!/usr/bin/env bash
# The README's two commands on a fresh clone, timed (issue 25; a benchmark, not CI).
#
#   bash tests/benchmarks/build_time/time_fresh_clone.sh [--first-only|--tests-only] [REPO] [WORK]
#
# Clones REPO (default: this repository's HEAD) into WORK (default /tmp/envdesign-fresh-clone,
# replaced), with ../shared beside it as a link, and runs there, as README.md writes them:
#   1. the first command (build the CLI, design the restaurant): seconds to its answer;
#   2. the test command (build everything, run every test): seconds to its end.
# --first-only runs the first alone; --tests-only the test command alone, on the fresh clone
# (what a new user who runs only the tests waits: every compile is the test command's).
# ccache starts empty (a fresh machine has no cache), and every compile and link is logged
# with its wall and CPU seconds (time_command.sh); at the end, the slowest files, each
# step's CPU seconds, and the machine's load, which stretches wall time on a shared machine.
# Packages are not timed: deploy/install-deps.sh finds them installed (docs/results/build.md
# says what a fresh machine downloads).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
run_first=1 run_tests=1
case ${1:-} in
    --first-only) run_tests=0; shift ;;
    --tests-only) run_first=0; shift ;;
esac
repo=${1:-$(cd "$here/../../.." && pwd)}
work=${2:-/tmp/envdesign-fresh-clone}
shared=$(cd "$repo/../shared" && pwd)

rm -rf "$work"
mkdir -p "$work"
git clone -q "$repo" "$work/envdesign"
ln -s "$shared" "$work/shared"
cd "$work/envdesign"

# The commands as the README writes them: its indented lines that run deploy/build.sh.
first=$(grep -E '^    bash deploy/build.sh .*build/bin/envdesign design' README.md | head -1 | sed 's/^ *//')
tests=$(grep -E '^    bash deploy/build.sh && ctest' README.md | head -1 | sed 's/^ *//')
[ -n "$first" ] && [ -n "$tests" ] || { echo "the README's two commands not found" >&2; exit 1; }

export CCACHE_DIR=$work/ccache
export ENVDESIGN_TIME_LOG=$work/compile-times.txt
# CMake (3.17+) takes a launcher from the environment on the first configure: the timing
# launcher, in front of ccache when there is one, as deploy/build.sh would use it.
launcher=$here/time_command.sh
command -v ccache >/dev/null && launcher="$launcher;$(command -v ccache)"
export CMAKE_CXX_COMPILER_LAUNCHER=$launcher CMAKE_C_COMPILER_LAUNCHER=$launcher

# step NAME COMMAND: runs COMMAND with bash, prints its wall and CPU seconds (children too)
# and the machine's load: before, after, and the mean of one-minute load averages taken
# every 10 s meanwhile (the other builds and tests that shared the cores).
step() {
    local name=$1 command=$2 log="$work/$1.log"
    local load_before start end cpu sampler
    load_before=$(cut -d' ' -f1 /proc/loadavg)
    (while sleep 10; do cut -d' ' -f1 /proc/loadavg; done) >"$work/$name.load" &
    sampler=$!
    start=$(date +%s.%N)
    /usr/bin/time -f '%U %S' -o "$work/$name.cpu" bash -c "$command" >"$log" 2>&1 ||
        { kill $sampler; echo "$name failed; the end of $log:"; tail -30 "$log"; exit 1; }
    end=$(date +%s.%N)
    kill $sampler
    cpu=$(awk '{print $1 + $2}' "$work/$name.cpu")
    printf '%-6s %7.1f s wall %7.1f s CPU  (load %s before, %s after, %s mean)\n' "$name" \
        "$(echo "$end - $start" | bc)" "$cpu" "$load_before" "$(cut -d' ' -f1 /proc/loadavg)" \
        "$(awk '{s += $1} END {printf "%.1f", NR ? s / NR : 0}' "$work/$name.load")"
}

echo "clone of $(git rev-parse --short HEAD) in $work/envdesign, $(nproc) cores"
if [ $run_first = 1 ]; then
    echo "first: $first"
    step first "$first"
    grep -q "^design: {barrier-00-01, barrier-10-11}" "$work/first.log" ||
        { echo "the first command did not give the restaurant's design"; exit 1; }
    objects=$(grep -c '\.o$' "$ENVDESIGN_TIME_LOG" || true)
    echo "       $objects compiles; the answer: $(grep '^design: {' "$work/first.log")"
fi
if [ $run_tests = 1 ]; then
    echo "tests: $tests"
    step tests "$tests"
    grep -E "tests passed|tests failed" "$work/tests.log" | tail -1
    # ctest's part of it, and the tests that took longest (wall seconds, under this load).
    grep -E "^Total Test time" "$work/tests.log" | sed 's/^/       ctest: /'
    echo "slowest tests (wall s):"
    sed -nE 's|^ *[0-9]+/[0-9]+ Test +#[0-9]+: ([^ ]+) [ .]*Passed +([0-9.]+) sec$|\2 \1|p' \
        "$work/tests.log" | sort -rn | head -12 | sed 's/^/  /'
fi

echo "slowest compiles (wall s, CPU s, object):"
sort -k2 -rn "$ENVDESIGN_TIME_LOG" | head -12 | sed 's/^/  /'
awk '{cpu += $2} END {printf "all compiles: %.0f CPU s in %d compiler runs\n", cpu, NR}' "$ENVDESIGN_TIME_LOG"
