#!/usr/bin/env bash
# The 1-hour soak of issue 11 (a command, not CI; docs/results/soak.md):
#
#   tests/benchmarks/soak/run.sh [--minutes M] [--out DIR] [--drift-minutes D]
#       [--kill-minutes K] [--rate R] [--request-every S] [--port P] [--domain N] [--bin DIR]
#       [--profile steps|ramps]
#
# Starts, on loopback (LCM udpm on its own port, DDS on its own domain): a coordinator
# (--state-dir), 2 planners, a bridge (--redesign local, --state-dir) and an arrivals
# publisher (R arrivals a second whose task mix changes every D minutes), plus `envdesign
# watch --json` recording every estimate and design the bridge publishes. While it runs: a
# client request every ~S seconds, one planner SIGKILLed and restarted every K minutes, RSS
# and open fds of every process sampled every minute. At the end: soak.py check (design in
# force vs an independent optimum, error lines in the logs, bounds, plot). Exit code 0 when
# every clause passed.
set -u

SOURCE=$(cd "$(dirname "$0")/../../.." && pwd)
ARGS="$*"
MINUTES=60 DRIFT=5 KILL=10 RATE=50 EVERY=3 PORT=7990 DOMAIN=199 PROFILE=steps
BIN=$SOURCE/build/bin OUT=
while [ $# -gt 0 ]; do
    case $1 in
    --minutes) MINUTES=$2 ;;
    --out) OUT=$2 ;;
    --drift-minutes) DRIFT=$2 ;;
    --kill-minutes) KILL=$2 ;;
    --rate) RATE=$2 ;;
    --request-every) EVERY=$2 ;;
    --port) PORT=$2 ;;
    --domain) DOMAIN=$2 ;;
    --bin) BIN=$2 ;;
    --profile) PROFILE=$2 ;;
    *) echo "usage: $0 [--minutes M] [--out DIR] [--drift-minutes D] [--kill-minutes K]" \
        "[--rate R] [--request-every S] [--port P] [--domain N] [--bin DIR] [--profile steps|ramps]" >&2; exit 2 ;;
    esac
    shift 2 || { echo "$0: $1 needs a value" >&2; exit 2; }
done
OUT=${OUT:-$SOURCE/build/soak-$(date -u +%Y%m%dT%H%M%S)}
for b in envdesign envdesign-coordinator envdesign-planner envdesign-bridge envdesign-arrivals; do
    [ -x "$BIN/$b" ] || { echo "$0: $BIN/$b is missing (build it first)" >&2; exit 2; }
done
mkdir -p "$OUT"/{logs,bin,specs,requests,state/coordinator,state/bridge} || exit 2
OUT=$(cd "$OUT" && pwd)
# A copy of the binaries: a rebuild of $BIN during the run does not change what restarts.
cp "$BIN"/envdesign "$BIN"/envdesign-{coordinator,planner,bridge,arrivals} "$OUT/bin/"
B=$OUT/bin
URL="udpm://239.255.76.67:$PORT?ttl=0"
export CYCLONEDDS_URI=file://$SOURCE/deploy/cyclonedds-loopback.xml
SPEC=$SOURCE/tests/arrivals/data/restaurant-drift.textproto
PY=$SOURCE/tests/benchmarks/soak/soak.py
EVENTS=$OUT/events.log
event() { echo "$(date -u +%FT%T.%3NZ) $*" | tee -a "$EVENTS"; }

python3 "$PY" replay "$OUT/arrivals.csv" --minutes "$MINUTES" --drift-minutes "$DRIFT" \
    --rate "$RATE" --profile "$PROFILE" || exit 2
cat >"$OUT/run.json" <<EOF
{"started": "$(date -u +%FT%TZ)", "command": "tests/benchmarks/soak/run.sh $ARGS",
 "commit": "$(git -C "$SOURCE" rev-parse --short HEAD)$(git -C "$SOURCE" diff --quiet HEAD -- common services clients || echo +dirty)",
 "machine": "$(uname -sm), $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), $(awk '/MemTotal/ {printf "%.0f GiB", $2/1048576}' /proc/meminfo)",
 "minutes": $MINUTES, "profile": "$PROFILE", "drift_minutes": $DRIFT, "kill_minutes": $KILL, "rate": $RATE,
 "request_every": $EVERY, "lcm_url": "$URL", "dds_domain": $DOMAIN}
EOF

declare -A PID
start_planner() { # N
    "$B/envdesign-planner" --lcm-url "$URL" --name "planner/soak-$1" \
        >>"$OUT/logs/planner-$1.log" 2>&1 &
    PID[planner-$1]=$!
    event "started planner-$1 pid ${PID[planner-$1]}"
}

"$B/envdesign-coordinator" --lcm-url "$URL" --name coordinator/soak \
    --state-dir "$OUT/state/coordinator" --stored-evaluations 20000 \
    >"$OUT/logs/coordinator.log" 2>&1 &
PID[coordinator]=$!
start_planner 1
start_planner 2
"$B/envdesign-bridge" --problem "restaurant=$SPEC" --domain "$DOMAIN" --lcm-url "$URL" \
    --name bridge/soak --state-dir "$OUT/state/bridge" --estimator window:200 \
    --publish-hz 10 >"$OUT/logs/bridge.log" 2>&1 &
PID[bridge]=$!
"$B/envdesign" watch --json --status --connect "$URL" >"$OUT/logs/watch.jsonl" \
    2>"$OUT/logs/watch.log" &
