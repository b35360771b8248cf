#include "experiments/claims/claim.hpp"
#include "experiments/claims/origin/ginac_values.hpp"
#include "experiments/proofs/identity.hpp"
#include "experiments/proofs/step_nodes.hpp"
#include "plots/origin/fig_2_7.hpp"
#include "theory/origin/affine_frames.hpp"
#include "theory/origin/equal_energy_locus.hpp"
#include "theory/origin/printed_section_2_3.hpp"
#include "theory/origin/symbols.hpp"
#include "theory/origin/two_triangles.hpp"

#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace affinterp::claims::thesis_sec_2_3_matrices {
namespace {

Outcome check(const ClaimContext& ctx);

const ClaimDeclaration claim{{
    .id = "thesis.sec-2.3.matrices",
    .chapter = Chapter::origin,
    .where = "thesis §2.3",
    .statement = "The printed A1, A2 (origin o = (x, y)) and B1, B2 describe the two-triangle configuration.",
    .strength = Strength::exact_counterexample,
    .check = check,
}};

// Reading: source p1 = (0, 0), p2 = (1, 0), p3 = (0, 1), p4 = (1, 1) (the only one B1's columns v2 − v1, v3 − v1 and
//   B2's v4 − v3, v4 − v2 allow), T1 = (p1, p2, p3) and T2 = (p2, p4, p3) sharing the edge p2p3; A_i the affine map
//   of T_i onto its image in one target configuration; every printed X(o) the world map X⁰ written about the
//   origin o, X(o) = T(X⁰, −o) (Def 2.3.2). b21, b22 are read as printed ('− v4x x(…)') and as intended
//   ('− v4x + x(…)').
// Method: exact symbolic identities in x, y and v (GiNaC over ℚ): each printed matrix against T(X⁰, −o), and the
//   images of the shared vertices under A1 and A2, which one target configuration requires to agree. Draws
//   thesis Fig 2.7.
//   The same identities are decided by the two checkers of the identity prover (proof()).
// Sizes: symbolic; the same at either size.

using origin::printed::Reading;

GiNaC::matrix minus_o() { return origin::column(-origin::symbols().x, -origin::symbols().y); }

nlohmann::json point(const GiNaC::matrix& p) { return {exact_number(p(0, 0)), exact_number(p(1, 0))}; }

std::string text(const GiNaC::matrix& p) {
  std::ostringstream out;
  out << "(" << formula(p(0, 0)) << "," << formula(p(1, 0)) << ")";
  return out.str();
}

/// The identities behind the verdict, each decided by GiNaC and an exact degree grid: every printed matrix is its
/// world map written about o (B2 with the '+' restored), and A1, A2 send the shared vertices to different points.
Proof proof(const ClaimContext& ctx, const origin::TwoTriangles& config) {
  const origin::Symbols& s = origin::symbols();
  const GiNaC::matrix B1 = origin::intermediate_map(config, 0, s.v), B2 = origin::intermediate_map(config, 1, s.v);
  // T(A, −o) = shift(−o) · A · shift(o) (Def. 2.3.2, translate_origin), a product the checkers perform.
  const GiNaC::matrix I{{1, 0}, {0, 1}};
  const auto about_o = [&I](const GiNaC::matrix& world) -> GiNaC::ex {
    return proofs::product(
        {origin::affine_matrix(I, minus_o()), world, origin::affine_matrix(I, minus_o().mul_scalar(-1))});
  };
  // A p for a point p = (p1, p2): the first two entries of A (p1, p2, 1)ᵀ, a product the checkers perform.
  const auto apply = [](const GiNaC::matrix& A, const GiNaC::matrix& p) -> GiNaC::ex {
    const GiNaC::ex image = proofs::product(A, GiNaC::matrix{{p(0, 0)}, {p(1, 0)}, {1}});
    return GiNaC::matrix{{proofs::entry(image, 0)}, {proofs::entry(image, 1)}};
  };
  std::vector<proofs::Identity> identities = {
      {"A1-about-o", "printed A1 = T(A1(0), −o)", origin::printed::A1(), about_o(config.A[0])},
      {"A2-about-o", "printed A2 = T(A2(0), −o)", origin::printed::A2(), about_o(config.A[1])},
      {"B1-about-o", "printed B1 = T(B1(v), −o)", origin::printed::B1(), about_o(B1)},
      {"B2-intended-about-o", "printed B2 with the '+' restored in b21, b22 = T(B2(v), −o)",
       origin::printed::B2(Reading::intended), about_o(B2)},
      {"B2-as-printed-about-o", "printed B2 as it stands = T(B2(v), −o) (fails: '− v4x x(…)')",
       origin::printed::B2(Reading::as_printed), about_o(B2)},
  };
  for (unsigned k : {1u, 2u}) {
    const std::string p = k == 1 ? "p2" : "p3";
    const GiNaC::matrix at = origin::column(config.source(0, k), config.source(1, k));
    identities.push_back({"shared-vertex-" + p, "A1 " + p + " = A2 " + p + " (one target configuration; fails)",
                          apply(config.A[0], at), apply(config.A[1], at)});
  }
  return proofs::identity_proof(
      "every origin o = (x, y) and every intermediate configuration v",
      "identities in x, y and v from theory/origin's T(A, o) (Def. 2.3.2) and the printed matrices",
      proofs::prove_identities(identities, ctx.proof_files()));
}

/// Whether each printed matrix is its world-coordinate map written about the origin o, X = T(X⁰, −o) (Def. 2.3.2);
/// B2 in both readings of b21, b22.
struct AboutOrigin {
  bool A1 = false, A2 = false, B1 = false, B2_printed = false, B2_intended = false;
};
AboutOrigin about_origin(const origin::TwoTriangles& config) {
  const origin::Symbols& s = origin::symbols();
  const GiNaC::matrix B1 = origin::intermediate_map(config, 0, s.v), B2 = origin::intermediate_map(config, 1, s.v);
  const auto holds = [](const GiNaC::matrix& world, const GiNaC::matrix& printed) {
    return origin::is_zero_matrix(origin::translate_origin(world, minus_o()).sub(printed));
  };
  return {holds(config.A[0], origin::printed::A1()), holds(config.A[1], origin::printed::A2()),
          holds(B1, origin::printed::B1()), holds(B2, origin::printed::B2(Reading::as_printed)),
          holds(B2, origin::printed::B2(Reading::intended))};
}

/// One target configuration: A1 and A2 must send the shared vertices p2, p3 to the same points. Each vertex's
/// images, and both maps' images of the edge in words.
struct SharedEdge {
  nlohmann::json vertices = nlohmann::json::array();
  std::string by_A1, by_A2;
  bool agrees = true;
};
SharedEdge shared_edge(const origin::TwoTriangles& config) {
  SharedEdge edge;
  for (unsigned k : {1u, 2u}) {
    const GiNaC::matrix p = origin::column(config.source(0, k), config.source(1, k));
    const GiNaC::matrix q1 = origin::apply(config.A[0], p), q2 = origin::apply(config.A[1], p);
    const bool agrees = origin::is_zero_matrix(q1.sub(q2));
    edge.agrees = edge.agrees && agrees;
    edge.by_A1 += (edge.by_A1.empty() ? "" : ", ") + text(q1);
    edge.by_A2 += (edge.by_A2.empty() ? "" : ", ") + text(q2);
    edge.vertices.push_back({{"vertex", k == 1 ? "p2" : "p3"},
                             {"p", point(p)},
                             {"A1 p", point(q1)},
                             {"A2 p", point(q2)},
                             {"agree", agrees}});
  }
  return edge;
}

/// The target triangles A_i(T_i) that the maps imply, corner by corner.
nlohmann::json target_triangles(const origin::TwoTriangles& config) {
  nlohmann::json targets = nlohmann::json::object();
  for (unsigned i = 0; i < 2; ++i) {
    nlohmann::json corners = nlohmann::json::array();
    for (unsigned k : config.triangles[i])
      corners.push_back(point(origin::apply(config.A[i], origin::column(config.source(0, k), config.source(1, k)))));
    targets[i == 0 ? "A1(T1) = (A1 p1, A1 p2, A1 p3)" : "A2(T2) = (A2 p2, A2 p4, A2 p3)"] = corners;
  }
  return targets;
}

/// The proof's two checkers decide the same identities as the symbolic comparison; a difference is reported.
void require_proof_agrees(const Proof& proof, const AboutOrigin& about, const SharedEdge& edge) {
  const std::vector<bool> symbolic = {about.A1,
                                      about.A2,
                                      about.B1,
                                      about.B2_intended,
                                      about.B2_printed,
                                      edge.vertices[0]["agree"].get<bool>(),
                                      edge.vertices[1]["agree"].get<bool>()};
  for (std::size_t i = 0; i < symbolic.size(); ++i)
    if ((proof.sentences[i].result == "zero") != symbolic[i])
      throw std::runtime_error("the proof's identity " + proof.sentences[i].name +
                               " disagrees with the symbolic comparison");
}

/// The verdict: confirmed when the matrices are one configuration written about o, corrected when only B2's
/// missing '+' stands in the way, refuted otherwise (A1 and A2 from two configurations, or o entering otherwise).
void decide(Outcome& out, const origin::TwoTriangles& config, const AboutOrigin& about, const SharedEdge& edge) {
  const bool origin_role = about.B1 && about.A1 && about.A2 && about.B2_intended;
  if (origin_role && edge.agrees) {
    out.verdict = about.B2_printed ? Verdict::confirmed : Verdict::corrected;
  } else {
    out.verdict = Verdict::refuted;
  }
  if (!edge.agrees) {
    const GiNaC::matrix p3_minus_p2 = origin::column(-1, 1);
    out.summary = "A1 and A2 do not come from one target configuration: A1 sends the shared vertices p2, p3 to " +
                  edge.by_A1 + ", A2 to " + edge.by_A2 + " (the edge p3 - p2 to " +
                  text(origin::linear_part(config.A[0]).mul(p3_minus_p2)) + " vs " +
                  text(origin::linear_part(config.A[1]).mul(p3_minus_p2)) +
                  "); the origin enters A1, A2, B1 consistently as T(X, -o), B2 " +
                  (about.B2_printed ? "too" : "only with the '+' missing in b21, b22 restored");
    out.counterexample = {{"x", "0"},
                          {"y", "0"},
                          {"A1", exact_matrix(config.A[0])},
                          {"A2", exact_matrix(config.A[1])},
                          {"images of the shared vertices", edge.vertices}};
  } else if (!origin_role) {
    out.summary = "the printed matrices are not the maps of the configuration written about the origin o";
  } else {
    out.summary = about.B2_printed ? "the printed matrices describe one two-triangle configuration about the origin o"
                                   : "the printed matrices describe one configuration once the '+' missing in b21, "
                                     "b22 is restored";
  }
  if (out.verdict == Verdict::corrected)
    out.correction = "b21 = -x + v2x + v3x - v4x + x(-v3x + v4x) + y(-v2x + v4x), b22 likewise in y";
}

Outcome check(const ClaimContext& ctx) {
  const origin::TwoTriangles config = origin::thesis_two_triangles();
  const AboutOrigin about = about_origin(config);
  const SharedEdge edge = shared_edge(config);
  Outcome out;
  out.evidence.method = "exact symbolic identities in x, y and v (GiNaC, rational arithmetic)";
  out.evidence.sample_size = 7;
  out.evidence.details = {
      {"reading",
       "source p1=(0,0), p2=(1,0), p3=(0,1), p4=(1,1) (the only one B1's columns v2-v1, v3-v1 and B2's v4-v3, "
       "v4-v2 with their translations allow), T1=(p1,p2,p3), T2=(p2,p4,p3) sharing edge p2p3; A_i the affine "
       "map of T_i onto its image in ONE target configuration of four vertices; every printed matrix X(o) the "
       "world map X0 written about the origin o, X(o) = T(X0, -o) (Def. 2.3.2)"},
      {"B1 = T(B1(v), -o)", about.B1},
      {"B2 = T(B2(v), -o), b21/b22 as printed ('- v4x x(...)')", about.B2_printed},
      {"B2 = T(B2(v), -o), b21/b22 intended ('- v4x + x(...)')", about.B2_intended},
      {"A1 = T(A1(0), -o)", about.A1},
      {"A2 = T(A2(0), -o)", about.A2},
      {"A1, A2 agree on the shared edge", edge.agrees},
      {"shared vertices", edge.vertices},
      {"target triangles", target_triangles(config)},
  };
  out.proof = proof(ctx, config);
  require_proof_agrees(*out.proof, about, edge);
  decide(out, config, about, edge);
  if (ctx.draws_figures()) {
    const plots::Fig27 figure = plots::draw_fig_2_7(ctx.figure_dir, config);
    out.figures = ctx.figure_refs(figure.files);
    out.evidence.details["Fig 2.7: largest vertex gap between red and green frames"] = figure.largest_gap;
  }
  return out;
}

}  // namespace
}  // namespace affinterp::claims::thesis_sec_2_3_matrices
