#!/usr/bin/env bash
# lcm_tools_test.sh BUILD_DIR [--key]: LCM's own tools on envdesign traffic (issue 5, "must
# show"). --key: every process signs with a bus key (ENVDESIGN_KEY_FILE), so the traffic
# carries authentication trailers (common/bus/auth.h) that LCM's Java decoders must skip.
#   1. deploy/cluster.sh starts a coordinator and 2 planners; lcm-logger records a design
#      run and one sample of every message type;
#   2. lcm-spy (deploy/lcm-spy.sh --check, under Xvfb) decodes all ten ENVDESIGN_ channels (the services send their status themselves);
#   3. every ENVDESIGN_ event of the log decodes with the types jar (lcm-spy's type database);
#   4. lcm-logplayer replays the log onto another port, where a second lcm-logger records
#      exactly the same messages, channel by channel.
set -euo pipefail

build=$(cd "$1" && pwd)
root=$(cd "$(dirname "$0")/../.." && pwd)
port=$(python3 "$root/tests/support/test_ports.py" --held-by $$)
replay_port=$(python3 "$root/tests/support/test_ports.py" --held-by $$)
url="udpm://239.255.76.67:$port?ttl=0&recv_buf_size=4194304"
replay_url="udpm://239.255.76.67:$replay_port?ttl=0&recv_buf_size=4194304"
work=$(mktemp -d)
pids=()
cleanup() {
    ENVDESIGN_BIN=$build/bin bash "$root/deploy/cluster.sh" stop --dir "$work/cluster" >/dev/null 2>&1 || true
    for p in "${pids[@]}"; do kill -INT "$p" 2>/dev/null || true; done
    rm -rf "$work"
}
trap cleanup EXIT
if [ "${2:-}" = --key ]; then
    echo "k1 $(head -c 32 /dev/urandom | od -An -tx1 | tr -d ' \n')" >"$work/bus.key"
    chmod 600 "$work/bus.key"
    export ENVDESIGN_KEY_FILE=$work/bus.key
fi
export ENVDESIGN_BIN=$build/bin ENVDESIGN_LCM_JAR=$build/lcmtypes/envdesign_lcmtypes.jar

lcm_jar=$(pkg-config --variable=classpath lcm-java 2>/dev/null || echo /usr/share/java/lcm.jar)
javac -d "$work" -cp "$lcm_jar" "$root/deploy/lcm-spy/LcmCheck.java"
# Channel, type and count of every ENVDESIGN_ event of a log (lcm-spy's type scan chatters).
check_log() {
    java -cp "$lcm_jar:/usr/share/java/jchart2d.jar:$ENVDESIGN_LCM_JAR:$work" LcmCheck log "$1" \
        >"$1.check" 2>&1 || { cat "$1.check"; return 1; }
    grep '^ENVDESIGN_' "$1.check"
}

echo "== 1. a recorded run on $url"
lcm-logger --lcm-url="$url" -f "$work/run.lcmlog" >"$work/logger.out" 2>&1 &
logger=$!
pids+=("$logger")
bash "$root/deploy/cluster.sh" start --planners 2 --lcm-url "$url" --dir "$work/cluster"
sleep 0.3
"$build/bin/design_remote" "$root/examples/restaurant/c-two-tasks-t10.textproto" "$url" >"$work/result.json"
grep -q '"status":"optimal"' "$work/result.json"
"$build/bin/lcm_samples" "$url" --count 2

echo "== 2. lcm-spy decodes every channel"
if command -v xvfb-run >/dev/null && [ -f /usr/share/java/jchart2d.jar ]; then
    # Samples until the spy has checked: Java and Xvfb may take seconds to start on a busy
    # machine, and a spy that starts after the samples end hears only heartbeats.
    "$build/bin/lcm_samples" "$url" --count 600 --period-ms 100 &
    samples=$!
    pids+=("$samples")
    bash "$root/deploy/lcm-spy.sh" --lcm-url "$url" --check 3
    kill "$samples" 2>/dev/null || true
    wait "$samples" || true
else
    echo "SKIPPED: no xvfb-run or jchart2d (deploy/install-deps.sh installs them)"
fi
bash "$root/deploy/cluster.sh" stop --dir "$work/cluster"
sleep 0.3
kill -INT "$logger"
wait "$logger" || true

echo "== 3. the log decodes"
check_log "$work/run.lcmlog" | tee "$work/recorded.txt"
for channel in REQUEST CANCEL PROGRESS RESULT SPEC JOB SPEC_NEED EVALUATION HEARTBEAT STATUS; do
    grep -q "^ENVDESIGN_$channel " "$work/recorded.txt" || { echo "ENVDESIGN_$channel not recorded"; exit 1; }
done

echo "== 4. lcm-logplayer replays it"
lcm-logger --lcm-url="$replay_url" --flush-interval=1 -f "$work/replay.lcmlog" >"$work/logger2.out" 2>&1 &
logger=$!
pids+=("$logger")
sleep 0.5
# At the speed recorded: five times as fast, the logger lost messages in 2 runs of 5 on a
# busy machine (load 7), and the diff failed.
lcm-logplayer --lcm-url="$replay_url" --speed=1 "$work/run.lcmlog"
# Recorded whole once the second log is as long as the first (the same events, each its
# same size; this logger flushes every 1 ms), rather than after a fixed wait a busy machine
# may outlast. Messages lost never get it there: after 10 s the diff says which.
recorded_bytes=$(stat -c %s "$work/run.lcmlog")
for _ in $(seq 100); do
    [ "$(stat -c %s "$work/replay.lcmlog" 2>/dev/null || echo 0)" -ge "$recorded_bytes" ] && break
    sleep 0.1
done
kill -INT "$logger"
wait "$logger" || true
check_log "$work/replay.lcmlog" >"$work/replayed.txt"
diff "$work/recorded.txt" "$work/replayed.txt"
echo "OK: recorded $(wc -l <"$work/recorded.txt") channel/type pairs, replayed identically"
