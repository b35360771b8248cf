#!/usr/bin/env bash
# The test command: set up (as experiments/setup.sh), run every test except the `heavy` sweeps, then build
# and test a second configuration whose floating-point code differs from the first: the portable
# x86-64-v3 (AVX2 + FMA, contraction on) when this CPU runs it, else generic x86-64 without contraction.
# A test that depends on the vector width or on FMA contraction fails in one of the two.
# AFFINTERP_SECOND_CONFIG=0 skips the second configuration (e.g. while iterating on one test).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
bash "$root/experiments/setup.sh"
echo "==> running the tests ($root/build: -march=native)"
ctest --test-dir "$root/build" --output-on-failure -j "$(nproc)" -LE heavy "$@"

[ "${AFFINTERP_SECOND_CONFIG:-1}" = 0 ] && exit 0
if /lib64/ld-linux-x86-64.so.2 --help 2>/dev/null | grep -q 'x86-64-v3 (supported'; then
  flags="-march=x86-64-v3 -ffp-contract=fast"
else
  flags="-march=x86-64 -ffp-contract=off"
fi
second="$root/build-portable"
echo "==> second configuration in $second: $flags"
cmake -S "$root" -B "$second" -G Ninja -DCMAKE_BUILD_TYPE=Release -DAFFINTERP_NATIVE=OFF \
  -DCMAKE_CXX_FLAGS="$flags" >/dev/null
cmake --build "$second" -j "$(nproc)"
echo "==> running the tests ($second: $flags)"
ctest --test-dir "$second" --output-on-failure -j "$(nproc)" -LE "heavy|install" "$@"
