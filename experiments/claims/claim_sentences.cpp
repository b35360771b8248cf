#include "experiments/claims/claim_sentences.hpp"

#include <stdexcept>

namespace affinterp::claims {

namespace {

std::map<std::string, SentenceBuilder, std::less<>>& builders() {
  static std::map<std::string, SentenceBuilder, std::less<>> map;  // filled before main, read after
  return map;
}

}  // namespace

SentencesDeclaration::SentencesDeclaration(std::string_view claim_id, SentenceBuilder build) {
  if (!builders().emplace(std::string(claim_id), std::move(build)).second)
    throw std::logic_error("the sentences of " + std::string(claim_id) + " are declared twice");
}

const std::map<std::string, SentenceBuilder, std::less<>>& declared_sentences() { return builders(); }

}  // namespace affinterp::claims
