#!/usr/bin/env bash
# `affinterp interpolate` on 3D meshes and `affinterp blend` end to end, on small generated meshes
# (meshes3_files.py: a tetrahedral bar in MEDIT .mesh, a tube surface in OFF) and on `affinterp shapes`' 3D pose
# sets: frames written, the end frames equal to source and target, a blend at e_k equal to pose k, metrics.json per
# frame; each kind of bad input a one-line error, a non-zero exit and OUT as it was. On the cat poses of Sumner and
# Popovic 2004 (when present), cat-0 -> cat-4 with exp-log, 11 frames as frames.npy: the inverted triangles per
# frame are printed, not asserted (the 3D engine's own test, checks/global3/cat3_test.cpp, asserts its bound).
# Usage: interpolate3_cli_test.sh path/to/affinterp SOURCE_DIR
set -u
affinterp=$(realpath "$1")
make_mesh="python3 $2/checks/apps/meshes3_files.py"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
cd "$work" || exit 1

$make_mesh bar 0 bar.mesh && $make_mesh bar 1.5708 bar90.mesh && $make_mesh bar 3 bar170.mesh
$make_mesh tube 0 tube.off && $make_mesh tube 1 tube1.off
for option in degenerate nan fewer split; do
  $make_mesh bar 0.5 "bar-$option.mesh" "$option" && $make_mesh tube 0.5 "tube-$option.off" "$option"
done
$make_mesh bar 0.5 bar-inverted.mesh inverted

# max |a - b| over the vertices of two frame files (OBJ "v x y z" lines or MEDIT Vertices), in Python.
max_difference() {
  python3 - "$1" "$2" <<'PY'
import sys
def vertices(file):
    lines = open(file).read().split("\n")
    if file.endswith(".obj"):
        return [list(map(float, l.split()[1:4])) for l in lines if l.startswith("v ")]
    start = lines.index("Vertices") + 2
    return [list(map(float, l.split()[:3])) for l in lines[start:start + int(lines[start - 1])]]
a = vertices(sys.argv[1])
b = vertices(sys.argv[2]) if not sys.argv[2].endswith(".off") else [
    list(map(float, l.split())) for l in open(sys.argv[2]).read().split("\n")[2:2 + len(a)]]
print(max(abs(x - y) for p, q in zip(a, b) for x, y in zip(p, q)) if len(a) == len(b) else "inf")
PY
}
expect_equal() {  # FRAME MESH WHAT: the frame's vertices are the mesh's to 1e-9
  local d
  d=$(max_difference "$1" "$2")
  python3 -c "import sys; sys.exit(0 if float('$d') < 1e-9 else 1)" || fail "$3: differs from $2 by $d"
}
frame_count() { python3 -c "import json; print(len(json.load(open('$1/metrics.json'))['frames']))"; }

# interpolate: a tetrahedral bar turned by 90 degrees, a tube surface turned by one radian as frames.npy.
"$affinterp" interpolate --source bar.mesh --target bar90.mesh --out bar-run --frames 5 2>err || fail "bar: $(cat err)"
[ "$(frame_count bar-run)" = 5 ] && [ -f bar-run/frame_0004.mesh ] || fail "bar: 5 frames"
expect_equal bar-run/frame_0000.mesh bar.mesh "bar frame 0"
expect_equal bar-run/frame_0004.mesh bar90.mesh "bar frame 4"
"$affinterp" interpolate --source bar.mesh --target bar90.mesh --out bar-symmetric --frames 3 --symmetric --no-figures \
  2>err || fail "bar --symmetric: $(cat err)"
expect_equal bar-symmetric/frame_0000.mesh bar.mesh "bar --symmetric frame 0"
expect_equal bar-symmetric/frame_0002.mesh bar90.mesh "bar --symmetric frame 2"
# a vertex locus of large weight: vertex 0 follows the line through its points, (0,0,0) at t = 0.5
"$affinterp" interpolate --source bar.mesh --target bar90.mesh --out bar-locus --times 0.5 --no-figures \
  --locus "0@1e8:-1,-1,-1;1,1,1" --barycentre-locus "0,0,0;1,0,0" 2>err || fail "bar --locus: $(cat err)"
python3 - bar-locus/frame_0000.mesh <<'PY' || fail "bar --locus: vertex 0 not at (0, 0, 0) at t = 0.5"
import sys
lines = open(sys.argv[1]).read().split("\n")
first = lines[lines.index("Vertices") + 2].split()
assert max(abs(float(x)) for x in first[:3]) < 1e-6, first
PY
python3 -c "
import json; f = json.load(open('bar-run/metrics.json'))['frames'][2]
assert all(k in f for k in ('t', 'energy', 'measure_ratio', 'max_distortion', 'inverted_elements')), f" ||
  fail "bar: metrics.json entries"
if [ -f /usr/share/javascript/three/build/three.min.js ]; then  # libjs-three, which setup.sh installs
  grep -q "THREE.OrbitControls" bar-run/viewer.html || fail "bar: viewer.html with three.js inlined"
