#include "experiments/claims/claim.hpp"
#include "experiments/claims/global/exact_global.hpp"
#include "experiments/claims/global/symbolic_er.hpp"
#include "experiments/claims/values.hpp"
#include "experiments/proofs/ginac_polynomial.hpp"
#include "experiments/proofs/identity.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

namespace affinterp::claims::kaji_er_positive_definite {
namespace {

Outcome check(const ClaimContext& ctx);

const ClaimDeclaration claim{{
    .id = "kaji.er.positive-definite",
    .chapter = Chapter::global,
    .where = "Kaji §4, Appendix",
    .statement = "E^R is a positive definite quadratic form in the entries of B.",
    .strength = Strength::exact_counterexample,
    .check = check,
}};

// Reading: "positive definite in the entries of B" for fixed A.
// Method: E^R(A, ·) is the quadratic form Q = I − (a aᵀ + j jᵀ)/‖A‖² on vec B (a = vec A, j = vec JA); its rank
//   and Q² = Q (an orthogonal projection, hence only semi-definite) computed exactly on random A, and
//   E^R(I, I) = 0 as the counterexample.
//   Proof for all A ≠ 0: E^R(A, A) = 0 (not definite) and ‖A‖⁴ E^R(A, B) is a square (semi-definite), identities
//   over symbols from theory/global's E^R (proof()).
// Sizes: quick 100 matrices; full 2000.

using global_exact::Mat2Q;
using global_exact::Rational;

/// The proof for all A ≠ 0, from theory/global's E^R over symbols. Identities:
///   E^R(A, A) = 0                                    (at-A: B = A ≠ 0 gives 0, so not definite)
///   ‖A‖⁴ E^R(A, B) = ‖ ‖A‖²B − ⟨A,B⟩A − ⟨JA,B⟩JA ‖²     (semidefinite: a square, so E^R ≥ 0)
/// and sentences in the eight entries, with ‖A‖²E^R(A, B) a polynomial:
///   printed.nonzero-B-with-ER-le-0: ∃ A, B: ‖A‖² > 0 ∧ B ≠ 0 ∧ ‖A‖²E^R(A, B) ≤ 0      (non-empty: not definite)
///   semidefinite.ER-negative.*:     ∃ B (and p, q): ‖A‖²E^R(A, B) < 0 at A = [[1, p], [0, q]] and at
///                                   A = [[0, 1], [0, 0]]                              (empty: semi-definite)
/// The semi-definite sentence is decided at the similarity normal form: a similarity C = xI + yJ ≠ 0 multiplies the
/// first column of A as the complex number x + iy does, so some C gives CA = [[1, p], [0, q]] (first column ≠ 0) or
/// [[0, 1], [0, 0]] (first column 0, second ≠ 0), and E^R(CA, B) = E^R(A, B) (invariant, an identity). In all eight
/// entries QEPCAD B warns that its McCallum projection may not be valid; the normal form's sentence decides quickly.
Proof proof(const ClaimContext& ctx) {
  using symbolic_er::Mat2X;
  const symbolic_er::Pair p;
  const GiNaC::symbol x("x"), y("y");
  const GiNaC::ex nA = symbolic_er::norm2(p.A), a = symbolic_er::inner(p.A, p.B), j = symbolic_er::inner_J(p.A, p.B);
  const Mat2X JA = global::rotation_J<GiNaC::ex>().lazyProduct(p.A);
  const Mat2X projection_residual = local::scaled(nA, p.B) - local::scaled(a, p.A) - local::scaled(j, JA);
  const std::vector<proofs::Identity> identities = {
      {"at-A", "E^R(A, A) = 0 for every A ≠ 0", symbolic_er::E_R(p.A, p.A), GiNaC::ex(0)},
      {"semidefinite", "‖A‖⁴ E^R(A, B) = ‖ ‖A‖²B − ⟨A,B⟩A − ⟨JA,B⟩JA ‖²", nA * nA * symbolic_er::E_R(p.A, p.B),
       projection_residual.squaredNorm()},
      {"invariant", "E^R((xI + yJ)A, B) = E^R(A, B) wherever both are defined (the normal form's lemma)",
       symbolic_er::E_R(symbolic_er::times(symbolic_er::similarity(x, y), p.A), p.B), symbolic_er::E_R(p.A, p.B)},
  };

  using logic::Polynomial;
  const Polynomial norm2_A = proofs::to_polynomial(nA);
  const Polynomial form = proofs::to_polynomial((nA * symbolic_er::E_R(p.A, p.B)).normal());  // ‖A‖²E^R(A, B)
  // ‖A‖²E^R(A, B) at the similarity normal forms A = [[1, p], [0, q]] and [[0, 1], [0, 0]] (see above).
  const GiNaC::symbol p_("p"), q_("q");
  const auto normal_form = [&](const GiNaC::ex& top_right, const GiNaC::ex& bottom_right,
                               bool first_column_zero = false) {
    Mat2X A;
    if (first_column_zero)
      A << 0, 1, 0, 0;
    else
      A << 1, top_right, 0, bottom_right;
    return proofs::to_polynomial((symbolic_er::norm2(A) * symbolic_er::E_R(A, p.B)).normal());
  };
  const std::vector<std::string> entries = {"a11", "a12", "a21", "a22", "b11", "b12", "b21", "b22"};
  // B ≠ 0 as "some entry ≠ 0": linear atoms, which QEPCAD projects far faster than ‖B‖² > 0 (not decided within 60 s).
  std::vector<logic::Formula> B_nonzero;
  for (const char* b : {"b11", "b12", "b21", "b22"}) B_nonzero.push_back(logic::not_equal(Polynomial::variable(b), 0));
  const std::vector<proofs::Sentence> sentences = {
      {"printed.nonzero-B-with-ER-le-0",
       "some A ≠ 0 and B ≠ 0 have E^R(A, B) ≤ 0 (the form is not definite)",
       logic::exists(entries, logic::greater(norm2_A, 0) && logic::disjunction(std::move(B_nonzero)) &&
                                  logic::less_equal(form, 0)),
       {}},
      {"semidefinite.ER-negative.normal-form",
       "some A = [[1, p], [0, q]] and B have E^R(A, B) < 0 (not semi-definite, first column of A nonzero)",
       logic::exists({"p", "q", "b11", "b12", "b21", "b22"}, logic::less(normal_form(p_, q_), 0)),
       {}},
      {"semidefinite.ER-negative.first-column-zero",
       "some B has E^R([[0, 1], [0, 0]], B) < 0 (not semi-definite, first column of A zero)",
       logic::exists({"b11", "b12", "b21", "b22"}, logic::less(normal_form(0, 0, true), 0)),
       {}},
  };
  std::vector<ProofSentence> decided;
  for (const proofs::Sentence& sentence : sentences)
    decided.push_back(proofs::prove_sentence(sentence, ctx.proof_files(), {.seconds = 60}));
  return proofs::combined_proof(
      "all real 2×2 A ≠ 0 and B",
      "identities over symbols from theory/global's E^R: E^R(A, ·) vanishes at B = A ≠ 0 (not definite) and "
      "‖A‖⁴E^R(A, B) is a sum of squares (semi-definite); the same two facts as sentences, the second at the "
      "similarity normal form of A (E^R(CA, B) = E^R(A, B))",
      proofs::prove_identities(identities, ctx.proof_files()), std::move(decided));
}

Outcome check(const ClaimContext& ctx) {
  Outcome out;
  Rng rng(ctx.seed);
  const int samples = ctx.pick(100, 2000);
  // E^R(A, ·) is the quadratic form Q = I − (a aᵀ + j jᵀ)/‖A‖² on vec B (a = vec A, j = vec JA): compute its
  // rank, check Q² = Q (an orthogonal projection, hence semi-definite) and that B = A gives 0.
  // Q = I − (a aᵀ + j jᵀ)/‖A‖², from E^R(A, B) = ‖B‖² − (⟨A,B⟩² + ⟨JA,B⟩²)/‖A‖² (Kaji Appendix).
  Eigen::Index worst_rank = 4;
  bool projection = true;
  for (int k = 0; k < samples; ++k) {
    const Mat2Q A = global_exact::random_matrix(rng, 9, 4, true);
    const Eigen::Matrix<Rational, 4, 1> a = global::vec(A),
                                        j = global::vec<Rational>(global::rotation_J<Rational>().lazyProduct(A));
    const Eigen::Matrix<Rational, 4, 4> projected = a.lazyProduct(a.transpose()) + j.lazyProduct(j.transpose());
    const Eigen::Matrix<Rational, 4, 4> Q =
        Eigen::Matrix<Rational, 4, 4>::Identity() - local::scaled(Rational(1) / A.squaredNorm(), projected);
    const global_exact::MatQ dynamic_Q = Q;
    worst_rank = std::min(worst_rank, global_exact::rank(dynamic_Q));
    const global_exact::MatQ Q_squared = Q.lazyProduct(Q);
    projection = projection && global_exact::equal(Q_squared, dynamic_Q);
  }
  const Mat2Q A = Mat2Q::Identity(), B = Mat2Q::Identity();
  const Rational at_A = global::similarity_error(A, B);
  out.verdict = at_A == 0 ? Verdict::refuted : Verdict::confirmed;
  out.summary = "E^R(A, ·) is only positive semi-definite: an orthogonal projection of rank " +
                std::to_string(worst_rank) +
                " on vec B, vanishing on the plane span{A, JA} = {s R_δ A}; e.g. E^R(I, I) = " + exact::to_string(at_A);
  out.evidence.method = "exact rational computation of the form's matrix, its rank and Q² = Q";
  out.evidence.sample_size = static_cast<std::uint64_t>(samples);
  out.evidence.seed = ctx.seed;
  out.evidence.details = {
      {"smallest_rank_seen", worst_rank},
      {"Q_squared_equals_Q_on_all", projection},
      {"consequence",
       "Σ E^R_i over a mesh is invariant under translation and, up to the factor s², under global "
       "rotation and scale: constraints must fix translation, rotation and scale (Kaji's claim that "
       "E_t is positive definite fails too; its minimum without them is the collapse B = 0)"}};
  out.counterexample = {{"A", exact_matrix(A)},
                        {"B", exact_matrix(B)},
                        {"E_R", exact::to_string(at_A)},
                        {"note", "B ≠ 0 with E^R(A, B) = 0: the quadratic form is not definite"}};
  out.proof = proof(ctx);
  // The proof's parts in order: at-A, semidefinite, invariant (identities), then the three sentences.
  const std::vector<std::string> expected = {"zero", "zero", "zero", "non-empty", "empty", "empty"};
  for (std::size_t i = 0; i < expected.size(); ++i)
    if (const std::string& r = out.proof->sentences[i].result; r != expected[i] && r != "unknown")
      throw std::runtime_error("the proof's " + out.proof->sentences[i].name + " is " + r + ", not " + expected[i]);
  if (out.proof->decided_by_two()) out.summary += "; proved for all A ≠ 0 (identities and sentences)";
  return out;
}

}  // namespace
}  // namespace affinterp::claims::kaji_er_positive_definite
