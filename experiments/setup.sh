#!/usr/bin/env bash
# Sets up affinterp on Debian: installs the Debian packages that are missing, then configures and builds
# in Release into build/. Idempotent: a second run installs nothing and rebuilds only what changed.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)

# libopenblas0-pthread: CHOLMOD's BLAS and LAPACK, through the libblas.so.3 / liblapack.so.3 alternatives
# (Debian's default is the reference BLAS, 2-3x slower in the supernodal factorisation at 1M triangles). The
# threaded build, as the engine factorises frames on several threads at once: Debian's serial OpenBLAS is
# not safe to call concurrently (it returned wrong factors, theory/global/sparse_factor.hpp).
packages=(
  cmake g++ make ninja-build pkg-config
  libeigen3-dev libsuitesparse-dev libopenblas0-pthread libboost-dev libboost-iostreams-dev libboost-filesystem-dev
  libgtest-dev googletest librapidcheck-dev libbenchmark-dev
  libgnuplot-iostream-dev gnuplot-nox fonts-dejavu-core
  libcairo2-dev libgif-dev chromium
  nlohmann-json3-dev libcli11-dev
  libcgal-dev libcgal-demo libxsimd-dev
  libginac-dev ginac-tools
  libflint-arb-dev
  qepcad z3 libz3-dev cvc5 libssl-dev
  clang libclang-rt-14-dev clang-format
  pybind11-dev python3-dev python3-numpy python3-pytest python3-matplotlib
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' || missing+=("$p")
done
if ((${#missing[@]})); then
  sudo=""
  [ "$(id -u)" -eq 0 ] || sudo=sudo
  echo "==> installing Debian packages: ${missing[*]}"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -q --no-install-recommends "${missing[@]}"
else
  echo "==> Debian packages: all present"
fi

echo "==> configuring (Release) in $root/build"
cmake -S "$root" -B "$root/build" -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
echo "==> building"
cmake --build "$root/build" -j "$(nproc)"
