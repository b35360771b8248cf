#pragma once
// Families of 3×3 symmetric test matrices for the accuracy sweep and the benchmarks of thesis ch. 3.
// Every family is deterministic for a seed: the same (family, seed, count) gives the same draws on every
// platform (affinterp::Rng). The matrices built from them are exactly symmetric on every CPU; their last
// bits may differ between builds that vectorise or contract (FMA) differently.
#include "experiments/support/random.hpp"

#include <Eigen/Core>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace affinterp::sym3 {

using Mat3 = Eigen::Matrix3d;
using Vec3 = Eigen::Vector3d;

/// S = Mᵀ M with the entries of M uniform in [−1, 1]: the thesis's random distribution (§3.4).
std::vector<Mat3> thesis_distribution(std::uint64_t seed, std::size_t count);

/// A random rotation Q (det Q = +1), uniform on SO(3) (normalised Gaussian quaternion, Box–Muller).
Mat3 random_rotation(Rng& rng);

/// Q diag(lambda) Qᵀ: a symmetric matrix (exactly, on every CPU) with the prescribed spectrum in the
/// orthonormal basis Q.
Mat3 with_spectrum(const Vec3& lambda, const Mat3& Q);

/// How the spectra of one family are drawn.
struct Family {
  std::string name;         ///< e.g. "pair-gap-1e-06"
  std::string description;  ///< one line, for the report
  /// The gap between clustered eigenvalues (pairs and triples); empty for unclustered families.
  std::optional<double> gap;
  /// Whether every spectrum lies in [0, 3], the range of the thesis's accuracy statement (§3.4).
  bool in_thesis_range = false;
  /// Draws `count` matrices of the family.
  std::vector<Mat3> (*draw)(const Family&, std::uint64_t seed, std::size_t count);
  /// Entries and spectra across the whole double range: exp S may overflow (then the truth is "overflows")
  /// and only the certified references (theory/certified) hold there; the 100-digit Boost references of
  /// theory/sym3/reference.hpp lose moderate eigenvalues beside 10³⁰⁰ ones.
  bool whole_double_range = false;
};

/// The gaps of the cluster families: decades 1e−1 … 1e−16, points around the thesis's 10⁻⁶
/// equality threshold, and 0 (an exact repeat before rounding to the basis).
const std::vector<double>& cluster_gaps();

/// Every family: the thesis distribution, spectra spread over [0, 3], clustered pairs and triples at
/// every gap of cluster_gaps() (inside [0, 3]), wide spectra (ratio 10¹²), large |λ| (up to 700),
/// diagonal, nearly diagonal, multiples of the identity, zero, and last the two whole_double_range families:
/// "full-range" and "far-apart" (λmax − λmid > 709, λmax across exp's overflow).
const std::vector<Family>& families();

}  // namespace affinterp::sym3
