#!/usr/bin/env bash
# deploy/build.sh [TARGET...]: installs the Debian packages it needs (if missing), configures
# and builds envdesign into build/ (binaries in build/bin/). Safe to run again: it only
# rebuilds what changed.
#
#   bash deploy/build.sh              everything: every binary, the tests, the benchmarks
#   bash deploy/build.sh envdesign    only these targets (here the CLI), with only the
#                                     packages a build needs (deploy/install-deps.sh --build)
#
# ccache, when installed, caches compiles across build folders and clean builds (CMakeLists.txt).
set -euo pipefail
cd "$(dirname "$0")/.."
if [ $# -gt 0 ]; then
    bash deploy/install-deps.sh --build
else
    bash deploy/install-deps.sh
fi
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j"$(nproc)" ${1:+--target "$@"}
