#!/usr/bin/env bash
# The main job: set up, build the benchmarks, check that every installed header compiles on its own and that
# the lemmas' Coq proofs pass Coq's kernel, decide the proofs' sentences whose stored answers are missing or
# stale, run the speed benchmarks, decide every claim at full size, draw the figures, and write
# reports/claims.json, reports/REPORT.md and reports/claims/. Outputs are replaced only when a step succeeds.
#   --scale     also run the engine's scale study: meshes up to 1M triangles (bench_scale), the CLI against the
#               engine at that size (bench_cli_scale), the 3D engine on 1.4M triangles (bench_3d_scale) and the
#               1M-triangle spiral with every energy through the CLI (ctest -L scale). Without it the report
#               shows the latest committed scale run, with its date and machine.
#   --reprove   re-decide every committed sentence first (QEPCAD B, Z3) and fail if any answer differs from
#               the committed one (reports/proofs/); without it only missing or stale answers are decided.
# Other arguments go to `affinterp claims` (e.g. --only ID, --seed N).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
reprove=0
scale=0
args=()
for a in "$@"; do
  case "$a" in
    --reprove) reprove=1 ;;
    --scale) scale=1 ;;
    -h | --help)
      sed -n '2,12p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'
      exit 0
      ;;
    *) args+=("$a") ;;
  esac
done
bash "$root/experiments/setup.sh"
cli="$root/build/bin/affinterp"
echo "==> building the benchmarks"
cmake --build "$root/build" --target benchmarks -j "$(nproc)"

# The one check too slow for CI's 15 minutes: every installed header compiled on its own (checks/README.md).
echo "==> compiling every installed header on its own (ctest -L headers)"
ctest --test-dir "$root/build" --output-on-failure -L headers
if ((scale)); then
  echo "==> the 1M-triangle spiral with every energy (ctest -L scale)"
  ctest --test-dir "$root/build" --output-on-failure -L scale
fi

echo "==> the lemmas' Coq proofs checked by Coq's kernel (ctest -R proofs.coq)"
ctest --test-dir "$root/build" --output-on-failure -R proofs.coq

if ((reprove)); then
  echo "==> re-deciding every committed sentence (affinterp prove --all --check)"
  "$cli" prove --all --check
else
  echo "==> deciding the sentences whose stored answers are missing or stale (affinterp prove)"
  "$cli" prove
fi

bench_dir="$root/reports/bench"
mkdir -p "$bench_dir"
# The speed programs run as whole processes in interleaved order (A B C A B C ...), AFFINTERP_BENCH_PROCESSES
# times each (one by default: each run joins the history, whose runs on one machine are pooled): slow phases of
# a shared machine then fall between processes, which the bootstrap intervals cover
# (experiments/bench/bootstrap.hpp), instead of tilting a verdict. Their processes are merged into one file each.
processes=${AFFINTERP_BENCH_PROCESSES:-1}
# bench_3d (the 3D engine's set-up, frames and blends; about half a minute) has no verdict of its own: the report's
# 3D section and thesis.app.speedup's second table read its file.
speed_programs=(bench_exp3 bench_app3 bench_interp bench_3d)
staging="$bench_dir/.processes"
rm -rf "$staging"
mkdir -p "$staging"
for k in $(seq 1 "$processes"); do
  for name in "${speed_programs[@]}"; do
    [ -x "$root/build/bin/$name" ] || continue
    echo "==> benchmark $name (process $k of $processes)"
    "$root/build/bin/$name" --benchmark_out="$staging/$name.$k.json" --benchmark_out_format=json
  done
done
for name in "${speed_programs[@]}"; do
  [ -x "$root/build/bin/$name" ] || continue
  mapfile -t outputs < <(ls "$staging/$name".*.json | sort -V)
  "$root/build/bin/affinterp" bench merge --out "$bench_dir/$name.json" "${outputs[@]}"
done
rm -rf "$staging"
# The other programs once each; the scale study's only with --scale.
other_programs=(bench_figures)
((scale)) && other_programs+=(bench_scale bench_cli_scale bench_3d_scale)
for name in "${other_programs[@]}"; do
  [ -x "$root/build/bin/$name" ] || continue
  echo "==> benchmark $name"
  "$root/build/bin/$name" --benchmark_out="$bench_dir/.$name.json.tmp" --benchmark_out_format=json
  mv "$bench_dir/.$name.json.tmp" "$bench_dir/$name.json"
done
# This run joins the history the speed verdicts are decided over (the entries of earlier runs are kept).
echo "==> recording the run in reports/bench/history"
"$root/build/bin/affinterp" bench record --bench-dir "$bench_dir" \
  --note "${AFFINTERP_BENCH_NOTE:-main job (experiments/reproduce.sh): $processes interleaved processes per speed program}"

# Not a timing: the 3D engine's frames against baselines (inverted elements, distortion) on the pose pairs here.
echo "==> the 3D frames against baselines (quality_3d)"
"$root/build/bin/quality_3d" --out "$bench_dir/quality_3d.json"

echo "==> deciding the claims (full size)"
"$cli" claims --size full --out "$root/reports" ${args[@]+"${args[@]}"}
echo "==> report: $root/reports/REPORT.md"