fi
"$affinterp" interpolate --source tube.off --target tube1.off --out tube-run --frames 3 --format npy --no-figures 2>err ||
  fail "tube: $(cat err)"
head -c 100 tube-run/frames.npy | grep -q "'shape': (3, 40, 3)" || fail "tube: frames.npy's shape"
python3 -c "import json; assert json.load(open('tube-run/metrics.json'))['target_folds'] == []" ||
  fail "tube: a turn folds no triangle within the surface"
# A target that folds triangles within the surface: a note, their indices and the inversions beside them counted.
$make_mesh tube 0.5 tube-folded.off folded
"$affinterp" interpolate --source tube.off --target tube-folded.off --out folded-run --frames 3 --no-figures 2>err ||
  fail "folded tube: $(cat err)"
grep -q "note: the target folds [1-9][0-9]* of 64 triangles" err || fail "folded tube: the note ($(cat err))"
python3 -c "
import json; d = json.load(open('folded-run/metrics.json'))
assert d['target_folds'] and all(0 <= f['inverted_near_folds'] <= f['inverted_elements'] for f in d['frames'])" ||
  fail "folded tube: metrics.json's target_folds and inverted_near_folds"
# The same pose in a blend: its folds against the first pose, per pose, and the inversions beside them.
"$affinterp" blend --poses tube.off tube1.off tube-folded.off --weights 0.2,0.3,0.5 --out folded-blend --no-figures \
  2>err || fail "folded blend: $(cat err)"
grep -q "note: tube-folded.off folds [1-9][0-9]* of 64 triangles" err || fail "folded blend: the note ($(cat err))"
python3 -c "
import json; d = json.load(open('folded-blend/metrics.json'))
assert d['pose_folds'][0] == [] and d['pose_folds'][1] == [] and d['pose_folds'][2]
assert all('inverted_near_folds' in f for f in d['frames'])" || fail "folded blend: metrics.json's pose_folds"
[ ! -e tube-run/viewer.html ] || fail "tube: a viewer despite --no-figures"

# Tetrahedra all negatively oriented are reversed for the engine (a note), the frames keep the file's corners.
$make_mesh bar 0 bar-reversed.mesh reversed && $make_mesh bar 1.5708 bar90-reversed.mesh reversed
"$affinterp" interpolate --source bar-reversed.mesh --target bar90-reversed.mesh --out reversed-run --frames 3 \
  --no-figures 2>err || fail "reversed: $(cat err)"
grep -q "all were reversed" err || fail "reversed: no note"
diff <(sed -n '/Tetrahedra/,$p' bar-reversed.mesh) <(sed -n '/Tetrahedra/,$p' reversed-run/frame_0002.mesh) >/dev/null ||
  fail "reversed: the frames' tetrahedra are not the file's"
expect_equal reversed-run/frame_0002.mesh bar90-reversed.mesh "reversed: last frame"

# The other surface formats, read by CGAL's polygon-soup reader (STL's repeated corners merged).
for format in ply stl obj; do
  $make_mesh tube 0 "tube.$format" && $make_mesh tube 1 "tube1.$format"
  "$affinterp" interpolate --source "tube.$format" --target "tube1.$format" --out "$format-run" --frames 3 \
    --no-figures 2>err || fail "$format: $(cat err)"
  if [ "$format" = stl ]; then  # merged corners come in the facets' order: the target as read is the reference
    "$affinterp" interpolate --source tube1.stl --target tube1.stl --out stl-target --frames 2 --no-figures 2>err
    expect_equal stl-run/frame_0002.obj stl-target/frame_0000.obj "stl: last frame"
  else
    expect_equal "$format-run/frame_0002.obj" tube1.off "$format: last frame"
  fi
done

# blend: weight vectors (e_2 gives pose 2), and keys at times.
"$affinterp" blend --poses bar.mesh bar90.mesh bar170.mesh --weights 0.2,0.5,0.3 --weights 0,0,1 --out blend-run \
  2>err || fail "blend: $(cat err)"
[ "$(frame_count blend-run)" = 2 ] || fail "blend: 2 frames"
expect_equal blend-run/frame_0001.mesh bar170.mesh "blend at e_2"
"$affinterp" blend --keys tube.off:0 tube1.off:0.5 tube.off:1 --times 0,0.25,0.5,1 --out keys-run 2>err ||
  fail "keys: $(cat err)"
[ "$(frame_count keys-run)" = 4 ] || fail "keys: 4 frames"
expect_equal keys-run/frame_0002.obj tube1.off "keys at t = 0.5"
"$affinterp" blend --help | grep -q -- "--allow-extrapolation" || fail "blend --help"

