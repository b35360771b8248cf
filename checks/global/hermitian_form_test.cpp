// The complex form of the local errors (theory/global/hermitian_form.hpp, hermitian_local_error.hpp):
// each real 6×6 form of local_error.hpp commutes with rotating all three vertices by π/2, exactly (in
// rationals); and the complex forms the solver assembles are those real forms read as Hermitian blocks.
#include "theory/global/hermitian_form.hpp"
#include "theory/exact/rational.hpp"
#include "theory/global/hermitian_local_error.hpp"
#include "theory/global/local_error.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

namespace affinterp::global::hermitian_form_test {
namespace {

using exact::Rational;

/// A small rational in [−3, 3] with denominator up to 4.
Rational small_rational() { return Rational(*rc::gen::inRange(-12, 13)) / Rational(*rc::gen::inRange(1, 5)); }

template <int Rows, int Cols>
Eigen::Matrix<Rational, Rows, Cols> rational_matrix() {
  Eigen::Matrix<Rational, Rows, Cols> M;
  for (int r = 0; r < Rows; ++r)
    for (int c = 0; c < Cols; ++c) M(r, c) = small_rational();
  return M;
}

/// J ⊗ I₃ in vertex-interleaved coordinates: every vertex rotated by π/2.
Eigen::Matrix<Rational, 6, 6> quarter_turn_of_all_vertices() {
  Eigen::Matrix<Rational, 6, 6> R = Eigen::Matrix<Rational, 6, 6>::Zero();
  for (int k = 0; k < 3; ++k) R(2 * k, 2 * k + 1) = Rational(-1), R(2 * k + 1, 2 * k) = Rational(1);
  return R;
}

template <int Rows, int Cols>
Eigen::Matrix<double, Rows, Cols> to_double(const Eigen::Matrix<Rational, Rows, Cols>& M) {
  return M.unaryExpr([](const Rational& q) { return q.convert_to<double>(); });
}

RC_GTEST_PROP(HermitianForm, EveryLocalErrorCommutesWithAQuarterTurnExactly, ()) {
  Corners<Rational> p = rational_matrix<2, 3>();
  const Mat2<Rational> edges = p.rightCols<2>() - p.leftCols<2>().col(0).replicate<1, 2>();
  RC_PRE(edges.determinant() != 0);
  const Mat2<Rational> A = rational_matrix<2, 2>();
  RC_PRE(A.determinant() != 0);
  const auto D = linear_part_operator(p);
  const Rational w = Rational(*rc::gen::inRange(0, 5)) / Rational(4);
  const Eigen::Matrix<Rational, 6, 6> R = quarter_turn_of_all_vertices();
  for (const auto& H : {frobenius_quadratic(D, A).H, similarity_quadratic(D, A).H, blend_quadratic(D, A, w).H,
                        procrustes_quadratic(p, A).H}) {
    const Eigen::Matrix<Rational, 6, 6> HR = H.lazyProduct(R), RH = R.lazyProduct(H);
    for (int r = 0; r < 6; ++r)
      for (int c = 0; c < 6; ++c) RC_ASSERT(HR(r, c) == RH(r, c));
  }
}

RC_GTEST_PROP(HermitianForm, SolverFormsAreTheRealFormsAsHermitianBlocks, ()) {
  const Corners<double> p = to_double(rational_matrix<2, 3>());
  RC_PRE(std::abs((p.col(1) - p.col(0)).x() * (p.col(2) - p.col(0)).y() -
                  (p.col(1) - p.col(0)).y() * (p.col(2) - p.col(0)).x()) > 0.1);
  const Eigen::Matrix2d A = to_double(rational_matrix<2, 2>());
  RC_PRE(std::abs(A.determinant()) > 0.1);
  const auto D = linear_part_operator(p);
  const double w = *rc::gen::inRange(0, 5) / 4.0;
  const std::pair<Energy, TriangleQuadratic<double>> cases[] = {{Energy::F, frobenius_quadratic(D, A)},
                                                                {Energy::R, similarity_quadratic(D, A)},
                                                                {Energy::blend, blend_quadratic(D, A, w)},
                                                                {Energy::S, procrustes_quadratic(p, A)}};
  for (const auto& [energy, real] : cases) {
    const HermitianTriangleForm form = hermitian_local_error(energy, D, p, A, w);
    const double scale = 1 + real.H.cwiseAbs().maxCoeff();
    RC_ASSERT((form.H - hermitian_block(real.H)).cwiseAbs().maxCoeff() < 1e-12 * scale);
    const Eigen::Vector3cd u(std::complex<double>(real.g[0], real.g[1]), std::complex<double>(real.g[2], real.g[3]),
                             std::complex<double>(real.g[4], real.g[5]));
    RC_ASSERT((form.u - u).cwiseAbs().maxCoeff() < 1e-12 * (1 + real.g.cwiseAbs().maxCoeff()));
  }
}

TEST(HermitianForm, RealifiedIsTheBlockFormOfH) {
  Eigen::SparseMatrix<std::complex<double>> H(2, 2);
  H.insert(0, 0) = 2.0, H.insert(1, 0) = {3.0, 5.0}, H.insert(1, 1) = 7.0;
  const Eigen::MatrixXd G = Eigen::MatrixXd(realified(H));
  Eigen::MatrixXd expected(4, 4);
  expected << 2, 0, 0, 0,  //
      0, 2, 0, 0,          //
      3, -5, 7, 0,         //
      5, 3, 0, 7;
  EXPECT_EQ(G, expected);
}

}  // namespace
}  // namespace affinterp::global::hermitian_form_test
