#include "experiments/claims/context.hpp"

namespace affinterp::claims {

std::uint64_t RunContext::seed_for(std::string_view claim_id) const {
  // FNV-1a over the ID, mixed with the run seed by one SplitMix64 step.
  std::uint64_t h = 1469598103934665603ull;
  for (const char c : claim_id) h = (h ^ static_cast<unsigned char>(c)) * 1099511628211ull;
  std::uint64_t z = seed + 0x9e3779b97f4a7c15ull * (h | 1);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

std::vector<std::string> RunSettings::figure_refs(const std::vector<std::string>& file_names) {
  std::vector<std::string> refs;
  for (const std::string& name : file_names) refs.push_back(figure_ref(name));
  return refs;
}

std::filesystem::path RunSettings::committed_answers() { return AFFINTERP_COMMITTED_ANSWERS; }

proofs::SentenceFiles ClaimContext::proof_files() const {
  const std::string id(claim_id);
  return {proof_dir.empty() ? std::filesystem::path() : proof_dir / id, "proofs/" + id, answer_dir / id, plan};
}

std::string_view to_string(Size size) { return size == Size::quick ? "quick" : "full"; }

}  // namespace affinterp::claims
