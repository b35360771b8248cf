#!/usr/bin/env bash
# Builds affinterp::theory alone, as the architecture promises (no test, app or plotting dependency looked
# up), installs it into a fresh prefix, then builds and runs the outside project beside this script
# against that install. Usage: run.sh SOURCE_DIR WORK_DIR
set -euo pipefail
src=$1
work=$2
rm -rf "$work"
mkdir -p "$work"
# Debug: this checks configuration, installation and headers, not speed, and Debug compiles fastest.
cmake -S "$src" -B "$work/build" -G Ninja -DCMAKE_BUILD_TYPE=Debug -DAFFINTERP_NATIVE=OFF \
  -DAFFINTERP_BUILD_TESTS=OFF -DAFFINTERP_BUILD_APPS=OFF \
  -DCMAKE_DISABLE_FIND_PACKAGE_GTest=ON -DCMAKE_DISABLE_FIND_PACKAGE_rapidcheck=ON \
  -DCMAKE_DISABLE_FIND_PACKAGE_benchmark=ON -DCMAKE_DISABLE_FIND_PACKAGE_CLI11=ON \
  -DCMAKE_DISABLE_FIND_PACKAGE_nlohmann_json=ON -DCMAKE_INSTALL_PREFIX="$work/prefix" --no-warn-unused-cli >/dev/null
cmake --build "$work/build"
cmake --install "$work/build" >/dev/null
echo "installed: $(find "$work/prefix" -name '*.hpp' | wc -l) headers, $(find "$work/prefix" -name '*.a' | wc -l) libraries"
cmake -S "$src/checks/consumer" -B "$work/consumer" -G Ninja -DCMAKE_BUILD_TYPE=Debug \
  -DCMAKE_PREFIX_PATH="$work/prefix"
cmake --build "$work/consumer"
"$work/consumer/consumer"
