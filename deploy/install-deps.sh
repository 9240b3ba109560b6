#!/usr/bin/env bash
# Installs every Debian package envdesign needs to build, test and run.
# Idempotent and non-interactive: packages already present are skipped.
set -euo pipefail

PACKAGES=(
    build-essential cmake pkg-config
    libspdlog-dev libfmt-dev libcli11-dev nlohmann-json3-dev
    libprotobuf-dev protobuf-compiler
    libgtest-dev libgmock-dev
    liblcm-dev liblcm-bin liblcm-java libglib2.0-dev
    libssl-dev  # HMAC-SHA256 of bus messages (common/bus/auth.h)
    openjdk-17-jdk xvfb xauth libjchart2d-java iproute2
    cyclonedds-dev cyclonedds-tools libcycloneddsidl0
    coinor-libcbc-dev  # the witness search's hitting-set phase (integer programs)
    libsqlite3-dev libssl-dev  # the coordinator's durable evaluations (common/store)
    python3-setuptools python3-wheel python3-venv python3-pip  # pip install clients/python
    libsystemd-dev  # sd_notify: Type=notify units with a watchdog (common/service/systemd_notify.h)
    gnuplot-nox  # the interplay plot (tests/benchmarks/paper), the plots of envdesign report
    chromium  # tests/cli/report_test.py renders the report headless
    clang libclang-rt-14-dev  # tests/fuzz: libFuzzer, ASan and UBSan runtimes; the clang build
    libyaml-cpp-dev  # envdesign floor import reads Open-RMF building maps (common/floor)
)

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
