#!/usr/bin/env bash
# `affinterp pair` end to end on the hand-drawn outlines of checks/inputs/outlines (convex and strongly
# non-convex, equal counts and resampled): the meshes it writes are accepted by `affinterp interpolate`
# with no flipped triangle in any frame's source and target; malformed outlines get a one-line error,
# status 1, and leave OUT as it was. Also `affinterp --version`.
# Usage: pair_cli_test.sh path/to/affinterp SOURCE_DIR
set -u
affinterp=$1
outlines=$2/checks/inputs/outlines
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

"$affinterp" --version | grep -qE '^affinterp [0-9]+\.[0-9]+' || fail "--version"
"$affinterp" pair --help >/dev/null || fail "pair --help"

# pair SOURCE TARGET [options]: writes source.obj and target.obj that interpolate accepts as they are.
pair() {
  local out=$work/$1-$2
  shift 2
  "$affinterp" pair "$@" --out "$out" >"$work/report" 2>"$work/err" || { fail "pair $*: $(cat "$work/err")"; return; }
  grep -qE "triangles, 0 flipped; smallest angle [0-9.]+ deg \(source\), [0-9.]+ deg \(target\)" "$work/report" ||
    fail "pair $*: report $(cat "$work/report")"
  "$affinterp" interpolate --source "$out/source.obj" --target "$out/target.obj" --out "$out/run" --frames 3 \
    --no-figures 2>"$work/err" || fail "interpolate refused the pair $*: $(cat "$work/err")"
}
pair blob square "$outlines/blob.txt" "$outlines/rounded-square.txt"
pair c star "$outlines/letter-c.txt" "$outlines/star.txt"
pair comb c "$outlines/comb.txt" "$outlines/letter-c.txt" --resample 40

# SVG outlines: a polyline and a path.
cat >"$work/l.svg" <<'SVG'
<svg xmlns="http://www.w3.org/2000/svg"><polyline points="0,0 40,0 40,10 10,10 10,40 0,40 0,0"/></svg>
SVG
cat >"$work/t.svg" <<'SVG'
<svg xmlns="http://www.w3.org/2000/svg"><path d="M 0 0 h 50 v 10 h -20 l -5 30 l -5 0 L 20 10 H 0 Z"/></svg>
SVG
"$affinterp" pair "$work/l.svg" "$work/t.svg" --out "$work/svg" --resample 24 >/dev/null 2>"$work/err" ||
  fail "pair of SVG outlines: $(cat "$work/err")"

# Malformed outlines: one line, status 1, OUT untouched.
cp -r "$work/c-star" "$work/kept"
printf '0 0\n1 0\n0 1\n1 1\n' >"$work/bowtie.txt"
printf '0 0\n1 0\n1 1\n' >"$work/triangle.txt"
printf '0 0\n1 zero\n1 1\n' >"$work/garbage.txt"
for bad in bowtie triangle garbage; do
  "$affinterp" pair "$work/$bad.txt" "$outlines/blob.txt" --out "$work/c-star" >/dev/null 2>"$work/err"
  status=$?
  [ "$status" -eq 1 ] || fail "$bad: exit $status, expected 1"
  [ "$(wc -l <"$work/err")" -eq 1 ] || fail "$bad: error is not one line: $(cat "$work/err")"
done
grep -q "not a simple polygon" "$work/err" && fail "garbage read as a polygon"
diff -r "$work/kept" "$work/c-star" >/dev/null || fail "a failed pair changed OUT"

echo "$failures failed"
[ "$failures" -eq 0 ]
