#include "experiments/proofs/condition_sentences.hpp"

namespace affinterp::proofs {

using logic::Formula;

Sentence sentence(std::string name, std::string meaning, std::vector<std::string> variables, Formula body) {
  return {std::move(name), std::move(meaning), logic::exists(std::move(variables), std::move(body)), {}};
}

Sentence cond_not_prop(const std::string& prefix, const std::string& level, const std::vector<std::string>& variables,
                       const Formula& domain, const Formula& condition, const Formula& property) {
  return sentence(prefix + "cond-not-prop." + level,
                  "a point of the domain where the condition holds and the property (level " + level + ") fails",
                  variables, domain && condition && !property);
}

Sentence prop_not_cond(const std::string& prefix, const std::string& level, const std::vector<std::string>& variables,
                       const Formula& domain, const Formula& condition, const Formula& property) {
  return sentence(prefix + "prop-not-cond." + level,
                  "a point of the domain where the property (level " + level + ") holds and the condition fails",
                  variables, domain && !condition && property);
}

}  // namespace affinterp::proofs
