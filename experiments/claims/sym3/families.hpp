#pragma once
// Families of S ∈ Sym(3) on which the chapter-3 algorithms are tested and swept: the thesis's own
// (S = MᵀM, §3.4) and the hard cases for eigenvalue-based formulas (clusters, exact repeats, wide and
// large spectra, (nearly) diagonal, zero).
#include "experiments/common/random.hpp"
#include "theory/sym3/algorithms.hpp"

#include <span>
#include <string_view>

namespace affinterp::sym3 {

struct Family {
  std::string_view name;
  std::string_view description;
  Mat3 (*draw)(Rng& rng);
};

/// "thesis", "spread-0-3", "clustered", "repeated", "wide", "large", "near-diagonal", "zero".
std::span<const Family> families();
const Family* find_family(std::string_view name);

/// A uniformly distributed rotation (normalised quaternion with uniform direction).
Mat3 random_rotation(Rng& rng);
/// Q diag(lambda) Qᵀ with a random rotation Q, symmetrised.
Mat3 with_eigenvalues(Rng& rng, const Vec3& lambda);

}  // namespace affinterp::sym3
