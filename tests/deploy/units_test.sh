#!/usr/bin/env bash
# The shipped systemd units bound the memory of every service (issue 10): each has
# MemoryMax= in [Service].
set -euo pipefail
dir="$(dirname "$0")/../../deploy/systemd"
status=0
for unit in "$dir"/*.service; do
    if ! awk '/^\[/{section=$0} section=="[Service]" && /^MemoryMax=[0-9]+[KMGT]?$/{found=1}
              END{exit !found}' "$unit"; then
        echo "FAIL: $(basename "$unit") sets no MemoryMax= in [Service]"
        status=1
    fi
done
exit $status
