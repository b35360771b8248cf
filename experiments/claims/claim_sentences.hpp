#pragma once
// The sentences a claim's check decides for all reals, declared beside its ClaimDeclaration (claim.hpp) so that
// they can be built without deciding them: checks/claims/sentence_files_test.cpp compares their text with the
// committed files reports/proofs/<claim id>/<name>.qepcad and .smt2, whose decided answers belong to that text.
#include "experiments/claims/context.hpp"
#include "experiments/proofs/decide_sentence.hpp"

#include <functional>
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace affinterp::claims {

/// The sentences a check decides, built for its context (the size picks which).
using SentenceBuilder = std::function<std::vector<proofs::Sentence>(const ClaimContext&)>;

/// Adds the builder of the claim's sentences to declared_sentences() when constructed. Define at most one, at
/// namespace scope, in the claim's file; a repeated ID stops the program before main, naming the ID.
class SentencesDeclaration {
 public:
  SentencesDeclaration(std::string_view claim_id, SentenceBuilder build);
};

/// Every declared builder, by claim ID.
const std::map<std::string, SentenceBuilder, std::less<>>& declared_sentences();

}  // namespace affinterp::claims
