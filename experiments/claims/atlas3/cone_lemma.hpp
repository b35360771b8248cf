#pragma once
// Lemma L15 (b) as a sentence of its own (LEMMAS.md): the polar and exp-log norm cells' level C then rests on no
// step by hand beyond the eigenbasis (L15 (a)) and, for exp-log, L17's monotone derivative.
#include "experiments/claims/atlas/proved_cell.hpp"

namespace affinterp::claims::atlas3 {

/// "L15.cone" (Hong's projection for QEPCAD) followed by the sentences of level C.
std::vector<proofs::Sentence> with_cone_lemma(std::vector<proofs::Sentence> level_C);

}  // namespace affinterp::claims::atlas3
