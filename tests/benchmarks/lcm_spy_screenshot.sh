#!/usr/bin/env bash
# tests/benchmarks/lcm_spy_screenshot.sh [OUT.png]
#
# The picture in docs/results/lcm-spy.md: a local cluster (coordinator + 2 planners) on a
# loopback LCM URL, lcm-spy started through deploy/lcm-spy.sh (so it has envdesign's Java
# types) under Xvfb, the ENVDESIGN_STATUS row double-clicked to open lcm-spy's decoded view,
# and the screen saved as PNG. Not run by CI. Needs build/bin/envdesign-{coordinator,planner},
# build/lcmtypes/envdesign_lcmtypes.jar, and (beyond deploy/install-deps.sh) the Debian
# packages xdotool, x11-apps (xwd) and netpbm:
#
#   cmake --build build --target envdesign-coordinator envdesign-planner envdesign_lcmtypes_jar
#   apt-get install xdotool x11-apps netpbm
#   bash tests/benchmarks/lcm_spy_screenshot.sh docs/results/lcm-spy-status.png
set -euo pipefail

root=$(cd "$(dirname "$0")/../.." && pwd)
out=$(realpath -m "${1:-$root/docs/results/lcm-spy-status.png}")
# A port of its own, so that other LCM runs on this host neither show up nor are disturbed.
url='udpm://239.255.76.67:7793?ttl=0'
work=$(mktemp -d)
xvfb_pid=""
spy_pid=""

cleanup() {
    if [ -n "$spy_pid" ]; then kill "$spy_pid" 2>/dev/null || true; fi
    if [ -n "$xvfb_pid" ]; then kill "$xvfb_pid" 2>/dev/null || true; fi
    bash "$root/deploy/cluster.sh" stop --dir "$work/cluster" >/dev/null || true
    rm -rf "$work"
}
trap cleanup EXIT

mkdir -p "$work/cluster"
bash "$root/deploy/cluster.sh" start --planners 2 --lcm-url "$url" --dir "$work/cluster"

# Xvfb picks a free display and writes its number to fd 3. No window manager: windows have no
# title bars and we place them ourselves.
exec 3>"$work/display"
Xvfb -displayfd 3 -screen 0 800x720x24 -nolisten tcp >"$work/xvfb.log" 2>&1 &
xvfb_pid=$!
exec 3>&-
for _ in $(seq 50); do [ -s "$work/display" ] && break; sleep 0.1; done
DISPLAY=":$(cat "$work/display")"
export DISPLAY

# lcm-spy.sh execs java, so this pid is lcm-spy's.
bash "$root/deploy/lcm-spy.sh" --lcm-url "$url" >"$work/spy.log" 2>&1 &
spy_pid=$!
spy_window=$(timeout 30 xdotool search --sync --name '^LCM Spy$' | head -1)
# Every service sends its status once a second; let a few arrive (and lcm-spy's rates settle).
sleep 6

# The channel table is sorted by name; an idle cluster sends only ENVDESIGN_HEARTBEAT and
# ENVDESIGN_STATUS, so STATUS is the second row (header 19 px, rows 16 px, at x = 80).
xdotool mousemove --sync 80 43 click --repeat 2 --delay 80 1
view_window=$(timeout 10 xdotool search --sync --name '^ENVDESIGN_STATUS$' | head -1)
xdotool windowsize "$spy_window" 800 150
xdotool windowmove "$view_window" 0 155
xdotool windowsize "$view_window" 800 560
sleep 3 # a few more messages, so the decoded view's sparklines have a history

mkdir -p "$(dirname "$out")"
xwd -root -silent | xwdtopnm 2>/dev/null | pnmtopng >"$out"
echo "lcm_spy_screenshot.sh: wrote $out"