PID[watch]=$!
sleep 3
"$B/envdesign-arrivals" --replay "$OUT/arrivals.csv" --rate "$RATE" --problem restaurant \
    --site dock-1 --domain "$DOMAIN" --wait-bridge 30 >"$OUT/logs/arrivals.log" 2>&1 &
PID[arrivals]=$!
T0=$(date +%s)
event "arrivals started pid ${PID[arrivals]} ($RATE/s, mix changes every $DRIFT min)"

# Requests: one at a time, every EVERY +- 1 s, until the stop file appears.
request_loop() {
    local n=0
    echo "n,start_utime,seconds,kind,rc,status,design,jobs_sent,stored_answers" >"$OUT/requests.csv"
    while [ ! -e "$OUT/stop" ]; do
        n=$((n + 1))
        local spec=$OUT/specs/request-$n.textproto
        local kind
        kind=$(python3 "$PY" request-spec "$spec" --seed "$n")
        local t1 t2 rc
        t1=$(date +%s.%N)
        timeout 300 "$B/envdesign" design "$spec" --connect "$URL" --json \
            >"$OUT/requests/$n.json" 2>"$OUT/requests/$n.err"
        rc=$?
        t2=$(date +%s.%N)
        python3 - "$OUT/requests/$n.json" "$n" "$t1" "$t2" "$kind" "$rc" \
            >>"$OUT/requests.csv" <<'PYEOF'
import json, sys
path, n, t1, t2, kind, rc = sys.argv[1:]
status = design = jobs = stored = ""
try:
    r = json.load(open(path))
    status, design = r.get("status", ""), "{%s}" % " ".join(r.get("design", []))
    def find(o):
        if isinstance(o, dict):
            if "jobs_sent" in o:
                return o
            for v in o.values():
                f = find(v)
                if f: return f
    c = find(r) or {}
    jobs, stored = c.get("jobs_sent", ""), c.get("stored_answers", "")
except Exception as e:
    status = "unreadable"
print("%s,%d,%.3f,%s,%s,%s,%s,%s,%s" % (n, float(t1) * 1e6, float(t2) - float(t1), kind, rc,
                                        status, design, jobs, stored))
PYEOF
        # Keep the request's stderr in the logs checked at the end; the JSON only if it failed.
        sed "s/^/[request $n] /" "$OUT/requests/$n.err" >>"$OUT/logs/client.log"
        [ "$rc" = 0 ] && rm -f "$OUT/requests/$n.json" "$OUT/requests/$n.err" "$spec"
        sleep "$(python3 -c "import random; print(max(0.5, $EVERY + random.uniform(-1, 1)))")"
    done
}
request_loop &
REQ_LOOP=$!

sample() { # minute
    local role pid rss fds
    for role in coordinator planner-1 planner-2 bridge arrivals watch; do
        pid=${PID[$role]}
        rss=$(awk '/^VmRSS:/ {print $2}' "/proc/$pid/status" 2>/dev/null)
        fds=$(ls "/proc/$pid/fd" 2>/dev/null | wc -l)
        [ -n "$rss" ] || fds=
        echo "$1,$(date +%s%6N),$role,$pid,$rss,$fds" >>"$OUT/samples.csv"
    done
}
echo "minute,utime,role,pid,rss_kb,fds" >"$OUT/samples.csv"

# Whole seconds since T0 (minutes, drift and kill periods may be fractions of a minute).
secs() { python3 -c "print(int(round($1 * 60)))"; }
END=$(secs "$MINUTES") DRIFT_S=$(secs "$DRIFT") KILL_S=$(secs "$KILL")
minute=0 kills=0 next_sample=0 next_kill=$KILL_S next_drift=$DRIFT_S
declare -A DEAD
while :; do
    now=$(($(date +%s) - T0))
    if [ "$now" -ge "$next_sample" ]; then
        sample "$minute"
        minute=$((minute + 1))
        next_sample=$((minute * 60))
    fi
    [ "$now" -ge "$END" ] && break
    if [ "$now" -ge "$next_drift" ]; then
        event "drift: the arrivals' mix changes now (nominal)"
        next_drift=$((next_drift + DRIFT_S))
    fi
    if [ "$now" -ge "$next_kill" ]; then
        kills=$((kills + 1))
        n=$(((kills - 1) % 2 + 1))
        event "SIGKILL planner-$n pid ${PID[planner-$n]}"
        kill -KILL "${PID[planner-$n]}"
        wait "${PID[planner-$n]}" 2>/dev/null
        sleep 1
        start_planner "$n"
        next_kill=$((next_kill + KILL_S))
    fi
    for role in coordinator planner-1 planner-2 bridge watch; do
        if [ -z "${DEAD[$role]:-}" ] && ! kill -0 "${PID[$role]}" 2>/dev/null; then
            DEAD[$role]=1
            event "UNEXPECTED: $role pid ${PID[$role]} is gone"
        fi
    done
    sleep 1
done

event "end: stopping"
touch "$OUT/stop"
wait "$REQ_LOOP"
for role in arrivals bridge planner-1 planner-2 coordinator watch; do
    kill -TERM "${PID[$role]}" 2>/dev/null
    wait "${PID[$role]}"
    event "$role pid ${PID[$role]} exited with $?"
done
python3 "$PY" check "$OUT" --drift-minutes "$DRIFT" --envdesign "$B/envdesign"
rc=$?
event "check exit code $rc; summary: $OUT/summary.md"
exit $rc
