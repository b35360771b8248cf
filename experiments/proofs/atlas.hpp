#pragma once
// The goodness atlas: for each homotopy and each notion of "good" (thesis Defs 2.2.1,
// 2.2.2), the parameters, their domain, and the exact region where the homotopy is good, as a condition in
// the `decide` grammar, proved equivalent to the definition (experiments/claims/atlas/).
//
//   linear   A = [[a, b], [c, d]], det A > 0                 A(t) = (1−t)I + tA
//   svd      A = R_α D R_β, D = diag(x, y), x, y > 0        A(t) = R_{tα}((1−t)I + tD)R_{tβ}; β in radians
//   polar    A = R S, S = [[x, h], [h, y]] ≻ 0               A(t) = R_{tθ}((1−t)I + tS)
//   exp-log  A = R S, S as polar                              A(t) = R_{tθ} S^t
// The rotations R_{tα}, R_{tθ} leave det and ‖·‖ alone (Lemma L5), so they are no parameters; R_{tβ} on the
// right does not leave the SVD norm alone (Lemma L9), and only β² enters.
#include "theory/logic/formula.hpp"

#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace affinterp::proofs {

enum class Homotopy { linear, svd, polar, exp_log };
enum class Notion { area, norm, volume, singular_values };  ///< volume, singular_values: 3D (atlas3.hpp)

std::string_view to_string(Homotopy h);  ///< "linear", "svd", "polar", "exp-log"
std::string_view to_string(Notion n);    ///< "area", "norm", "volume", "singular-values"

struct AtlasCell {
  Homotopy homotopy;
  Notion notion;
  std::vector<std::string> variables;               ///< the parameters, in the decide grammar
  std::map<std::string, logic::Polynomial> macros;  ///< tr and det of A, D or S
  logic::Formula domain;
  std::string domain_words;
  std::string condition;        ///< the exact region, in the decide grammar (proved: experiments/claims/atlas)
  std::string condition_words;  ///< the same, in words
  int dimension = 2;            ///< 2: the 2×2 atlas here; 3: the 3×3 atlas (atlas3.hpp)

  std::string id() const;  ///< "linear.area", "exp-log.norm"
  logic::Formula condition_formula() const;
};

const AtlasCell& atlas_cell(Homotopy h, Notion n);
const std::vector<AtlasCell>& atlas_cells();

/// Whether the homotopy is good at `p` by the suite's own exact decider (theory/local/goodness.hpp: linear and
/// polar area and norm, svd area; goodness3.hpp for the 3D cells, atlas3.hpp), or nullopt for the cells it has
/// none for (svd norm, exp-log in 2D) or, in 3D, where its certificates do not reach.
std::optional<bool> suite_says_good(const AtlasCell& cell, const logic::Point& p);

}  // namespace affinterp::proofs
