#!/usr/bin/env bash
# install_test.sh BUILD_DIR: `cmake --install` into a scratch prefix; check that every binary,
# the docs, the examples and the types are there (each binary's --version the project's);
# build the client example (clients/cpp/example) there with find_package(envdesign), and run
# it against the installed coordinator and planner.
set -euo pipefail

build=$(cd "$1" && pwd)
root=$(cd "$(dirname "$0")/../.." && pwd)
prefix=$(mktemp -d)
url="udpm://239.255.76.67:$(python3 "$root/tests/support/test_ports.py" --held-by $$)?ttl=0"
trap 'ENVDESIGN_BIN=$prefix/bin bash "$root/deploy/cluster.sh" stop --dir "$prefix/cluster" >/dev/null 2>&1 || true; rm -rf "$prefix"' EXIT

cmake --install "$build" --prefix "$prefix" >"$prefix/install.log"
test -f "$prefix/lib/cmake/envdesign/envdesignConfig.cmake"

# Every binary, each printing the one version of CMakeLists.txt's project(VERSION).
version=$(sed -n 's/^project(envdesign VERSION \([0-9.]*\).*/\1/p' "$root/CMakeLists.txt")
test -n "$version"
for binary in envdesign envdesign-coordinator envdesign-planner envdesign-bridge envdesign-arrivals; do
    test -x "$prefix/bin/$binary" || { echo "not installed: bin/$binary"; exit 1; }
    got=$("$prefix/bin/$binary" --version)
    [ "$got" = "$binary $version" ] || { echo "$binary --version: '$got', not '$binary $version'"; exit 1; }
done
# The docs README.md links to, and the examples they run.
for doc in README.md docs/concepts.md docs/spec-reference.md docs/cli.md docs/services.md docs/messages.md; do
    test -s "$prefix/share/doc/envdesign/$doc" || { echo "not installed: $doc"; exit 1; }
done
# The installed CLI on the installed example: the two barriers of setting (c).
"$prefix/bin/envdesign" design "$prefix/share/envdesign/examples/restaurant/c-two-tasks-t10.textproto" \
    --json >"$prefix/local.json" 2>/dev/null
grep -q '"design":\["barrier-00-01","barrier-10-11"\]' "$prefix/local.json"
# The types: every .lcm, its C++ header and its Python class; the Python client beside them.
for lcm in "$root"/lcmtypes/envdesign/*.lcm; do
    type=$(basename "$lcm" .lcm)
    test -f "$prefix/share/envdesign/lcmtypes/$type.lcm" || { echo "not installed: $type.lcm"; exit 1; }
    test -f "$prefix/include/envdesign/$type.hpp" || { echo "not installed: $type.hpp"; exit 1; }
    test -f "$prefix/share/envdesign/python/envdesign/$type.py" || { echo "not installed: $type.py"; exit 1; }
done
env -u ENVDESIGN_PYTHON_TYPES python3 -c "import sys; sys.path.insert(0, '$prefix/share/envdesign/python'); import envdesign_client; envdesign_client.parse_url('udpm://239.255.76.67:7667')"
cmake -S "$root/clients/cpp/example" -B "$prefix/example" -DCMAKE_PREFIX_PATH="$prefix" \
    -DCMAKE_BUILD_TYPE=Release >"$prefix/configure.log"
cmake --build "$prefix/example" >"$prefix/build.log"

ENVDESIGN_BIN=$prefix/bin bash "$root/deploy/cluster.sh" start --planners 1 --lcm-url "$url" \
    --dir "$prefix/cluster"
"$prefix/example/design_remote" "$root/examples/restaurant/c-two-tasks-t10.textproto" "$url" \
    >"$prefix/result.json"
grep -q '"status":"optimal"' "$prefix/result.json"
echo "OK: the installed client library and services designed $(grep -o '"design":\[[^]]*\]' "$prefix/result.json")"
