#pragma once
// The 3×3 symmetric matrix exponential and eigenvalue algorithms of the thesis, chapter 3, their peers
// from Eigen, and ours ("affinterp"), behind one catalogue so that tests, benchmarks, sweeps and the
// CLI can run every algorithm by name.
#include <Eigen/Core>

#include <span>
#include <string_view>

namespace affinterp::sym3 {

using Mat3 = Eigen::Matrix3d;
using Vec3 = Eigen::Vector3d;

/// An eigenvalue algorithm for S ∈ Sym(3); eigenvalues are returned in ascending order.
struct EigAlgorithm {
  std::string_view name;
  Vec3 (*eigenvalues)(const Mat3&);
};

/// A matrix exponential algorithm for S ∈ Sym(3).
struct ExpAlgorithm {
  std::string_view name;
  Mat3 (*exp)(const Mat3&);
};

/// "eigen-qr", "eigen-direct", "viete" (thesis §3.2 as printed), "viete-clamped", "affinterp".
std::span<const EigAlgorithm> eig_algorithms();
/// "eigen-qr-diag", "eigen-direct-diag" (thesis §3.1.1 with each Eigen solver), "eigen-pade",
/// "thesis-sd-printed", "thesis-sd-corrected" (§3.1.2), "thesis-improved-sd" (§3.2 + §3.1.2),
/// "affinterp".
std::span<const ExpAlgorithm> exp_algorithms();

/// The algorithm of that name, or nullptr.
const EigAlgorithm* find_eig(std::string_view name);
const ExpAlgorithm* find_exp(std::string_view name);

/// Ours, batched over arrays (SIMD): out[i] = exp(in[i]). Throws std::invalid_argument when in and
/// out differ in size.
void exp_batched(std::span<const Mat3> in, std::span<Mat3> out);

}  // namespace affinterp::sym3
