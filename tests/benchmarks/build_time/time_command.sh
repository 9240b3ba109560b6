#!/usr/bin/env bash
# A compiler launcher that logs what each compile and link costs:
#   cmake -DCMAKE_CXX_COMPILER_LAUNCHER=$PWD/tests/benchmarks/build_time/time_command.sh ...
# appends "WALL_S CPU_S OUTPUT" to $ENVDESIGN_TIME_LOG (default /tmp/envdesign-times.txt).
# CPU seconds (user + system, GNU time) are what a file costs whatever else runs; wall
# seconds grow with the load. time_fresh_clone.sh sums the log up. No build the README
# gives uses it.
set -uo pipefail
log="${ENVDESIGN_TIME_LOG:-/tmp/envdesign-times.txt}"
output="?"
previous=""
for arg in "$@"; do
    [ "$previous" = "-o" ] && output="$arg"
    previous="$arg"
done
if [ ! -x /usr/bin/time ]; then  # Debian's package `time`; without it, no CPU seconds
    start=$(date +%s.%N)
    "$@"
    status=$?
    printf '%.2f - %s\n' "$(echo "$(date +%s.%N) - $start" | bc)" "$output" >>"$log"
    exit $status
fi
measured=$(mktemp)
/usr/bin/time -f '%e %U %S' -o "$measured" "$@"
status=$?
read -r wall user system < <(tail -1 "$measured") # after "Command exited with ..."
rm -f "$measured"
printf '%s %.2f %s\n' "$wall" "$(echo "$user + $system" | bc)" "$output" >>"$log"
exit $status
