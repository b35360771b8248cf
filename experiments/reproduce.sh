#!/usr/bin/env bash
# The main job: set up, run the benchmarks, decide every claim at full size, draw the figures, and write
# reports/claims.json and reports/REPORT.md. Outputs are replaced only when a step succeeds.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
bash "$root/experiments/setup.sh"

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
"$root/build/bin/affinterp" claims --size full --out "$root/reports" "$@"
echo "==> report: $root/reports/REPORT.md"
