#!/usr/bin/env bash
# The test command (what CI runs): set up and build as experiments/setup.sh does, then run the `unit` tier, the
# `portable` tier and the installed package's consumer test (`install`). The two builds of the floating-point
# tests differ where a result could: `unit` is -march=native (on this project's machines AVX-512 with FMA
# contraction), `portable` the same tests compiled for the x86-64 baseline (no AVX, no FMA) and linked to the
# libraries the package installs (checks/CMakeLists.txt). A result that depends on the vector width or on
# contraction fails in one of the two. Both come out of the one build tree: the package's portable libraries
# are built anyway, so the second build costs only the tests' own compilation.
# The `proof` and `heavy` tiers are not run here (checks/README.md); the proofs' answers are read from
# reports/proofs/, which `affinterp prove` keeps.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
bash "$root/experiments/setup.sh"

echo "==> running the unit, portable and install tiers ($root/build)"
ctest --test-dir "$root/build" --output-on-failure -j "$(nproc)" -L "unit|portable|install" "$@"
