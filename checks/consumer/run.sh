#!/usr/bin/env bash
# The affinterp package as an outside project sees it, from the build tree this test runs in, as it was
# configured and built (no rebuild): (a) installs it into a fresh prefix, checks that the installed
# libraries use no instruction beyond the x86-64 baseline (baseline_only.sh; with AFFINTERP_NATIVE the
# project's own copies are tuned to this CPU, the installed ones must not be), then builds and runs the
# outside project beside this script against the install; (b) builds and runs it against the build tree
# itself (its export()). With `headers` it instead compiles every installed header on its own against the install
# (the `headers` tier: every installed header, each parsing Eigen or Boost.Multiprecision anew, minutes of CPU
# that CI's 15 minutes cannot hold; the main job runs it).
# Usage: run.sh SOURCE_DIR BUILD_DIR WORK_DIR [headers]
set -euo pipefail
src=$1
build=$2
work=$3
mode=${4:-package}
rm -rf "$work"
mkdir -p "$work"
cmake --install "$build" --prefix "$work/prefix" >/dev/null
mapfile -t archives < <(find "$work/prefix" -name '*.a' | sort)
echo "installed: $(find "$work/prefix" -name '*.hpp' | wc -l) headers, ${#archives[@]} libraries"
bash "$src/checks/consumer/baseline_only.sh" "${archives[@]}"
# Where the package configuration lies under a prefix (the build tree is laid out as the install).
config=$(dirname "$(find "$work/prefix" -name affinterpConfig.cmake)")
config=${config#"$work/prefix/"}

# The build's compiler launcher (ccache) serves the outside project too.
launcher=$(sed -n 's/^CMAKE_CXX_COMPILER_LAUNCHER:[A-Z]*=//p' "$build/CMakeCache.txt")

# consume NAME PREFIX [CMAKE_OPTION...]: configures the outside project against the package under PREFIX
# (checked: that one and no other), builds it and runs it. Debug: this checks the package, not speed, and
# compiles fastest.
consume() {
  local name=$1 dir=$work/$1 prefix=$2
  shift 2
  cmake -S "$src/checks/consumer" -B "$dir" -G Ninja -DCMAKE_BUILD_TYPE=Debug -DCMAKE_PREFIX_PATH="$prefix" \
    -DCMAKE_CXX_COMPILER_LAUNCHER="$launcher" "$@" \
    >"$dir.configure.log" || { cat "$dir.configure.log"; exit 1; }
  local found
  found=$(sed -n 's/^affinterp_DIR:PATH=//p' "$dir/CMakeCache.txt")
  if [[ $found != "$prefix/$config" ]]; then
    echo "consumer: the $name build found affinterp in $found, not in $prefix/$config" >&2
    exit 1
  fi
  cmake --build "$dir"
  "$dir/consumer"
}
if [[ $mode == headers ]]; then
  consume installed "$work/prefix" -DCONSUMER_COMPILE_HEADERS=ON
else
  consume installed "$work/prefix" -DCONSUMER_COMPILE_HEADERS=OFF
  consume build-tree "$(realpath "$build")" -DCONSUMER_COMPILE_HEADERS=OFF
fi
