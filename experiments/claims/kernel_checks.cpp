#include "experiments/claims/kernel_checks.hpp"

#include "experiments/claims/proof_strength.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <fstream>
#include <regex>
#include <stdexcept>

namespace affinterp::claims {

KernelChecks read_kernel_checks(const std::filesystem::path& manifest) {
  KernelChecks checks;
  std::ifstream in(manifest);
  if (!in) return checks;
  try {
    const nlohmann::json json = nlohmann::json::parse(in);
    for (const auto& lemma : json.at("lemmas"))
      if (lemma.at("status") == "kernel-checked") checks.lemmas.insert(lemma.at("id").get<std::string>());
    for (const auto& claim : json.value("claims", nlohmann::json::array()))
      if (claim.at("status") == "kernel-checked")
        checks.claims[claim.at("claim").get<std::string>()] =
            claim.at("file").get<std::string>() + ": " + claim.at("theorem").get<std::string>();
    for (const auto& sentence : json.value("sentences", nlohmann::json::array())) {
      SentenceCertificates& count = checks.certificates[sentence.at("claim").get<std::string>()];
      ++count.tried;
      if (sentence.at("status") == "certificate") ++count.certified;
    }
  } catch (const nlohmann::json::exception& e) {
    throw std::runtime_error(manifest.string() + ": " + e.what());
  }
  return checks;
}

namespace {

void add_lemmas_of(const std::string& method, std::vector<std::string>& lemmas) {
  static const std::regex lemma(R"(\bL([0-9]+)\b)");
  for (std::sregex_iterator it(method.begin(), method.end(), lemma), end; it != end; ++it)
    if (std::find(lemmas.begin(), lemmas.end(), it->str()) == lemmas.end()) lemmas.push_back(it->str());
}

}  // namespace

std::vector<std::string> lemmas_named(const Proof& proof) {
  std::vector<std::string> lemmas;
  add_lemmas_of(proof.method, lemmas);
  for (const Proof& formulation : proof.formulations) add_lemmas_of(formulation.method, lemmas);
  return lemmas;
}

void apply_kernel_checks(const std::string& id, Outcome& outcome, const KernelChecks& checks) {
  if (const auto count = checks.certificates.find(id); count != checks.certificates.end())
    outcome.certificates = count->second;
  if (!is_proved(outcome.strength) || !outcome.proof) return;
  if (const auto theorem = checks.claims.find(id); theorem != checks.claims.end()) {
    outcome.kernel_checked = theorem->second;
    outcome.strength = Strength::proved_kernel_checked;
    return;
  }
  for (const std::string& lemma : lemmas_named(*outcome.proof))
    if (!checks.lemmas.contains(lemma) &&
        std::find(outcome.hand_steps.begin(), outcome.hand_steps.end(), lemma) == outcome.hand_steps.end())
      outcome.hand_steps.push_back(lemma);
  if (outcome.strength == Strength::proved && !outcome.hand_steps.empty())
    outcome.strength = Strength::proved_hand_steps;
}

}  // namespace affinterp::claims
