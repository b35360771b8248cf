#pragma once
// Exact rational versions of the global problem for the algebraic claims: small random meshes with
// rational vertices, the global quadratic form G, u assembled from the same templated local errors as the
// engine (theory/global/local_error.hpp), and exact rank and solve by Gaussian elimination.
#include "experiments/support/random.hpp"
#include "theory/exact/rational.hpp"
#include "theory/global/interpolation.hpp"
#include "theory/global/local_error.hpp"

#include <Eigen/Core>
#include <nlohmann/json.hpp>

#include <vector>

namespace affinterp::claims::global_exact {

using exact::Rational;
using MatQ = Eigen::Matrix<Rational, Eigen::Dynamic, Eigen::Dynamic>;
using VecQ = Eigen::Matrix<Rational, Eigen::Dynamic, 1>;
using Mat2Q = Eigen::Matrix<Rational, 2, 2>;

struct RationalMeshPair {
  Eigen::Matrix<Rational, 2, Eigen::Dynamic> P, Q;  ///< source and target vertices
  Eigen::Matrix3Xi triangles;
  Eigen::Index vertex_count() const { return P.cols(); }
  global::Corners<Rational> corners(const Eigen::Matrix<Rational, 2, Eigen::Dynamic>& V, Eigen::Index i) const;
  /// A_i: the linear part of eq. (1) from source to target triangle i.
  Mat2Q linear_part(Eigen::Index i) const;
  /// A_i of every triangle, in order.
  std::vector<Mat2Q> linear_parts() const;
  nlohmann::json to_json() const;
};

/// One triangle, the unit right triangle (0, 0), (1, 0), (0, 1), mapped onto `target` (one vertex per column):
/// the smallest counterexample of the global claims.
RationalMeshPair one_triangle(const Eigen::Matrix<Rational, 2, 3>& target);

/// A cols × rows strip of unit squares (two triangles each) jittered by multiples of 1/8, and a target
/// moved by a random rational linear map with entries in eighths plus jitter; no triangle degenerate or
/// flipped.
RationalMeshPair random_rational_pair(Rng& rng, int cols, int rows);

/// A random rational 2×2 matrix with entries k/den, |k| ≤ range; with det > 0 when `positive`.
Mat2Q random_matrix(Rng& rng, int range, int den, bool positive);

/// The local error of `energy` (w = E^F's share for the blend) of every triangle, with the triangle's
/// local map A_i(t) given, and of the reverse problem (target as reference, maps `reverse_A`) when not
/// empty, assembled into the 2n × 2n G and u of E = vᵀGv + vᵀu + c (no constraints).
struct ExactQuadratic {
  MatQ G;
  VecQ u;
};
ExactQuadratic assemble(const RationalMeshPair& mesh, global::Energy energy, const Rational& w,
                        const std::vector<Mat2Q>& A, const std::vector<Mat2Q>& reverse_A = {});

/// Entry-wise equality.
bool equal(const MatQ& a, const MatQ& b);
/// Rank by exact Gaussian elimination.
Eigen::Index rank(MatQ M);
/// The solution of M x = b for nonsingular M, by exact Gaussian elimination.
VecQ solve(MatQ M, VecQ b);

}  // namespace affinterp::claims::global_exact
