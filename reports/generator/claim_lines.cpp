#include "reports/generator/claim_lines.hpp"

#include "reports/generator/markdown.hpp"

#include <sstream>

namespace affinterp::report {

using nlohmann::json;

namespace {

/// The strength in words, before the sentence certificates.
std::string strength_label(const json& claim) {
  const std::string strength = claim.value("strength", "unstated");
  const json proof = claim.value("proof", json());
  if (strength == "proved-kernel-checked")
    return "proved, kernel-checked (Coq: " + claim.value("kernel_checked", std::string("?")) + ")";
  if (strength == "proved") return "proved for all reals";
  if (strength == "proved-with-hand-steps") {
    std::string steps;
    for (const auto& step : claim.value("hand_steps", json::array()))
      steps += (steps.empty() ? "" : ", ") + step.get<std::string>();
    return "proved; " + steps + " by hand";
  }
  if (strength == "proved-one-decider") return "proved, one decider (" + checkers(proof) + ")";
  if (strength == "proved-citing") return "proved, citing " + proof.value("cites", std::string("?"));
  if (strength == "exact-counterexample") {
    if (!proof.is_object() || proof.value("checked_by", json::array()).size() < 2) return "exact counterexample";
    return "exact counterexample; rest proved (" + checkers(proof) + ")";
  }
  if (strength == "grid") return "grid only";
  if (strength == "sample") return "sample only";
  if (strength == "measured") return "measured";
  return "not stated";
}

}  // namespace

std::string strength_words(const json& claim) {
  const json certificates = claim.value("coq_certificates", json::object());
  const int tried = certificates.value("tried", 0);
  if (tried == 0) return strength_label(claim);
  return strength_label(claim) + "; Coq certificates for " + std::to_string(certificates.value("certified", 0)) +
         " of " + std::to_string(tried) + " empty sentences";
}

std::string one_line_evidence(const json& evidence) {
  std::ostringstream out;
  out << evidence.value("method", "");
  if (evidence.value("sample_size", 0ull) > 0) out << "; n = " << evidence["sample_size"].get<unsigned long long>();
  if (!evidence["seed"].is_null()) out << "; seed " << evidence["seed"].get<unsigned long long>();
  if (!evidence["tolerance"].is_null()) out << "; tol " << number(evidence["tolerance"]);
  if (!evidence["worst_deviation"].is_null()) out << "; worst " << number(evidence["worst_deviation"]);
  return out.str();
}

std::string checkers(const json& proof) {
  std::string names;
  for (const auto& tool : proof.value("checked_by", json::array()))
    names += (names.empty() ? "" : ", ") + tool.get<std::string>();
  return names.empty() ? "none" : names;
}

bool is_viewer(const std::string& path) { return path.ends_with(".html"); }

}  // namespace affinterp::report
