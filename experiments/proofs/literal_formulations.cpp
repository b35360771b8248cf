#include "experiments/proofs/literal_formulations.hpp"

#include "experiments/proofs/condition_sentences.hpp"
#include "experiments/proofs/lemma_sentences.hpp"

namespace affinterp::proofs {

namespace {

std::vector<Sentence> against(const ConditionOnDomain& c, const std::string& prefix, const std::string& level,
                              const Formula& property) {
  std::vector<Sentence> sentences{cond_not_prop(prefix, level, c.variables, c.domain, c.condition, property),
                                  prop_not_cond(prefix, level, c.variables, c.domain, c.condition, property)};
  if (c.hong)
    for (Sentence& s : sentences) s.qepcad_setup = hong_projection(s.formula);
  return sentences;
}

/// The condition against norm_property_directions(c.B, level): "<prefix>directions.cond-not-prop.<level>" and
/// "…prop-not-cond.<level>".
std::vector<Sentence> norm_directions_sentences(const ConditionOnDomain& c, const std::string& level) {
  return against(c, c.prefix + "directions.", level, norm_property_directions(c.B, level));
}

/// The lemmas every directions formulation uses: the norm against its square, the directions.
std::vector<Sentence> direction_lemmas() { return {lemma_L4(), lemma_L6_directions(), lemma_L1()}; }

}  // namespace

FormulationPlan area_literal(const ConditionOnDomain& c) {
  return {
      "Def 2.2.1 as written (level L): det A(t) > 0 for every t in [0, 1] and det A(s) <= det A(t) for all "
      "0 <= s <= t <= 1, or >= for all; det A(t) = det((1-t)I + tB) as the rotations have det 1 (Lemma L5, "
      "identity). No other lemma",
      against(c, c.prefix, "L", area_property(c.B, "L"))};
}

std::vector<FormulationPlan> norm_directions(const ConditionOnDomain& c) {
  const std::string common =
      "Def 2.2.2 without Dines' theorem and without Lemma L3: ||A(t)v|| = ||((1-t)I + tB)v|| (the rotations are "
      "orthogonal, Lemma L5, identity); monotone iff its square is (Lemma L4, sentence); every unit v is a non-zero "
      "multiple of (1, m) or (0, 1) and ||A(t)(lv)|| = |l| ||A(t)v|| (Lemma L6, sentence; identity "
      "L6.norm-homogeneous), so v runs over these "
      "directions, m over all reals; ";
  FormulationPlan D{common + "level D: the squared norm's t-derivative keeps one sign on [0, 1] (Lemma L1, sentence)",
                    direction_lemmas()};
  for (Sentence& s : norm_directions_sentences(c, "D")) D.sentences.push_back(std::move(s));
  FormulationPlan E{
      common + "level E: the derivative (affine in t) read at t = 0 and t = 1 (Lemmas L1 and L2, sentences)",
      direction_lemmas()};
  E.sentences.push_back(lemma_L2());
  for (Sentence& s : norm_directions_sentences(c, "E")) E.sentences.push_back(std::move(s));
  return {D, E};
}

AttemptPlan norm_directions_literal(const ConditionOnDomain& c) {
  return {
      "Def 2.2.2 at level L over the directions (1, m), (0, 1): the squared norm monotone as written, for all "
      "0 <= s <= t <= 1 (Lemmas L4, L6 only)",
      norm_directions_sentences(c, "L")};
}

}  // namespace affinterp::proofs