# shapes: every 3D pose set written, its first two poses interpolated (the ends are the poses), all of them blended.
for shape in $("$affinterp" shapes --list | grep -P '\t3D: ' | cut -f1); do
  "$affinterp" shapes "$shape" --out "shape-$shape" 2>err || { fail "shapes $shape: $(cat err)"; continue; }
  mapfile -t poses < <(ls "shape-$shape"/pose-*)
  ext=${poses[0]##*.}
  "$affinterp" interpolate --source "${poses[0]}" --target "${poses[1]}" --frames 3 --no-figures \
    --out "shape-$shape/run" 2>err || fail "interpolate $shape: $(cat err)"
  expect_equal "shape-$shape/run/frame_0002.$ext" "${poses[1]}" "$shape: last frame"
  if [ "${#poses[@]}" -gt 2 ]; then
    weights=$(python3 -c "print(','.join(['0'] * (${#poses[@]} - 1) + ['1']))")
    "$affinterp" blend --poses "${poses[@]}" --weights "$weights" --no-figures --out "shape-$shape/blend" 2>err ||
      fail "blend $shape: $(cat err)"
    expect_equal "shape-$shape/blend/frame_0000.$ext" "${poses[-1]}" "$shape: blend at the last pose"
  fi
done

# Bad input: one line on standard error, a non-zero exit, OUT untouched.
mkdir kept && echo earlier >kept/earlier.txt
refused() {  # WHAT ARGS...
  local what=$1
  shift
  if "$affinterp" "$@" --out kept 2>err; then fail "$what: accepted"; fi
  [ "$(wc -l <err)" = 1 ] && grep -q '^affinterp: ' err || fail "$what: not one line of affinterp's: $(cat err)"
  [ "$(ls -A kept)" = earlier.txt ] && [ "$(cat kept/earlier.txt)" = earlier ] || fail "$what: OUT changed"
}
refused "different connectivity" interpolate --source bar.mesh --target bar-fewer.mesh
refused "different surface" interpolate --source tube.off --target tube-fewer.off
refused "degenerate tetrahedron" interpolate --source bar-degenerate.mesh --target bar.mesh
refused "degenerate triangle" interpolate --source tube.off --target tube-degenerate.off
refused "inverted tetrahedra" interpolate --source bar.mesh --target bar-inverted.mesh
refused "NaN coordinate" interpolate --source bar.mesh --target bar-nan.mesh
refused "NaN on a surface" interpolate --source tube.off --target tube-nan.off
refused "disconnected" interpolate --source bar-split.mesh --target bar-split.mesh
refused "mixed triangles and tetrahedra" interpolate --source tube.off --target bar.mesh
refused "2D-only energy" interpolate --source bar.mesh --target bar90.mesh --energy R
refused "2D locus points in 3D" interpolate --source bar.mesh --target bar90.mesh --locus "0:1,2;3,4"
refused "locus vertex out of range" interpolate --source bar.mesh --target bar90.mesh --locus "999:0,0,0;1,1,1"
refused "2D-only edge direction" interpolate --source bar.mesh --target bar90.mesh --edge-direction 0:1
refused "pin out of range" interpolate --source bar.mesh --target bar90.mesh --pin 999
refused "negative refinement" interpolate --source bar.mesh --target bar90.mesh --arap-iterations -1
refused "refinement beyond its cap" blend --poses bar.mesh bar90.mesh --weights 0.5,0.5 --arap-iterations 1001
"$affinterp" shapes worm-curl --out plane 2>err || fail "shapes worm-curl: $(cat err)"
refused "3D-only refinement in 2D" interpolate --source plane/source.obj --target plane/target.obj --arap-iterations 2
refused "wrong weight count" blend --poses bar.mesh bar90.mesh bar170.mesh --weights 0.5,0.5
refused "off the simplex" blend --poses bar.mesh bar90.mesh bar170.mesh --weights 0.5,0.5,0 --weights -1,2,0
refused "not numbers" blend --poses bar.mesh bar90.mesh bar170.mesh --weights 0.5,x,0
refused "mixed poses" blend --poses bar.mesh bar90.mesh tube.off --weights 0.5,0.5,0
refused "keys not increasing" blend --keys bar.mesh:0 bar90.mesh:0.5 bar170.mesh:0.2
refused "time beyond the keys" blend --keys bar.mesh:0 bar90.mesh:0.5 bar170.mesh:1 --times 0,2
"$affinterp" blend --poses bar.mesh bar90.mesh --weights -0.5,1.5 --allow-extrapolation --out extrapolated 2>err ||
  fail "--allow-extrapolation: $(cat err)"

cat=/work/shared/data/meshes3d/cat
if [ -f "$cat/cat-0.off" ] && [ -f "$cat/cat-4.off" ]; then
  "$affinterp" interpolate --source "$cat/cat-0.off" --target "$cat/cat-4.off" --homotopy exp --frames 11 \
    --format npy --out cat-run 2>err || fail "cat: $(cat err)"
  python3 -c "
import json; m = json.load(open('cat-run/metrics.json'))
print('cat-0 -> cat-4, exp-log, inverted triangles per frame:', [f['inverted_elements'] for f in m['frames']])"
else
  echo "skipped the cat: $cat/cat-0.off, cat-4.off absent"
fi

[ "$failures" = 0 ] && echo "interpolate3_cli_test: all passed"
exit $((failures > 0))
