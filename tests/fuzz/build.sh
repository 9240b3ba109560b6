#!/usr/bin/env bash
# Builds every libFuzzer target (tests/fuzz/*_fuzz.cc) with clang, ASan and UBSan, in their
# own build directory (build-fuzz/ beside build/, or $ENVDESIGN_FUZZ_BUILD). Asserts stay on.
#   bash tests/fuzz/build.sh && bash tests/fuzz/run.sh 60
set -euo pipefail
cd "$(dirname "$0")/../.."
dir=${ENVDESIGN_FUZZ_BUILD:-build-fuzz}
flags="-fsanitize=address,undefined,fuzzer-no-link -fno-sanitize-recover=undefined"
flags+=" -fno-omit-frame-pointer"
command -v clang++ >/dev/null || { echo "fuzz: clang++ is needed (apt-get install clang)"; exit 1; }
cmake -S . -B "$dir" -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG="-g -O1" \
    -DCMAKE_C_FLAGS_DEBUG="-g -O1" -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ \
    -DCMAKE_C_FLAGS="$flags" -DCMAKE_CXX_FLAGS="$flags" -DENVDESIGN_FUZZ=ON >/dev/null
cmake --build "$dir" -j"${JOBS:-2}" --target fuzz_all
echo "fuzz targets in $dir/bin: $(cd "$dir/bin" && ls fuzz_* | tr '\n' ' ')"
