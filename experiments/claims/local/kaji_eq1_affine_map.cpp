#include "experiments/claims/claim.hpp"
#include "experiments/claims/confirmed_by_proof.hpp"
#include "experiments/proofs/ginac_scalar.hpp"
#include "experiments/proofs/identity.hpp"
#include "experiments/proofs/step_nodes.hpp"
#include "experiments/support/random.hpp"
#include "theory/exact/rational.hpp"
#include "theory/local/local.hpp"

#include <stdexcept>

namespace affinterp::claims::local::kaji_eq1_affine_map {
namespace {

Outcome check(const ClaimContext& ctx);

const ClaimDeclaration claim{{
    .id = "kaji.eq1.affine-map",
    .chapter = Chapter::local,
    .where = "Kaji eq. (1)",
    .statement = "The product of the target-vertex matrix and the inverse source-vertex matrix sends each source "
                 "vertex to its target vertex and has bottom row (0, 0, 1).",
    .strength = Strength::sample,
    .check = check,
}};

// Reading: the printed form labels the first row (a_{1,1}, a_{2,1}, d_x), transposing the usual row-column
//   indices of a; notation only, recorded in the evidence.
// Method: random triangle pairs with small rational coordinates; Â = Q̂ P̂⁻¹ in exact rational arithmetic must
//   send each p_k to q_k and have last row (0, 0, 1). Collinear sources (no inverse) are skipped and counted.
//   Proof for every non-degenerate source (proof()): the same inverse3 and affine_map over coordinate symbols,
//   P̂⁻¹P̂ = I (so Â P̂ = Q̂ P̂⁻¹ P̂ = Q̂: Â p_k = q_k) and Â's last row (0, 0, 1): rational identities with
//   denominator det P̂, nonzero exactly when the source is not collinear.
// Sizes: quick 200 pairs; full 5000.

using exact::Rational;

/// P̂⁻¹P̂ = I and Â's last row (0, 0, 1), from theory/local's inverse3 and affine_map over symbols p_ik, q_ik; with
/// Â = Q̂ P̂⁻¹ (affine_map) the first gives Â P̂ = Q̂, i.e. Â p_k = q_k. (Â P̂ = Q̂ directly over all twelve symbols
/// exceeds the exact grid's size: q cancels only by associativity.)
Proof proof(const ClaimContext& ctx) {
  using X = GiNaC::ex;
  const affinterp::local::Triangle<X> p = proofs::symbolic_matrix<2, 3>("p"), q = proofs::symbolic_matrix<2, 3>("q");
  const affinterp::local::Mat3<X> P_hat = affinterp::local::homogeneous(p);
  const auto map = affinterp::local::affine_map(p, q);  // Kaji eq. (1) over symbols
  Eigen::Matrix<X, 1, 3> last_row;
  last_row << X(0), X(0), X(1);
  const std::vector<proofs::Identity> identities = {
      {"inverse", "P̂⁻¹ P̂ = I (inverse3 by the adjugate), so Â P̂ = Q̂ P̂⁻¹ P̂ = Q̂: Â p_k = q_k",
       proofs::product(proofs::to_ginac<3, 3>(affinterp::local::inverse3(P_hat)), proofs::to_ginac<3, 3>(P_hat)),
       proofs::to_ginac<3, 3>(affinterp::local::Mat3<X>::Identity())},
      {"last-row", "Â's last row is (0, 0, 1)", proofs::to_ginac<1, 3>(map.A_hat.row(2)), proofs::to_ginac(last_row)},
  };
  return proofs::identity_proof(
      "every pair of triangles p, q with p not collinear (det P̂ ≠ 0)",
      "rational identities in the vertex coordinates from theory/local's inverse3 and affine_map (eq. (1), Â = "
      "Q̂ P̂⁻¹, inverse by the adjugate); Â P̂ = Q̂ by associativity",
      proofs::prove_identities(identities, ctx.proof_files()));
}

Outcome check(const ClaimContext& ctx) {
  Rng rng(ctx.seed);
  const int samples = ctx.pick(200, 5000);
  std::uint64_t tried = 0, degenerate = 0, failures = 0;
  for (int i = 0; i < samples; ++i) {
    affinterp::local::Triangle<Rational> p, q;
    for (int k = 0; k < 6; ++k) {
      p(k % 2, k / 2) = Rational(rng.integer(-20, 20)) / rng.integer(1, 6);
      q(k % 2, k / 2) = Rational(rng.integer(-20, 20)) / rng.integer(1, 6);
    }
    try {
      const auto map = affinterp::local::affine_map(p, q);  // Kaji eq. (1): Â = Q̂ P̂⁻¹
      ++tried;
      bool ok = map.A_hat(2, 0) == 0 && map.A_hat(2, 1) == 0 && map.A_hat(2, 2) == 1;
      for (int k = 0; k < 3; ++k)
        ok = ok && affinterp::local::exactly_equal(
                       affinterp::local::Vec2<Rational>(map.A.lazyProduct(p.col(k)) + map.d), q.col(k));
      failures += !ok;
    } catch (const std::invalid_argument&) {
      ++degenerate;  // collinear source: eq. (1) has no inverse
    }
  }
  Outcome outcome;
  outcome.evidence.method = "exact rational evaluation of eq. (1) on random triangle pairs";
  outcome.evidence.sample_size = tried;
  outcome.evidence.seed = ctx.seed;
  outcome.evidence.details = {{"non_degenerate_pairs", tried},
                              {"collinear_sources_skipped", degenerate},
                              {"failures", failures},
                              {"coordinates", "p/q with |p| <= 20, 1 <= q <= 6"},
                              {"note",
                               "the printed form labels the first row (a_{1,1}, a_{2,1}, d_x): the indices of a are "
                               "transposed relative to the usual row-column convention (notation only)"}};
  outcome.verdict = failures == 0 && tried > 0 ? Verdict::confirmed : Verdict::refuted;
  outcome.summary =
      failures == 0 ? "on " + std::to_string(tried) +
                          " random rational triangle pairs, eq. (1) maps p_k to q_k exactly and has last row (0, 0, 1)"
                    : std::to_string(failures) + " triangle pairs where eq. (1) does not map the vertices";
  outcome.proof = proof(ctx);
  if (outcome.verdict == Verdict::confirmed)
    weigh_confirmation_against_proof(outcome, "every non-collinear source triangle and every target");
  return outcome;
}

}  // namespace
}  // namespace affinterp::claims::local::kaji_eq1_affine_map
