#!/usr/bin/env bash
# Runs each libFuzzer target (built by tests/fuzz/build.sh) for SECONDS, one after another,
# starting from its committed corpus (tests/fuzz/corpus/NAME, never written to: new inputs go
# to BUILD/fuzz-corpus/NAME). Prints executions and coverage per target; crashing inputs are
# kept in BUILD/fuzz-artifacts/. Exit 1 if any target found a crash, leak or timeout.
#   bash tests/fuzz/run.sh 600 [NAME ...]
set -uo pipefail
cd "$(dirname "$0")/../.."
seconds=${1:?usage: run.sh SECONDS [NAME ...]}
shift
dir=${ENVDESIGN_FUZZ_BUILD:-build-fuzz}
names=("$@")
[ ${#names[@]} -gt 0 ] || names=(pddl spec_text spec_json coordinator planner intake store_records numbers
    service_config wire_numbers floor_inputs)
mkdir -p "$dir/fuzz-artifacts" "$dir/fuzz-logs"
failed=0
printf '%-12s %8s %12s %8s %8s %8s  %s\n' target seconds executions exec/s cov ft result
for name in "${names[@]}"; do
    binary="$dir/bin/fuzz_$name"
    [ -x "$binary" ] || { echo "fuzz: $binary missing: run tests/fuzz/build.sh"; exit 1; }
    mkdir -p "$dir/fuzz-corpus/$name"
    log="$dir/fuzz-logs/$name.log"
    # -rss_limit_mb: a leak or a bound that does not hold shows as an out-of-memory finding.
    "$binary" "$dir/fuzz-corpus/$name" "tests/fuzz/corpus/$name" -max_total_time="$seconds" \
        -timeout=60 -rss_limit_mb=2048 -max_len=65536 -print_final_stats=1 \
        -artifact_prefix="$dir/fuzz-artifacts/$name-" >"$log" 2>&1
    code=$?
    last=$(grep -E '^#[0-9]+' "$log" | tail -1)
    runs=$(grep -E '^stat::number_of_executed_units' "$log" | awk '{print $2}')
    speed=$(grep -E '^stat::average_exec_per_sec' "$log" | awk '{print $2}')
    cov=$(sed -nE 's/.*cov: ([0-9]+).*/\1/p' <<<"$last")
    ft=$(sed -nE 's/.*ft: ([0-9]+).*/\1/p' <<<"$last")
    result=ok
    if [ $code -ne 0 ]; then
        result="FOUND (exit $code, see $log)"
        failed=1
    fi
    printf '%-12s %8s %12s %8s %8s %8s  %s\n' "$name" "$seconds" "${runs:-?}" "${speed:-?}" \
        "${cov:-?}" "${ft:-?}" "$result"
done
exit $failed
