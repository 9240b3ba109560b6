#!/usr/bin/env bash
# deploy/cluster.sh start|stop|status [--planners N] [--workers W] [--lcm-url URL] [--dir DIR]
#                                     [--key-file FILE]
#
# A local envdesign cluster on this machine: one envdesign-coordinator and N envdesign-planner
# processes (default 2) on LCM's loopback default (udpm://239.255.76.67:7667?ttl=0; ttl=0
# keeps every datagram on this host). Logs and pid files go to DIR (default
# /tmp/envdesign-cluster), as coordinator.log and planner-N.log. Each process keeps its own
# default name on the bus, ROLE/HOST/PID (coordinator/vm/4242): two clusters started on one
# bus with other --dir have no name in common, so `envdesign status` shows every process and
# a job reaches the one planner it is addressed to (docs/services.md, "Names and two clusters
# on one bus"). `start` returns once every process is up; `stop` sends SIGTERM
# (planners first, so the coordinator hears them go), waits up to 10 s, then SIGKILLs.
# Both are idempotent. Binaries: $ENVDESIGN_BIN, else build/bin beside this script.
# --key-file (or $ENVDESIGN_KEY_FILE, which the services read themselves): bus keys.
#
#   bash deploy/cluster.sh start --planners 2
#   build/bin/envdesign design examples/restaurant/c-two-tasks-t10.textproto \
#       --connect 'udpm://239.255.76.67:7667?ttl=0'
#   bash deploy/cluster.sh stop
set -euo pipefail

here=$(cd "$(dirname "$0")" && pwd)
bin=${ENVDESIGN_BIN:-$here/../build/bin}
action=${1:-}
shift || true
planners=2
workers=1
url=${LCM_DEFAULT_URL:-udpm://239.255.76.67:7667?ttl=0}
dir=/tmp/envdesign-cluster
key_flags=()
while [ $# -gt 0 ]; do
    case $1 in
        --planners) planners=$2; shift 2 ;;
        --workers) workers=$2; shift 2 ;;
        --lcm-url) url=$2; shift 2 ;;
        --dir) dir=$2; shift 2 ;;
        --key-file) key_flags=(--key-file "$2"); shift 2 ;;
        *) echo "cluster.sh: unknown option $1" >&2; exit 2 ;;
    esac
done

alive() { [ -f "$1" ] && kill -0 "$(cat "$1")" 2>/dev/null; }

# bus_name FILE ROLE: the process's name on the bus (the services' default, ROLE/HOST/PID).
bus_name() { echo "$2/$HOSTNAME/$(cat "$1")"; }

# start_one FILE ARGS...: starts a service, logging to FILE.log, unless FILE.pid names a live
# process. No --name: the service's default is unique on the bus.
start_one() {
    local file=$1; shift
    if alive "$dir/$file.pid"; then
        echo "cluster.sh: $file already running (pid $(cat "$dir/$file.pid"))"
        return
    fi
    "$@" --lcm-url "$url" ${key_flags[@]+"${key_flags[@]}"} >"$dir/$file.log" 2>&1 &
    echo $! >"$dir/$file.pid"
}

# The service logs "on URL" once its bus is open; a process that died says why in its log.
wait_up() {
    local name=$1
    for _ in $(seq 100); do
        grep -q "| on " "$dir/$name.log" 2>/dev/null && return 0
        alive "$dir/$name.pid" || break
        sleep 0.05
    done
    echo "cluster.sh: $name did not start; its log:" >&2
    cat "$dir/$name.log" >&2
    return 1
}

stop_all() {
    local pids=() f
    for f in "$dir"/planner-*.pid "$dir"/coordinator.pid; do
        [ -f "$f" ] || continue
        if alive "$f"; then
            kill -TERM "$(cat "$f")"
            pids+=("$(cat "$f")")
        fi
    done
    for _ in $(seq 100); do
        local left=0 p
        for p in "${pids[@]}"; do kill -0 "$p" 2>/dev/null && left=1; done
        [ $left = 0 ] && break
        sleep 0.1
    done
    for p in "${pids[@]}"; do kill -0 "$p" 2>/dev/null && kill -KILL "$p" && echo "cluster.sh: killed $p"; done
    rm -f "$dir"/*.pid
    echo "cluster.sh: stopped ${#pids[@]} process(es)"
}

case $action in
    start)
        mkdir -p "$dir"
        start_one coordinator "$bin/envdesign-coordinator"
        for i in $(seq 1 "$planners"); do
            start_one "planner-$i" "$bin/envdesign-planner" --workers "$workers"
        done
        wait_up coordinator
        for i in $(seq 1 "$planners"); do wait_up "planner-$i"; done
        echo "cluster.sh: $(bus_name "$dir/coordinator.pid" coordinator) and $planners planner(s) on $url (logs in $dir)"
        ;;
    stop)
        stop_all
        ;;
    status)
        for f in "$dir"/*.pid; do
            [ -f "$f" ] || continue
            n=$(basename "$f" .pid)
            if alive "$f"; then
                echo "$n: running as $(bus_name "$f" "${n%%-*}") (pid $(cat "$f"))"
            else
                echo "$n: dead"
            fi
        done
        ;;
    *)
        echo "usage: cluster.sh start|stop|status [--planners N] [--workers W] [--lcm-url URL] [--dir DIR] [--key-file FILE]" >&2
        exit 2
        ;;
esac
