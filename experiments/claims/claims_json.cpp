#include "experiments/claims/claims_json.hpp"

#include <chrono>
#include <ctime>

namespace affinterp::claims {

namespace {

nlohmann::json optional_json(const auto& value) { return value ? nlohmann::json(*value) : nlohmann::json(nullptr); }

nlohmann::json formulation_json(const Proof& proof) {
  nlohmann::json sentences = nlohmann::json::array();
  for (const ProofSentence& s : proof.sentences) {
    nlohmann::json runs = nlohmann::json::array();
    for (const ProofSentence::Run& r : s.runs) {
      nlohmann::json run = {{"tool", r.tool}, {"file", r.file}, {"result", r.result}, {"seconds", r.seconds}};
      if (r.cpu_seconds) run["cpu_seconds"] = *r.cpu_seconds;
      if (r.max_rss_kb) run["max_rss_kb"] = *r.max_rss_kb;
      runs.push_back(run);
    }
    // "file" and "seconds" of the sentence are its first decider's, as claims.json's format names them.
    sentences.push_back({{"name", s.name},
                         {"meaning", s.meaning},
                         {"result", s.result},
                         {"file", s.runs.empty() ? "" : s.runs.front().file},
                         {"seconds", s.runs.empty() ? 0.0 : s.runs.front().seconds},
                         {"structural", s.structural},
                         {"runs", runs}});
  }
  nlohmann::json out = {
      {"scope", proof.scope}, {"method", proof.method}, {"checked_by", proof.checked_by}, {"sentences", sentences}};
  if (!proof.cites.empty()) out["cites"] = proof.cites;
  return out;
}

nlohmann::json proof_json(const std::optional<Proof>& proof) {
  if (!proof) return nullptr;
  nlohmann::json out = formulation_json(*proof);
  if (!proof->formulations.empty()) {
    out["formulations"] = nlohmann::json::array();
    for (const Proof& f : proof->formulations) out["formulations"].push_back(formulation_json(f));
  }
  if (!proof->attempts.empty()) {
    out["attempts"] = nlohmann::json::array();
    for (const proofs::Attempt& a : proof->attempts)
      out["attempts"].push_back({{"formulation", a.formulation},
                                 {"sentence", a.sentence},
                                 {"tool", a.tool},
                                 {"file", a.file},
                                 {"cpu_seconds", optional_json(a.cpu_seconds)},
                                 {"max_rss_kb", optional_json(a.max_rss_kb)},
                                 {"outcome", a.outcome}});
  }
  return out;
}

std::string utc_now() {
  const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm tm{};
  gmtime_r(&now, &tm);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return text;
}

}  // namespace

nlohmann::json to_json(const ClaimResult& result) {
  const Outcome& o = result.outcome;
  const Evidence& e = o.evidence;
  return {
      {"id", result.claim->id},
      {"group", report_section(result.claim->chapter)},
      {"where", result.claim->where},
      {"statement", result.claim->statement},
      {"verdict", to_string(o.verdict)},
      {"strength", to_string(o.strength)},
      {"hand_steps", o.hand_steps},
      {"kernel_checked", optional_json(o.kernel_checked)},
      {"coq_certificates", {{"certified", o.certificates.certified}, {"tried", o.certificates.tried}}},
      {"summary", o.summary},
      {"evidence",
       {{"method", e.method},
        {"sample_size", e.sample_size},
        {"seed", optional_json(e.seed)},
        {"tolerance", optional_json(e.tolerance)},
        {"worst_deviation", optional_json(e.worst_deviation)},
        {"details", e.details},
        {"measurements", e.measurements}}},
      {"counterexample", o.counterexample},
      {"correction", optional_json(o.correction)},
      {"condition", optional_json(o.condition)},
      {"proof", proof_json(o.proof)},
      {"figures", o.figures},
      {"seconds", result.seconds},
  };
}

nlohmann::json claims_document(const ClaimRegistry& registry, const std::vector<ClaimResult>& results,
                               const RunContext& context, const nlohmann::json& environment,
                               const nlohmann::json& previous, const EngineTables& engine) {
  nlohmann::json claims = nlohmann::json::array();
  for (const Claim& claim : registry.claims()) {
    const nlohmann::json* entry = nullptr;
    nlohmann::json fresh;
    for (const auto& r : results)
      if (r.claim->id == claim.id) entry = &(fresh = to_json(r));
    if (entry == nullptr && previous.contains("claims"))
      for (const auto& old : previous["claims"])
        if (old.value("id", "") == claim.id) entry = &old;
    if (entry != nullptr) claims.push_back(*entry);
  }
  return {
      {"tool", "affinterp"},
      {"generated_at", utc_now()},
      {"seed", context.seed},
      {"size", to_string(context.size)},
      {"environment", environment},
      {"claims", claims},
      {"engine_speed", engine.speed},
      {"engine_scale", engine.scale},
      {"engine_cli", engine.cli},
      {"engine3_speed", engine.engine3},
      {"engine3_scale", engine.engine3_scale},
      {"engine3_quality", engine.engine3_quality},
  };
}

}  // namespace affinterp::claims
