#!/usr/bin/env bash
# Installs the dependencies (if missing), configures and builds envdesign into build/.
# Safe to run again: it only rebuilds what changed.
set -euo pipefail
cd "$(dirname "$0")/.."
bash deploy/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j"$(nproc)"
