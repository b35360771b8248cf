#pragma once
// The proof for all reals of an area theorem of thesis §2.2 (Thms 2.2.1, 2.2.2, 2.2.4): the printed condition
// and its correction, each as two sentences against Def 2.2.1 for det((1−t)I + tB), and the
// counterexample of the printed condition from the deciders' point, shrunk and re-verified by goodness.hpp.
#include "experiments/claims/local/local_proof.hpp"
#include "theory/exact/rational.hpp"
#include "theory/local/matrix2.hpp"

#include <functional>
#include <string>
#include <vector>

namespace affinterp::claims::local {

/// B of the blend as a function of the parameters, and whether a point lies in the domain, both exact.
struct AreaParameters {
  PolyMat2 B;                          ///< in the parameters' names
  std::vector<std::string> variables;  ///< the parameters
  Formula domain;
  std::string scope;  ///< the domain, in words
  std::function<affinterp::local::Mat2<exact::Rational>(const logic::Point&)> B_at;
  std::function<bool(const logic::Point&)> in_domain;
  std::string rotations;  ///< how the homotopy's rotations drop out of det A(t), or empty
};

/// The sentences: Lemma L2 (both forms) and L1, then "printed." and "corrected." pairs at levels E, D and L. Identity:
/// det((1−t)I + tB) = 1 + (tr B − 2)t + (1 − tr B + det B)t².
ProofPlan area_theorem_plan(const AreaParameters& p);

/// The verdict the proof reaches (confirmed, corrected or refuted from the printed and corrected pairs at level
/// E), or nullopt when a sentence was not decided by both deciders.
std::optional<Verdict> area_proof_verdict(const ProofRun& run);

/// The counterexample to the printed condition from "printed.cond-not-prop.E": shrunk while det A > 0, the
/// printed condition holds and goodness.hpp says not good for area; null when there is none.
nlohmann::json area_proof_counterexample(const ProofRun& run, const AreaParameters& p);

}  // namespace affinterp::claims::local
