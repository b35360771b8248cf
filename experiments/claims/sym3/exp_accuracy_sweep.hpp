#pragma once
// thesis.exp.accuracy's computation (thesis §3.4): every algorithm of theory/sym3/exp_batch.hpp and Kaji's
// AffineLib expSym (experiments/inputs/sym3/affinelib_exp_sym.hpp) on every test-matrix family of
// experiments/inputs/sym3/families.hpp, each result judged against its Arb-certified exp S
// (certified_score.hpp), with the 50-digit Boost references (theory/sym3/reference.hpp) cross-checked
// against Arb's balls on the first matrices of every family they cover.
#include "experiments/claims/context.hpp"
#include "experiments/claims/sym3/certified_score.hpp"
#include "experiments/inputs/sym3/families.hpp"
#include "theory/sym3/exp_batch.hpp"

#include <cmath>
#include <map>
#include <string>
#include <vector>

namespace affinterp::claims::sym3 {

using affinterp::sym3::Family;
using affinterp::sym3::NamedExpBatch;

/// Every algorithm of theory/sym3 and, as a peer, AffineLib's expSym (named "affinelib-expsym").
std::vector<NamedExpBatch> algorithms_and_peers();

/// One family's matrices, their certified truths, and every algorithm's results and scores: scores[a][k].
struct FamilySweep {
  const Family* family;
  std::vector<Mat3> S;
  std::vector<CertifiedTruth> truth;
  std::vector<std::vector<Score>> scores;
  std::vector<std::vector<Mat3>> results;
};

/// How good the certified references are, and how they compare with the Boost ones.
struct ReferenceSummary {
  std::map<std::string, std::size_t> status;  ///< matrices per status: certified, overflows, too_wide
  /// The largest Frobenius radius of a certified exp S over ‖exp S‖_F, where ‖exp S‖_F ≥ 2⁻¹⁰²², and its family.
  double max_relative_radius = 0;
  std::string max_radius_family;
  /// Certified exp S with ‖exp S‖_F < 2⁻¹⁰²², and their largest absolute Frobenius radius.
  std::size_t below_normal = 0;
  double max_absolute_radius_below_normal = 0;
  /// Boost references compared with Arb's balls, those farther outside than their own 50-digit error
  /// (10⁻⁴⁵ ‖exp S‖_F), and the largest distance outside over ‖exp S‖_F (≤ 0: inside).
  std::size_t cross_checked = 0, outside = 0;
  double worst_outside = -INFINITY;
};

struct AccuracySweep {
  std::vector<FamilySweep> families;  ///< in the order of affinterp::sym3::families()
  ReferenceSummary references;
  std::size_t matrices = 0;
};

/// Draws `per_family` matrices of family f from seed ctx.seed + f, certifies exp S for each (in parallel on
/// ctx.threads, with progress on standard error), cross-checks the first `cross_checks` of every family
/// not spanning the whole double range against the Boost reference where exp S is certified, then runs and
/// scores every algorithm.
AccuracySweep sweep_accuracy(const ClaimContext& ctx, const std::vector<NamedExpBatch>& algorithms,
                             std::size_t per_family, std::size_t cross_checks);

/// The errors of one algorithm on one family that count: certified ones, and +∞ for a non-finite result
/// where exp S is finite; the rest tallied by judgement.
struct Stats {
  double max = 0, p999 = 0;
  std::size_t worst = 0;  ///< index of the worst matrix
  std::size_t counted = 0;
  std::map<Judgement, std::size_t> tally;
  double max_excluded_upper = 0;  ///< the largest upper bound of an uncertified error
};

Stats stats_of(const FamilySweep& sweep, std::size_t algorithm);
std::size_t tally(const Stats& s, Judgement j);

/// The worst matrix of one algorithm over the families inside [0, 3].
struct Worst {
  double error = 0;
  const FamilySweep* sweep = nullptr;
  std::size_t k = 0;
};

Worst worst_in_thesis_range(const std::vector<FamilySweep>& sweeps, std::size_t algorithm);

}  // namespace affinterp::claims::sym3
