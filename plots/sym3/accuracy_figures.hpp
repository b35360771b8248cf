#pragma once
// The figures of the accuracy of exp S (thesis §3.4, claim thesis.exp.accuracy): the worst certified error
// against the eigenvalue gap, and the peer table as a heat map. Each draws to `stem` (.png and .svg) and
// returns the names of the files it drew.
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace affinterp::plots {

/// One algorithm's worst certified relative Frobenius error per family of close eigenvalues, against the
/// family's gap: pairs λ, λ + gap (third eigenvalue free) and triples λ, λ + gap, λ + 2 gap. A gap of 0 (exact
/// repeats) is drawn at 10⁻¹⁸, an error of 0 at 10⁻¹⁸ and a non-finite one (NaN or ∞) at 10¹⁶.
struct GapErrors {
  std::vector<std::pair<double, double>> pairs, triples;  ///< (gap, worst error)
};

/// Two panels, pairs above and triples below, one curve per algorithm (errors[a] is algorithms[a]'s), with
/// the thesis's 10⁻⁶ threshold on both axes.
std::vector<std::string> draw_error_vs_gap(const std::filesystem::path& stem,
                                           const std::vector<std::string>& algorithms,
                                           const std::vector<GapErrors>& errors);

/// log₁₀ of worst[f][a], the worst certified error of algorithms[a] on families[f] (0 when none is certified),
/// per family (row) and algorithm (column); std::nullopt, where the algorithm returned a non-finite result
/// where exp S is finite or a finite one where it overflows, is drawn black.
std::vector<std::string> draw_peer_errors(const std::filesystem::path& stem, const std::vector<std::string>& families,
                                          const std::vector<std::string>& algorithms,
                                          const std::vector<std::vector<std::optional<double>>>& worst);

}  // namespace affinterp::plots
