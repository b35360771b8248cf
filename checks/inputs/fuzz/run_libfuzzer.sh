#!/usr/bin/env bash
# Builds the mesh reader's libFuzzer target with clang and fuzzes it for SECONDS (default 20) from the
# seed corpus. Exit 77 (CTest: skipped) when clang or libFuzzer is missing (Debian: clang
# libclang-rt-14-dev). Usage: run_libfuzzer.sh BUILD_DIR [SECONDS]
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
build=$1
seconds=${2:-20}
clangxx=$(command -v clang++ || command -v clang++-14 || true)
if [ -z "$clangxx" ]; then echo "skipped: clang++ not found"; exit 77; fi
probe=$(mktemp -d)
trap 'rm -rf "$probe"' EXIT
echo 'extern "C" int LLVMFuzzerTestOneInput(const unsigned char*, unsigned long) { return 0; }' > "$probe/p.cpp"
if ! "$clangxx" -fsanitize=fuzzer "$probe/p.cpp" -o "$probe/p" 2>/dev/null; then
  echo "skipped: libFuzzer not available to $clangxx (Debian: libclang-rt-14-dev)"; exit 77
fi
cmake -S "$here" -B "$build" -G Ninja -DCMAKE_CXX_COMPILER="$clangxx" -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
cmake --build "$build" >/dev/null
rm -rf "$build/corpus" && mkdir -p "$build/corpus" && cp "$here"/corpus/* "$build/corpus/"
# -seed fixes the mutation sequence; -timeout flags a hang (one input taking over 5 s); -rss_limit_mb a
# blow-up from a huge announced count.
"$build/mesh_reader_libfuzzer" -seed=2012 -max_total_time="$seconds" -timeout=5 -rss_limit_mb=1024 \
  -max_len=4096 -print_final_stats=1 "$build/corpus" 2>&1 | tail -12
