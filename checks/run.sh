#!/usr/bin/env bash
# The test command: set up (as experiments/setup.sh), then run every test except the `heavy` sweeps.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
bash "$root/experiments/setup.sh"
echo "==> running the tests"
ctest --test-dir "$root/build" --output-on-failure -j "$(nproc)" -LE heavy "$@"
