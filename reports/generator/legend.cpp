#include "reports/generator/legend.hpp"

#include <map>
#include <string>

namespace affinterp::report {

void write_verdict_legend(std::ostringstream& md) {
  md << "## Verdicts\n\n"
        "- **confirmed**: holds on everything tried (exact computation where the claim is algebraic, "
        "otherwise a sweep whose size, seed and tolerance are stated).\n"
        "- **refuted**: fails; the counterexample can be re-verified from claims.json alone.\n"
        "- **corrected**: fails as printed, holds after the stated correction.\n"
        "- **reproduced** / **not-reproduced**: a measured figure compared with the paper's on every recorded "
        "machine (`bench/history/`, one entry per run; a machine is one CPU model, vector extension and compiler): "
        "each machine's runs are pooled into one 95% interval (a bootstrap that resamples runs, then processes, "
        "then repetitions), which lies inside / outside the band of values the claim's wording allows (stated in "
        "the claim's rule; an interval across an edge of the band leaves that machine undecided), and every machine "
        "says so. More runs of one machine narrow its interval; they cannot make the claim machine-dependent.\n"
        "- **machine-dependent**: a measured figure reproduced on one machine and not on another: a property of "
        "the machine, not of the claim; the claim's tables list each machine's pooled interval and its runs. "
        "Machines that decide and agree while others are undecided leave the claim inconclusive.\n"
        "- **inconclusive**: not decided; the finding says why.\n"
        "- **pending**: no check implemented yet.\n\n";
}

void write_strength_legend(std::ostringstream& md, const nlohmann::json& claims) {
  md << "## Strength\n\n"
        "- **proved, kernel-checked (Coq: file: theorem)**: proved for all reals as below, and the claim's "
        "statement is also a theorem of `proofs/coq/` checked by Coq's kernel, every lemma and step of it in Coq, "
        "resting on no axiom beyond the standard Reals library's (`proofs/coq/MANIFEST.json`; the test "
        "`proofs.coq` compiles every file and prints each theorem's assumptions).\n"
        "- **Coq certificates for n of m empty sentences** (after any strength): of the first-order sentences the "
        "proof needs to be empty, n are also theorems Coq's kernel checked, closed by `psatz`/`nra` or a written "
        "proof (`proofs/coq/Sentences*.v`), of the m tried; the rest rest on the two deciders.\n"
        "- **proved; Lk by hand**: proved for all reals as below, except that the named lemmas of "
        "`proofs/LEMMAS.md` are proved there by hand and not yet checked by Coq's kernel.\n"
        "- **proved for all reals**: one complete formulation of the claim (and of its correction, if any) "
        "reduces, by the lemmas written out in `proofs/LEMMAS.md`, to first-order sentences over the reals each "
        "answered by two independent deciders (of QEPCAD B, Z3 and cvc5) and polynomial identities each checked by "
        "two independent checkers (GiNaC, an exact degree grid) that each carry out the identity's step (derivative, "
        "substitution, product), citing no external theorem, and every lemma it names checked by Coq's kernel; a "
        "transcript with an "
        "error or a warning answers nothing. The sentence files and each decider's transcript are in `proofs/` "
        "and rerun with the tool alone. A proof may have several formulations: the lemma chain, and one taken "
        "as nearly as written from the paper's definition (Def 2.2.1: for all 0 <= s <= t <= 1; Def 2.2.2: for "
        "every t in [0, 1] and every unit v) with as few lemmas as a decider answers, each lemma it uses a "
        "sentence of its own. What was tried and not answered (tool, CPU time, memory, outcome), and what no "
        "decider can be given (a transcendental homotopy), is listed under \"Tried for the record\".\n"
        "- **proved, one decider (name)**: as above, but some sentence was answered by the named decider only.\n"
        "- **proved, citing (theorem)**: as above, with an external published theorem as a step (full reference "
        "given), and no formulation without it answered by two deciders.\n"
        "- Sentences marked **structural** are empty for propositional reasons alone and count as no evidence; "
        "a proof of structural sentences only proves nothing.\n"
        "- **exact counterexample**: the printed claim fails at an exact (rational) point anyone can re-verify. "
        "With \"rest proved\", the claim's proof section decides for all reals, by the deciders named, the "
        "sentences that fail as printed and those that hold (the correction, or what holds instead); otherwise "
        "a correction is checked on a grid or sample only.\n"
        "- **grid only** / **sample only**: checked on the stated grid or random sample (size, seed and "
        "tolerance in the evidence), not proved.\n"
        "- **measured**: a measured figure, with its 95% bootstrap interval over repeated runs, on each recorded "
        "machine.\n\n";
  std::map<std::string, int> counts;
  for (const auto& claim : claims) ++counts[claim.value("strength", "unstated")];
  md << "Claims by strength (`strength` in claims.json):";
  for (const auto& [words, count] : counts) md << " " << words << ": " << count << ";";
  md << "\n\n";
}

}  // namespace affinterp::report
