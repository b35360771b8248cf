// The Python module `affinterp` (pybind11): the suite's algorithms with NumPy arrays in and out.
#include "experiments/python/bindings.hpp"

#include <pybind11/pybind11.h>

PYBIND11_MODULE(affinterp, m) {
  m.doc() = R"(affinterp: rigid 2D shape interpolation with affine maps (Kaji et al., SCA 2012; Matsushita,
thesis 2015).

  Interpolation(V0, V1, F, ...)   global interpolation (Kaji §4): .vertices_at(t), .frames(times), .energy_at(t);
                                  (n, 3) vertices with triangles or tetrahedra: the 3D engine
  Blend(poses, F, ...)            N-way blend of 3D poses: .vertices_at(w), w of shape (K,) or (frames, K)
  homotopy_at(A, t, homotopy)     the local homotopies A(t) of one A in GL+(2) (Kaji §3)
  good_for_area(B), good_for_norm(B)   thesis Defs 2.2.1 and 2.2.2, decided exactly
  exp3(S), eig3(S)                3x3 symmetric exponential and eigenvalues (thesis ch. 3)
  decide(condition, homotopy, notion)  QEPCAD B and Z3 on a goodness condition, as `affinterp decide`
  pair(source, target)            compatible triangulations of two simple polygons (`affinterp pair`)
  read_mesh(path)                 (V, F) of a mesh file, as `affinterp interpolate` reads it
Bad input raises ValueError with a one-line message.)";
  m.attr("__version__") = AFFINTERP_VERSION;
  affinterp::python::bind_interpolation(m);
  affinterp::python::bind_local(m);
  affinterp::python::bind_sym3(m);
  affinterp::python::bind_decide(m);
  affinterp::python::bind_pair(m);
  affinterp::python::bind_mesh(m);
  affinterp::python::bind_blend(m);
  affinterp::python::bind_keyframes(m);
}
