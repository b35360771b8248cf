#!/usr/bin/env bash
# The engine's scale case through the CLI: `affinterp shapes strip-spiral --quads 2000x250` (1,000,000 triangles,
# a strip 18.8 × 2 rolled 1.5 turns) interpolates with every energy, `affinterp interpolate`'s other options
# left at their defaults: exit 0, frames.npy of shape (2, 502251, 2) and its full size, and in metrics.json a
# finite E_t for each frame. Tier `heavy` (seconds per energy on 2 cores, up to 2 GB;
# under a minute in all).
# Usage: spiral_cli_heavy_test.sh path/to/affinterp
set -u
affinterp=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

"$affinterp" shapes strip-spiral --quads 2000x250 --out "$work/spiral" >/dev/null || {
  echo "FAIL: shapes strip-spiral --quads 2000x250"
  exit 1
}
vertices=$((2001 * 251))
for energy in F R S blend; do
  out=$work/run-$energy
  started=$SECONDS
  if ! "$affinterp" interpolate --source "$work/spiral/source.obj" --target "$work/spiral/target.obj" --out "$out" \
    --energy "$energy" --frames 2 --format npy --no-figures --metrics energy >/dev/null 2>"$work/err"; then
    fail "E^$energy refused the spiral: $(cat "$work/err")"
    continue
  fi
  npy=$out/frames.npy
  header=$(head -c 128 "$npy" | tr -d '\0')
  [[ $header == *"'shape': (2, $vertices, 2)"* ]] || fail "E^$energy: frames.npy header $header"
  header_bytes=$((10 + $(od -An -tu2 -j8 -N2 "$npy" | tr -d ' ')))  # magic, version, HEADER_LEN (npy 1.0)
  [[ $(stat -c %s "$npy") -eq $((header_bytes + 2 * vertices * 2 * 8)) ]] || fail "E^$energy: frames.npy size"
  # a frame's E_t is a number; one that is not finite is written as null
  energies=$(grep -cE '"energy": *-?[0-9]' "$out/metrics.json")
  [[ $energies -eq 2 ]] || fail "E^$energy: $energies finite energies in metrics.json, 2 frames"
  echo "E^$energy: 2 frames of the 1M-triangle spiral in $((SECONDS - started)) s"
done
exit $((failures > 0))
