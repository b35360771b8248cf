#include "experiments/claims/atlas3/cone_lemma.hpp"

#include "experiments/proofs/condition_sentences.hpp"
#include "experiments/proofs/goodness3_formulas.hpp"

namespace affinterp::claims::atlas3 {

std::vector<proofs::Sentence> with_cone_lemma(std::vector<proofs::Sentence> level_C) {
  std::vector<std::string> variables;
  for (const char* prefix : {"a", "b", "w"})
    for (int i = 1; i <= 3; ++i) variables.push_back(prefix + std::to_string(i));
  proofs::Sentence cone = proofs::sentence("L15.cone",
                                           "generators with a_i b_i > 0 or a_i = b_i = 0 whose cone meets the open "
                                           "second quadrant though no pair's does",
                                           variables, proofs::cone_lemma_fails());
  // McCallum's projection meets a factor that vanishes on a cylinder: Hong's is complete.
  cone.qepcad_setup = proofs::hong_projection(cone.formula);
  level_C.insert(level_C.begin(), cone);
  return level_C;
}

}  // namespace affinterp::claims::atlas3
