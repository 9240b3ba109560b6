#!/usr/bin/env bash
# deploy/install-deps.sh [--build]: installs the Debian packages envdesign needs.
#   (no flag)  everything to build, test and run: the tests' tools too (Java for lcm-spy,
#              Chromium, clang for the fuzz build, gnuplot, Python's venv)
#   --build    only what configuring and building needs (deploy/build.sh TARGET...): the
#              README's first command does not wait for a JDK and a browser
# Idempotent and non-interactive: packages already present are skipped.
set -euo pipefail

BUILD_PACKAGES=(
    build-essential cmake pkg-config
    ccache  # compiles cached across clean builds and build folders (CMakeLists.txt)
    libspdlog-dev libfmt-dev libcli11-dev nlohmann-json3-dev
    libprotobuf-dev protobuf-compiler
    libgtest-dev libgmock-dev  # configured with the project (tests/), small
    liblcm-dev liblcm-bin libglib2.0-dev
    libssl-dev  # HMAC-SHA256 of bus messages (common/bus/auth.h), SHA-256 of stored records
    cyclonedds-dev cyclonedds-tools libcycloneddsidl0
    coinor-libcbc-dev  # the witness search's hitting-set phase (integer programs)
    libsqlite3-dev  # the coordinator's durable evaluations (common/store)
    libsystemd-dev  # sd_notify: Type=notify units with a watchdog (common/service/systemd_notify.h)
    libyaml-cpp-dev  # envdesign floor import reads Open-RMF building maps (common/floor)
    libgoogle-perftools-dev  # tcmalloc for the design CLI (CMakeLists.txt)
)
TEST_PACKAGES=(
    liblcm-java openjdk-17-jdk xvfb xauth libjchart2d-java iproute2  # lcm-spy on our types
    python3-setuptools python3-wheel python3-venv python3-pip  # pip install clients/python
    gnuplot-nox  # the interplay plot (tests/benchmarks/paper), the plots of envdesign report
    chromium  # tests/cli/report_test.py renders the report headless
    clang libclang-rt-14-dev  # tests/fuzz: libFuzzer, ASan and UBSan runtimes; the clang build
    clang-format  # CI fails on a file .clang-format would change (tests/format/check.sh)
)

PACKAGES=("${BUILD_PACKAGES[@]}")
case "${1:-}" in
    --build) ;;
    "") PACKAGES+=("${TEST_PACKAGES[@]}") ;;
    *) echo "usage: install-deps.sh [--build]" >&2; exit 2 ;;
esac

missing=()
for pkg in "${PACKAGES[@]}"; do
    dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null | grep -q "install ok installed" || missing+=("$pkg")
done

if [ ${#missing[@]} -eq 0 ]; then
    echo "install-deps: all ${#PACKAGES[@]} packages already installed"
    exit 0
fi

SUDO=""
[ "$(id -u)" -ne 0 ] && SUDO="sudo"
echo "install-deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
