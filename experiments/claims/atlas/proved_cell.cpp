#include "experiments/claims/atlas/proved_cell.hpp"

#include "experiments/claims/proof_strength.hpp"
#include "experiments/proofs/condition_sentences.hpp"
#include "experiments/support/random.hpp"
#include "plots/region_map.hpp"

#include <algorithm>
#include <stdexcept>

namespace affinterp::claims::atlas {

namespace {

using logic::Formula;
using logic::Point;
using proofs::SetResult;

std::string point_text(const Point& p) {
  std::string text;
  for (const auto& [name, value] : p) text += (text.empty() ? "" : ", ") + name + " = " + exact::to_string(value);
  return text;
}

nlohmann::json point_json(const Point& p) {
  nlohmann::json j = nlohmann::json::object();
  for (const auto& [name, value] : p) j[name] = exact::to_string(value);
  return j;
}

/// Second line of evidence: the condition against the suite's own exact decider at random rational points of
/// the domain (coordinates p/q, |p| ≤ 32, 1 ≤ q ≤ 8).
struct SampleComparison {
  std::uint64_t points = 0, disagreements = 0;
  std::uint64_t unanswered = 0;  ///< points where the decider has no certificate either way (3D linear norm)
  std::optional<Point> first_disagreement;
};

SampleComparison compare_with_suite(const proofs::AtlasCell& cell, std::uint64_t seed, std::uint64_t wanted) {
  SampleComparison c;
  const Formula condition = cell.condition_formula();
  Rng rng(seed);
  for (std::uint64_t draws = 0; c.points < wanted && draws < 20 * wanted; ++draws) {
    Point p;
    for (const std::string& v : cell.variables) p[v] = Rational(rng.integer(-32, 32)) / Rational(rng.integer(1, 8));
    if (!logic::holds(cell.domain, p)) continue;
    const std::optional<bool> good = proofs::suite_says_good(cell, p);
    if (!good) {
      if (++c.unanswered >= 20 && c.points == 0) return c;  // no exact decider in the suite for this cell
      continue;
    }
    ++c.points;
    if (logic::holds(condition, p) != *good && c.disagreements++ == 0) c.first_disagreement = p;
  }
  return c;
}

std::vector<std::string> draw_slices(const ClaimContext& ctx, const proofs::AtlasCell& cell,
                                     const std::vector<Slice>& slices) {
  std::vector<std::string> refs;
  const Formula condition = cell.condition_formula();
  const int n = ctx.pick(32, 96);
  for (std::size_t k = 0; k < slices.size(); ++k) {
    const Slice& s = slices[k];
    std::vector<plots::RegionPoint> points;
    bool compared = false;
    const Rational lo = exact::from_double(s.lo), step = (exact::from_double(s.hi) - lo) / n;
    for (int i = 0; i <= n; ++i)
      for (int j = 0; j <= n; ++j) {
        Point p = s.fixed;
        p[s.x] = lo + step * i;
        p[s.y] = lo + step * j;
        if (!logic::holds(cell.domain, p)) continue;
        const bool inside = logic::holds(condition, p);
        const std::optional<bool> good = proofs::suite_says_good(cell, p);
        compared = good.has_value();
        points.push_back({static_cast<double>(p[s.x]), static_cast<double>(p[s.y]), inside, good.value_or(inside)});
      }
    std::string name = (cell.dimension == 3 ? "atlas3-" : "atlas-") + cell.id();
    std::replace(name.begin(), name.end(), '.', '-');
    if (slices.size() > 1) name += "-" + std::to_string(k + 1);
    const std::string title = (cell.dimension == 3 ? "atlas3 " : "atlas ") + cell.id() + ", slice " + s.label;
    const double half = static_cast<double>(step) / 2;
    if (compared)
      plots::draw_region_map(
          ctx.figure_stem(name),
          title + ": condition vs the exact decider of " + (cell.dimension == 3 ? "goodness3.hpp" : "goodness.hpp"),
          s.x, s.y, points, half, half);
    else
      plots::draw_region(ctx.figure_stem(name), title + ": where the condition holds", s.x, s.y,
                         "good (the condition holds)", points, half, half);
    refs.push_back(RunSettings::figure_ref(name + ".png"));
    refs.push_back(RunSettings::figure_ref(name + ".svg"));
  }
  return refs;
}

}  // namespace

proofs::Sentence atlas_sentence(const proofs::AtlasCell& cell, const std::string& name, const std::string& meaning,
                                const Formula& set, const std::vector<std::string>& extra) {
  std::vector<std::string> variables = cell.variables;
  variables.insert(variables.end(), extra.begin(), extra.end());
  return proofs::sentence(name, meaning, variables, cell.domain && set);
}

std::vector<proofs::Sentence> condition_sentences(const proofs::AtlasCell& cell, const std::string& level,
                                                  const Formula& property) {
  const Formula condition = cell.condition_formula();
  return {proofs::cond_not_prop("", level, cell.variables, cell.domain, condition, property),
          proofs::prop_not_cond("", level, cell.variables, cell.domain, condition, property)};
}

namespace {

/// The proof's sentences decided (each by both deciders unless z3_only): their records, whether every set is
/// empty, and the first non-empty one with its witness.
struct DecidedSentences {
  std::vector<ProofSentence> records;
  bool all_empty = true;
  std::optional<std::pair<std::string, proofs::Witness>> non_empty;
};
DecidedSentences decide_sentences(const ClaimContext& ctx, const AtlasProof& proof) {
  DecidedSentences decided;
  for (const proofs::Sentence& sentence : proof.sentences) {
    const bool z3_alone = std::find(proof.z3_only.begin(), proof.z3_only.end(), sentence.name) != proof.z3_only.end();
    // Where QEPCAD is known not to finish (it exhausts its prime list), it gets 10 s, enough for Z3.
    const proofs::DeciderLimits limits{.seconds = z3_alone ? 10.0 : 60.0};
    const proofs::SentenceDecision d = proofs::decide_sentence(sentence, ctx.proof_files(), limits);
    decided.records.push_back(proofs::to_proof_sentence(sentence, d));  // throws when the deciders disagree
    if (d.result == SetResult::non_empty && !decided.non_empty && d.witness)
      decided.non_empty.emplace(sentence.name, *d.witness);
    decided.all_empty = decided.all_empty && d.result == SetResult::empty;
  }
  return decided;
}

/// The proof of the cell from its decided sentences, with its further formulations decided; throws when a
/// formulation finds a point where the lemma chain proves there is none.
Proof cell_proof(const ClaimContext& ctx, const proofs::AtlasCell& cell, const AtlasProof& proof,
                 const DecidedSentences& decided) {
  Proof made = proofs::make_proof(proof.scope, proof.method, decided.records);
  made.cites = proof.cites;
  // The formulations closer to the definitions take QEPCAD far longer (level D): 300 s each, as the local
  // claims' sentences.
  proofs::add_formulations(made, proof.formulations, proof.attempts, ctx.proof_files(), {.seconds = 300});
  for (const Proof& formulation : made.formulations)
    for (const ProofSentence& s : formulation.sentences)
      if (decided.all_empty && s.result == "non-empty")
        throw std::runtime_error("the formulations of atlas." + cell.id() + " disagree: " + s.name + " is non-empty");
  return made;
}

/// The second line's evidence: the method (with the suite's exact decider where it has one), the random points
/// and their disagreements.
void add_sample_evidence(Outcome& outcome, const proofs::AtlasCell& cell, const AtlasProof& proof,
                         const SampleComparison& sample, std::uint64_t seed) {
  // The method says what ran: the second line only where the suite has an exact decider for the cell.
  outcome.evidence.method =
      "first-order sentences decided for all reals (the proof; each decider's answer read from its stored "
      "transcript)" +
      (sample.points ? "; second line: the condition against the suite's exact decider (theory/local/" +
                           std::string(cell.dimension == 3 ? "goodness3.hpp" : "goodness.hpp") + ") at " +
                           std::to_string(sample.points) + " random rational points"
                     : std::string());
  outcome.evidence.sample_size = sample.points;
  outcome.evidence.seed = seed;
  outcome.evidence.details["condition_in_words"] = cell.condition_words;
  outcome.evidence.details["identities"] = proof.identities.size();
  outcome.evidence.details["random_points"] =
      sample.points == 0 ? nlohmann::json("no exact decider in the suite for this cell")
                         : nlohmann::json{{"points", sample.points}, {"disagreements", sample.disagreements}};
  if (sample.points && sample.unanswered) outcome.evidence.details["random_points"]["unanswered"] = sample.unanswered;
}

/// What keeps the cell unproved: the sentences not found empty by every decider, and the identities that fail.
std::string undecided(const std::vector<ProofSentence>& records, const std::vector<std::string>& failed_identities) {
  std::string why;
  for (const ProofSentence& s : records)
    if (s.result != "empty" ||
        std::any_of(s.runs.begin(), s.runs.end(), [](const auto& r) { return r.result == "unknown"; }))
      why += (why.empty() ? "" : ", ") + s.name;
  for (const std::string& name : failed_identities) why += (why.empty() ? "identity " : ", identity ") + name;
  return why;
}

/// A counterexample to the cell's condition: refuted with an exact point.
void refute(Outcome& outcome, std::string summary, nlohmann::json point) {
  outcome.verdict = Verdict::refuted;
  outcome.strength = Strength::exact_counterexample;
  outcome.summary = std::move(summary);
  outcome.counterexample = std::move(point);
}

}  // namespace

Outcome atlas_outcome(const ClaimContext& ctx, const proofs::AtlasCell& cell, const AtlasProof& proof,
                      const std::vector<Slice>& slices) {
  Outcome outcome;
  outcome.condition = cell.condition;
  const DecidedSentences decided = decide_sentences(ctx, proof);
  std::vector<std::string> failed_identities;
  for (const auto& [name, difference] : proof.identities)
    if (!difference.is_zero()) failed_identities.push_back(name);
  outcome.proof = cell_proof(ctx, cell, proof, decided);
  const std::optional<Strength> strength = proof_strength(*outcome.proof);
  std::string checkers;
  for (const std::string& c : outcome.proof->checked_by) checkers += (checkers.empty() ? "" : ", ") + c;

  const SampleComparison sample = compare_with_suite(cell, ctx.seed, ctx.pick(200, 2000));
  add_sample_evidence(outcome, cell, proof, sample, ctx.seed);
  if (ctx.draws_figures()) outcome.figures = draw_slices(ctx, cell, slices);
  const std::string agreement =
      sample.points ? "the suite's exact decider agrees at " + std::to_string(sample.points) + " random" : "";

  if (sample.first_disagreement) {
    if (decided.all_empty)
      throw std::runtime_error("the proof says the condition of atlas." + cell.id() +
                               " is exact, but the suite's decider disagrees at " +
                               point_text(*sample.first_disagreement));
    refute(outcome, "the condition and the suite's exact decider disagree at " + point_text(*sample.first_disagreement),
           point_json(*sample.first_disagreement));
  } else if (decided.non_empty) {
    refute(outcome, "the sentence " + decided.non_empty->first + " is non-empty: the condition is not exact",
           point_json(decided.non_empty->second.point));
    outcome.counterexample["exact"] = decided.non_empty->second.exact;
  } else if (decided.all_empty && strength && failed_identities.empty()) {
    outcome.verdict = Verdict::confirmed;
    outcome.strength = *strength;
    outcome.summary = "proved for all reals: good for " + std::string(proofs::to_string(cell.notion)) +
                      " exactly when " + cell.condition_words + " (" + std::to_string(decided.records.size()) +
                      " sentences empty; checked by " + checkers +
                      (sample.points ? "; " + agreement + " rational points" : "") + ")";
  } else {
    outcome.verdict = Verdict::inconclusive;
    outcome.strength = Strength::sample;
    outcome.summary = "not proved: undecided " + undecided(decided.records, failed_identities) +
                      (sample.points ? "; " + agreement + " points" : "");
  }
  return outcome;
}

}  // namespace affinterp::claims::atlas
