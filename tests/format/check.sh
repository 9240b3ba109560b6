#!/usr/bin/env bash
# The tree as .clang-format writes it (issue 23): lists every tracked C++ file that
# clang-format would change and fails if there is one. Run by .ci/run before the build.
#   bash tests/format/check.sh         (fix: clang-format -i FILE...)
set -euo pipefail
cd "$(dirname "$0")/../.."
command -v clang-format >/dev/null || { echo "format: clang-format is needed (apt-get install clang-format)"; exit 1; }
changed=$(git ls-files '*.h' '*.cc' | xargs clang-format --dry-run 2>&1 |
    sed -n 's/^\([^:]*\):[0-9]*:[0-9]*: warning: code should be clang-formatted.*/\1/p' | sort -u)
if [ -n "$changed" ]; then
    echo "format: clang-format would change these files (clang-format -i them):"
    echo "$changed" | sed 's/^/  /'
    exit 1
fi
echo "format: $(git ls-files '*.h' '*.cc' | wc -l) files as .clang-format writes them"
