#!/usr/bin/env bash
# Sets up affinterp on Debian: installs the Debian packages that are missing, then configures and builds
# in Release into build/. Idempotent: a second run installs nothing and rebuilds only what changed.
# The packages only the programs' runs need are installed while the build runs (apt's download and unpacking
# overlap the compiler); the script returns when both are done.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)

# What the configure step and the compiler need: tools, libraries and headers, gnuplot (looked up by CMake).
build_packages=(
  cmake g++ make ninja-build pkg-config
  libeigen3-dev libsuitesparse-dev libboost-dev libboost-iostreams-dev libboost-filesystem-dev
  libgtest-dev googletest librapidcheck-dev libbenchmark-dev
  libgnuplot-iostream-dev gnuplot-nox
  libcairo2-dev libgif-dev
  nlohmann-json3-dev libcli11-dev
  libcgal-dev libxsimd-dev
  libginac-dev
  libflint-arb-dev
  libssl-dev
  pybind11-dev python3-dev
)
# What only the tests and the main job run: the viewer test's browser, the deciders, GiNaC's shell, the
# libFuzzer target's compiler, CGAL's demo meshes, the Python module's test runner and array library, the
# figures' font, clang-format (the layout test), matplotlib (README's Python example), and Coq with Coquelicot
# and CSDP (psatz's certificates) for the lemmas' kernel-checked proofs (checks/proofs/coq_test.sh).
# libopenblas0-pthread: CHOLMOD's BLAS and LAPACK at run time, through the libblas.so.3 / liblapack.so.3
# alternatives (Debian's default is the reference BLAS, several times slower in the supernodal factorisation at
# 1M triangles). The threaded build, as the engine factorises frames on several threads at once: Debian's serial
# OpenBLAS is not safe to call concurrently: frames factorised in parallel got wrong factors.
run_packages=(
  libopenblas0-pthread chromium qepcad z3 cvc5 ginac-tools clang libclang-rt-14-dev clang-format libcgal-demo
  python3-numpy python3-pytest python3-matplotlib fonts-dejavu-core coq libcoq-coquelicot coinor-csdp libjs-three
)

missing() {
  for p in "$@"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' || echo "$p"
  done
}
sudo=""
[ "$(id -u)" -eq 0 ] || sudo=sudo
install() {
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -q --no-install-recommends "$@"
}
mapfile -t missing_build < <(missing "${build_packages[@]}")
mapfile -t missing_run < <(missing "${run_packages[@]}")
if ((${#missing_build[@]} + ${#missing_run[@]})); then
  $sudo apt-get update -qq
fi
if ((${#missing_build[@]})); then
  echo "==> installing Debian packages for the build: ${missing_build[*]}"
  install "${missing_build[@]}"
fi
run_install=""
run_log="$root/build-packages.log"
if ((${#missing_run[@]})); then
  echo "==> installing Debian packages for the runs, while building (log: $run_log): ${missing_run[*]}"
  install "${missing_run[@]}" > "$run_log" 2>&1 &
  run_install=$!
fi
((${#missing_build[@]} + ${#missing_run[@]})) || echo "==> Debian packages: all present"

echo "==> configuring (Release) in $root/build"
cmake -S "$root" -B "$root/build" -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
echo "==> building"
cmake --build "$root/build" -j "$(nproc)"

if [ -n "$run_install" ] && ! wait "$run_install"; then
  cat "$run_log" >&2
  echo "==> installing the Debian packages for the runs failed" >&2
  exit 1
fi
