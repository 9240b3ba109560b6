#!/usr/bin/env bash
# install_test.sh BUILD_DIR: `cmake --install` into a scratch prefix, build the client example
# (clients/cpp/example) there with find_package(envdesign), and run it against the installed
# coordinator and planner.
set -euo pipefail

build=$(cd "$1" && pwd)
root=$(cd "$(dirname "$0")/../.." && pwd)
prefix=$(mktemp -d)
url="udpm://239.255.76.67:$((20000 + ($$ % 10000) * 2))?ttl=0"
trap 'ENVDESIGN_BIN=$prefix/bin bash "$root/deploy/cluster.sh" stop --dir "$prefix/cluster" >/dev/null 2>&1 || true; rm -rf "$prefix"' EXIT

cmake --install "$build" --prefix "$prefix" >"$prefix/install.log"
test -f "$prefix/lib/cmake/envdesign/envdesignConfig.cmake"
cmake -S "$root/clients/cpp/example" -B "$prefix/example" -DCMAKE_PREFIX_PATH="$prefix" \
    -DCMAKE_BUILD_TYPE=Release >"$prefix/configure.log"
cmake --build "$prefix/example" >"$prefix/build.log"

ENVDESIGN_BIN=$prefix/bin bash "$root/deploy/cluster.sh" start --planners 1 --lcm-url "$url" \
    --dir "$prefix/cluster"
"$prefix/example/design_remote" "$root/examples/restaurant/c-two-tasks-t10.textproto" "$url" \
    >"$prefix/result.json"
grep -q '"status":"optimal"' "$prefix/result.json"
echo "OK: the installed client library and services designed $(grep -o '"design":\[[^]]*\]' "$prefix/result.json")"
