#pragma once
// What Coq's kernel has checked (reports/proofs/coq/MANIFEST.json, which checks/proofs/coq_test.sh holds to the
// Coq files: it compiles every file and fails on a listed theorem that rests on an axiom beyond the standard
// Reals library's), and what that makes of a proved claim's strength: a claim whose statement is a
// kernel-checked theorem is `proved-kernel-checked`; a proved claim that names a lemma of LEMMAS.md the kernel has
// not checked takes that step by hand, and says so (`proved-with-hand-steps`, Outcome::hand_steps).
#include "experiments/claims/outcome.hpp"

#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace affinterp::claims {

struct KernelChecks {
  std::set<std::string> lemmas;               ///< lemma IDs ("L9") whose every theorem is kernel-checked
  std::map<std::string, std::string> claims;  ///< claim ID → "<file>: <theorem>" of its statement, kernel-checked
  /// claim ID → how many of its empty sentences a Coq certificate (psatz, nra or a written proof) closes, of those
  /// tried (MANIFEST.json's "sentences").
  std::map<std::string, SentenceCertificates> certificates;
};

/// The manifest `manifest` (reports/proofs/coq/MANIFEST.json); nothing checked when it is absent. Throws
/// std::runtime_error naming the file when it is malformed.
KernelChecks read_kernel_checks(const std::filesystem::path& manifest);

/// The lemmas of LEMMAS.md ("L1" … ) a proof's method texts name, its formulations' included, in order of first
/// mention: the method of every proof names each lemma it rests on.
std::vector<std::string> lemmas_named(const Proof& proof);

/// `outcome` with its sentence certificates counted, and with its strength, kernel_checked and hand_steps set from
/// `checks` when its strength is a proved one: proved-kernel-checked when the claim `id`'s statement is a
/// kernel-checked theorem; otherwise the lemmas its proof names that the kernel has not checked, added to its hand
/// steps, turn `proved` into `proved-with-hand-steps`. Other strengths are left as they are.
void apply_kernel_checks(const std::string& id, Outcome& outcome, const KernelChecks& checks);

}  // namespace affinterp::claims
