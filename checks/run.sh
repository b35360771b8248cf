#!/usr/bin/env bash
# The test command (what CI runs): set up and build as experiments/setup.sh does, run the `unit` tier and the
# installed package's consumer test, and build and test a second configuration whose floating-point code differs
# from the first: the portable x86-64-v3 (AVX2 + FMA, contraction on) when this CPU runs it, else generic
# x86-64 without contraction. A result that depends on the vector width or on FMA contraction fails in one of
# the two. The second configuration builds only what its floating point changes: the library and its tests
# (AFFINTERP_BUILD_APPS=OFF; not the CLI, report generator, viewer and benchmarks again, nor the exact GiNaC
# component affinterp::origin and the tests of the exact rationals and formulas), and it builds while the first
# configuration's tests run.
# The `proof` and `heavy` tiers are not run here (checks/README.md); the proofs' answers are read from
# reports/proofs/, which `affinterp prove` keeps.
# AFFINTERP_SECOND_CONFIG=0 skips the second configuration (e.g. while iterating on one test).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
bash "$root/experiments/setup.sh"

second_pid=""
if [ "${AFFINTERP_SECOND_CONFIG:-1}" != 0 ]; then
  if /lib64/ld-linux-x86-64.so.2 --help 2>/dev/null | grep -q 'x86-64-v3 (supported'; then
    flags="-march=x86-64-v3 -ffp-contract=fast"
  else
    flags="-march=x86-64 -ffp-contract=off"
  fi
  second="$root/build-portable"
  echo "==> second configuration in $second: $flags, the library and its tests (building in the background)"
  (cmake -S "$root" -B "$second" -G Ninja -DCMAKE_BUILD_TYPE=Release -DAFFINTERP_NATIVE=OFF -DAFFINTERP_BUILD_APPS=OFF \
     -DAFFINTERP_EXACT_TESTS=OFF -DCMAKE_DISABLE_FIND_PACKAGE_PkgConfig=ON -DCMAKE_CXX_FLAGS="$flags" &&
   cmake --build "$second" -j "$(nproc)") > "$root/build-portable.log" 2>&1 &
  second_pid=$!
fi

echo "==> running the unit tier and the install test ($root/build: -march=native)"
status=0
ctest --test-dir "$root/build" --output-on-failure -j "$(nproc)" -L "unit|install" "$@" || status=$?

if [ -n "$second_pid" ]; then
  if ! wait "$second_pid"; then
    cat "$root/build-portable.log"
    echo "==> the second configuration failed to build" >&2
    exit 1
  fi
  echo "==> running the unit tier ($second: $flags)"
  ctest --test-dir "$second" --output-on-failure -j "$(nproc)" -L unit "$@" || status=$?
fi
exit "$status"
