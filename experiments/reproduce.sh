#!/usr/bin/env bash
# The main job: set up, run the benchmarks, decide the proofs' sentences whose stored answers are missing or
# stale, decide every claim at full size, draw the figures, and write reports/claims.json and
# reports/REPORT.md. Outputs are replaced only when a step succeeds.
#   --reprove   re-decide every committed sentence first (QEPCAD B, Z3) and fail if any answer differs from
#               the committed one (reports/proofs/); without it only missing or stale answers are decided.
# Other arguments go to `affinterp claims` (e.g. --only ID, --seed N).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
reprove=0
args=()
for a in "$@"; do
  if [ "$a" = --reprove ]; then reprove=1; else args+=("$a"); fi
done
bash "$root/experiments/setup.sh"
cli="$root/build/bin/affinterp"

if ((reprove)); then
  echo "==> re-deciding every committed sentence (affinterp prove --all --check)"
  "$cli" prove --all --check
else
  echo "==> deciding the sentences whose stored answers are missing or stale (affinterp prove)"
  "$cli" prove
fi

bench_dir="$root/reports/bench"
mkdir -p "$bench_dir"
for bench in "$root"/build/bin/bench_*; do
  [ -x "$bench" ] || continue
  name=$(basename "$bench")
  echo "==> benchmark $name"
  "$bench" --benchmark_out="$bench_dir/.$name.json.tmp" --benchmark_out_format=json
  mv "$bench_dir/.$name.json.tmp" "$bench_dir/$name.json"
done

echo "==> deciding the claims (full size)"
"$cli" claims --size full --out "$root/reports" ${args[@]+"${args[@]}"}
echo "==> report: $root/reports/REPORT.md"
