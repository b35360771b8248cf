#include "theory/origin/affine_frames.hpp"

namespace affinterp::origin {

GiNaC::matrix affine_map(const GiNaC::matrix& corners, const GiNaC::matrix& images) {
  GiNaC::matrix P(2, 2), Q(2, 2), p_a(2, 1), q_a(2, 1);
  for (unsigned r = 0; r < 2; ++r) {
    p_a(r, 0) = corners(r, 0);
    q_a(r, 0) = images(r, 0);
    for (unsigned c = 0; c < 2; ++c) {
      P(r, c) = corners(r, c + 1) - corners(r, 0);
      Q(r, c) = images(r, c + 1) - images(r, 0);
    }
  }
  const GiNaC::matrix L = Q.mul(P.inverse());
  return affine_matrix(L, q_a.sub(L.mul(p_a)));
}

GiNaC::matrix translate_origin(const GiNaC::matrix& A, const GiNaC::matrix& o) {
  const GiNaC::matrix I{{1, 0}, {0, 1}};
  const GiNaC::matrix shift = affine_matrix(I, o), unshift = affine_matrix(I, o.mul_scalar(-1));
  GiNaC::matrix result = shift.mul(A).mul(unshift);
  for (unsigned r = 0; r < 3; ++r)
    for (unsigned c = 0; c < 3; ++c) result(r, c) = result(r, c).expand();
  return result;
}

GiNaC::matrix linear_part(const GiNaC::matrix& A) { return GiNaC::matrix{{A(0, 0), A(0, 1)}, {A(1, 0), A(1, 1)}}; }

GiNaC::matrix translation(const GiNaC::matrix& A) { return GiNaC::matrix{{A(0, 2)}, {A(1, 2)}}; }

GiNaC::matrix affine_matrix(const GiNaC::matrix& L, const GiNaC::matrix& t) {
  return GiNaC::matrix{{L(0, 0), L(0, 1), t(0, 0)}, {L(1, 0), L(1, 1), t(1, 0)}, {0, 0, 1}};
}

bool is_zero_matrix(const GiNaC::matrix& M) {
  for (unsigned r = 0; r < M.rows(); ++r)
    for (unsigned c = 0; c < M.cols(); ++c)
      if (!M(r, c).normal().is_zero()) return false;
  return true;
}

}  // namespace affinterp::origin
