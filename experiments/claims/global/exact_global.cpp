#include "experiments/claims/global/exact_global.hpp"

#include "experiments/claims/values.hpp"
#include "experiments/inputs/shapes/grid.hpp"

#include <stdexcept>
#include <utility>

namespace affinterp::claims::global_exact {

global::Corners<Rational> RationalMeshPair::corners(const Eigen::Matrix<Rational, 2, Eigen::Dynamic>& V,
                                                    Eigen::Index i) const {
  global::Corners<Rational> c;
  for (int k = 0; k < 3; ++k) c.col(k) = V.col(triangles(k, i));
  return c;
}

Mat2Q RationalMeshPair::linear_part(Eigen::Index i) const { return global::linear_part(corners(P, i), corners(Q, i)); }

std::vector<Mat2Q> RationalMeshPair::linear_parts() const {
  std::vector<Mat2Q> A;
  for (Eigen::Index i = 0; i < triangles.cols(); ++i) A.push_back(linear_part(i));
  return A;
}

nlohmann::json RationalMeshPair::to_json() const {
  nlohmann::json triangle_list = nlohmann::json::array();
  for (Eigen::Index i = 0; i < triangles.cols(); ++i)
    triangle_list.push_back({triangles(0, i), triangles(1, i), triangles(2, i)});
  // Copy-initialised: Eigen's explicit one-argument constructor trips over cpp_rational's conversions.
  const Eigen::Matrix<Rational, Eigen::Dynamic, 2> source = P.transpose(), target = Q.transpose();
  return {{"P", exact_matrix(source)},
          {"Q", exact_matrix(target)},
          {"triangles", triangle_list},
          {"note", "P, Q: one vertex (x, y) per row; triangles: 0-based vertex indices, counter-clockwise"}};
}

RationalMeshPair one_triangle(const Eigen::Matrix<Rational, 2, 3>& target) {
  RationalMeshPair triangle;
  triangle.P.resize(2, 3);
  triangle.P << 0, 1, 0, 0, 0, 1;
  triangle.Q = target;
  triangle.triangles = Eigen::Matrix3Xi(3, 1);
  triangle.triangles << 0, 1, 2;
  return triangle;
}

Mat2Q random_matrix(Rng& rng, int range, int den, bool positive) {
  for (;;) {
    Mat2Q M;
    for (int k = 0; k < 4; ++k) M(k / 2, k % 2) = Rational(rng.integer(-range, range)) / den;
    if (positive ? M.determinant() > 0 : M.squaredNorm() > 0) return M;
  }
}

RationalMeshPair random_rational_pair(Rng& rng, int cols, int rows) {
  for (;;) {
    RationalMeshPair mesh;
    const Eigen::Index n = (cols + 1) * (rows + 1);
    mesh.P.resize(2, n), mesh.Q.resize(2, n);
    const Mat2Q L = random_matrix(rng, 16, 8, true);
    for (int j = 0; j <= rows; ++j)
      for (int i = 0; i <= cols; ++i) {
        const Eigen::Index k = j * (cols + 1) + i;
        mesh.P(0, k) = Rational(i) + Rational(rng.integer(-2, 2)) / 8;
        mesh.P(1, k) = Rational(j) + Rational(rng.integer(-2, 2)) / 8;
        mesh.Q.col(k) = L.lazyProduct(mesh.P.col(k));
        for (int r = 0; r < 2; ++r) mesh.Q(r, k) += Rational(rng.integer(-2, 2)) / 8;
      }
    mesh.triangles = shapes::grid_triangles(cols, rows);
    bool valid = true;
    for (Eigen::Index i = 0; i < mesh.triangles.cols() && valid; ++i) {
      const auto p = mesh.corners(mesh.P, i);
      const Mat2Q edges =
          (Mat2Q() << p(0, 1) - p(0, 0), p(0, 2) - p(0, 0), p(1, 1) - p(1, 0), p(1, 2) - p(1, 0)).finished();
      valid = edges.determinant() > 0 && mesh.linear_part(i).determinant() > 0;
    }
    if (valid) return mesh;
  }
}

ExactQuadratic assemble(const RationalMeshPair& mesh, global::Energy energy, const Rational& w,
                        const std::vector<Mat2Q>& A, const std::vector<Mat2Q>& reverse_A) {
  const Eigen::Index n = mesh.vertex_count();
  ExactQuadratic form{MatQ::Zero(2 * n, 2 * n), VecQ::Zero(2 * n)};
  auto add = [&](const global::Corners<Rational>& reference, const Mat2Q& Ai, Eigen::Index i) {
    const global::LinearPartOperator<Rational> D = global::linear_part_operator(reference);
    global::TriangleQuadratic<Rational> q;
    switch (energy) {
      case global::Energy::F:
        q = global::frobenius_quadratic(D, Ai);
        break;
      case global::Energy::R:
        q = global::similarity_quadratic(D, Ai);
        break;
      case global::Energy::blend:
        q = global::blend_quadratic(D, Ai, w);
        break;
      case global::Energy::S:
        q = global::procrustes_quadratic(reference, Ai);
        break;
    }
    for (int a = 0; a < 3; ++a)
      for (int r = 0; r < 2; ++r) {
        const Eigen::Index row = 2 * mesh.triangles(a, i) + r;
        form.u[row] += q.g[2 * a + r];
        for (int b = 0; b < 3; ++b)
          for (int s = 0; s < 2; ++s) form.G(row, 2 * mesh.triangles(b, i) + s) += q.H(2 * a + r, 2 * b + s);
      }
  };
  for (Eigen::Index i = 0; i < mesh.triangles.cols(); ++i) {
    add(mesh.corners(mesh.P, i), A[static_cast<std::size_t>(i)], i);
    if (!reverse_A.empty()) add(mesh.corners(mesh.Q, i), reverse_A[static_cast<std::size_t>(i)], i);
  }
  return form;
}

namespace {

/// Row echelon form in place; returns the pivot count. Applies the same row operations to `b` if given.
Eigen::Index eliminate(MatQ& M, VecQ* b) {
  Eigen::Index pivot_row = 0;
  for (Eigen::Index col = 0; col < M.cols() && pivot_row < M.rows(); ++col) {
    Eigen::Index pivot = pivot_row;
    while (pivot < M.rows() && M(pivot, col) == 0) ++pivot;
    if (pivot == M.rows()) continue;
    M.row(pivot).swap(M.row(pivot_row));
    if (b) std::swap((*b)[pivot], (*b)[pivot_row]);
    for (Eigen::Index r = 0; r < M.rows(); ++r) {
      if (r == pivot_row || M(r, col) == 0) continue;
      const Rational factor = M(r, col) / M(pivot_row, col);
      M.row(r) -= factor * M.row(pivot_row);
      if (b) (*b)[r] -= factor * (*b)[pivot_row];
    }
    ++pivot_row;
  }
  return pivot_row;
}

}  // namespace

bool equal(const MatQ& a, const MatQ& b) {
  if (a.rows() != b.rows() || a.cols() != b.cols()) return false;
  for (Eigen::Index i = 0; i < a.size(); ++i)
    if (a.data()[i] != b.data()[i]) return false;
  return true;
}

Eigen::Index rank(MatQ M) { return eliminate(M, nullptr); }

VecQ solve(MatQ M, VecQ b) {
  if (eliminate(M, &b) < M.rows()) throw std::domain_error("exact solve: singular matrix");
  VecQ x(M.rows());
  for (Eigen::Index r = 0; r < M.rows(); ++r) x[r] = b[r] / M(r, r);  // reduced: diagonal after full elimination
  return x;
}

}  // namespace affinterp::claims::global_exact
