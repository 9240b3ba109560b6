#!/usr/bin/env bash
# clients/python/install.sh [VENV]: installs the Python client (the modules, the LCM message
# types and the command envdesign-client) into a virtual environment, offline.
#
#   bash clients/python/install.sh
#   ~/.local/share/envdesign/venv/bin/envdesign-client SPEC --connect URL
#
# VENV defaults to ~/.local/share/envdesign/venv; it is created, or reused if it exists.
# Debian 12's own Python refuses `pip install` outside a venv (externally-managed-environment,
# PEP 668), and a Python without the wheel package cannot build one (invalid command
# 'bdist_wheel'). So this takes the first Python that has venv, setuptools and wheel
# (Debian's /usr/bin/python3 with python3-venv, python3-setuptools, python3-wheel:
# deploy/install-deps.sh), makes the venv with --system-site-packages so that pip builds
# with those packages, and installs without an index (--no-index): nothing is downloaded.
# lcm-gen (liblcm-bin) writes the message types during the build (setup.py).
set -euo pipefail

here=$(cd "$(dirname "$0")" && pwd)
venv=${1:-$HOME/.local/share/envdesign/venv}
needs="import venv, ensurepip, setuptools, wheel"

python=
for candidate in /usr/bin/python3 "$(command -v python3 || true)"; do
    if [ -x "$candidate" ] && "$candidate" -c "$needs" 2>/dev/null; then
        python=$candidate
        break
    fi
done
if [ -z "$python" ]; then
    echo "install.sh: no Python 3 with venv, setuptools and wheel; on Debian:" >&2
    echo "  sudo apt-get install python3-venv python3-setuptools python3-wheel liblcm-bin" >&2
    exit 1
fi
if ! command -v lcm-gen >/dev/null; then
    echo "install.sh: lcm-gen not found (it writes the message types); on Debian:" >&2
    echo "  sudo apt-get install liblcm-bin" >&2
    exit 1
fi

"$python" -m venv --system-site-packages "$venv"
# pip builds in the source folder (build/, *.egg-info, both ignored by git); quiet unless it
# fails, then all of it.
if ! log=$("$venv/bin/python" -m pip install --no-build-isolation --no-index --no-deps \
    --disable-pip-version-check --force-reinstall "$here" 2>&1); then
    echo "$log" >&2
    echo "install.sh: pip could not install $here into $venv" >&2
    exit 1
fi
echo "install.sh: envdesign-client installed in $venv (Python $("$venv/bin/python" -c \
    'import platform; print(platform.python_version())'))"
echo "  run: $venv/bin/envdesign-client SPEC --connect URL"
echo "  or:  $venv/bin/python -c 'import envdesign_client'"
