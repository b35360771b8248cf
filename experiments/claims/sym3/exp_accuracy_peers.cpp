#include "experiments/claims/sym3/exp_accuracy_peers.hpp"

#include "experiments/claims/values.hpp"

#include <map>
#include <span>
#include <sstream>

namespace affinterp::claims::sym3 {

namespace {

/// exp S's certified midpoint as doubles.
Mat3 midpoint(const certified::Balls& F) {
  Mat3 M;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) M(i, j) = F.mid(i, j);
  return M;
}

}  // namespace

nlohmann::json error_json(double error) {
  if (std::isfinite(error)) return error;
  return "non-finite result (NaN or ∞)";
}

std::string short_number(double x) {
  std::ostringstream out;
  out.precision(1);
  out << std::scientific << x;
  return out.str();
}

nlohmann::json matrix_case(const Mat3& S, const std::string& algorithm, const Mat3& E, const CertifiedTruth& truth) {
  Eigen::Matrix<exact::Rational, 3, 3> exact_S;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) exact_S(i, j) = exact::from_double(S(i, j));
  const certified::CertifiedEigenvalues lambda = certified::eigenvalues(S);
  const Score s = score(E, truth);
  nlohmann::json out = {
      {"S", float_matrix(S)},
      {"S_exact", exact_matrix(exact_S)},
      {"eigenvalues", {lambda.value.mid(0), lambda.value.mid(1), lambda.value.mid(2)}},
      {"algorithm", algorithm},
      {"judgement", to_string(s.judgement)},
  };
  // JSON has no NaN or ∞: non-finite entries are written as text.
  nlohmann::json result = nlohmann::json::array();
  for (int i = 0; i < 3; ++i) {
    nlohmann::json row = nlohmann::json::array();
    for (int j = 0; j < 3; ++j)
      row.push_back(std::isfinite(E(i, j)) ? nlohmann::json(E(i, j)) : nlohmann::json(std::to_string(E(i, j))));
    result.push_back(row);
  }
  out["result"] = result;
  if (truth.exp.status == certified::Status::certified) {
    out["reference"] = float_matrix(midpoint(truth.exp.value));
    out["reference_frobenius_radius"] = truth.exp.value.frobenius_radius();
    out["relative_frobenius_error"] = error_json(s.error);
  }
  return out;
}

nlohmann::json matrix_case(const Mat3& S, const NamedExpBatch& algorithm) {
  Mat3 E;
  algorithm.exp(std::span<const Mat3>(&S, 1), std::span<Mat3>(&E, 1));
  return matrix_case(S, algorithm.name, E, certified_truth(S));
}

namespace {

/// Per algorithm and kind of failure ("wrong", "non_finite", "finite_where_overflow"): how many per family, and the
/// example kept (family sweep, index, key: the largest error when wrong, the smallest ‖S‖ otherwise).
struct Failures {
  struct Example {
    const FamilySweep* sweep = nullptr;
    std::size_t k = 0;
    double key = 0;
  };
  std::map<std::string, Example> examples;
  std::map<std::string, std::map<std::string, std::size_t>> counts;
};

/// Records algorithm `a`'s failures on `sweep` in `failures`; returns how many results were wrong (certified
/// error above kWrong).
std::size_t record_failures(const FamilySweep& sweep, std::size_t a, Failures& failures) {
  std::size_t wrong = 0;
  for (std::size_t k = 0; k < sweep.S.size(); ++k) {
    const Score& score = sweep.scores[a][k];
    std::string kind;
    double key = 0;
    if (score.judgement == Judgement::certified && score.error > kWrong) {
      kind = "wrong", key = score.error, ++wrong;
    } else if (score.judgement == Judgement::non_finite || score.judgement == Judgement::finite_where_overflow) {
      kind = score.judgement == Judgement::non_finite ? "non_finite" : "finite_where_overflow";
      key = -sweep.S[k].cwiseAbs().maxCoeff();
    } else {
      continue;
    }
    ++failures.counts[kind][sweep.family->name];
    Failures::Example& e = failures.examples[kind];
    if (!e.sweep || key > e.key) e = {&sweep, k, key};
  }
  return wrong;
}

/// Algorithm `a` on one family: its entry in the peer data and its cell in the table (worst certified error, then
/// the non-finite results, the finite ones where exp S overflows, and the excluded ones).
std::string peer_cell(const FamilySweep& sweep, std::size_t a, std::size_t wrong, nlohmann::json& data) {
  const Stats s = stats_of(sweep, a);
  const std::size_t non_finite = tally(s, Judgement::non_finite);
  const std::size_t finite_where_overflow = tally(s, Judgement::finite_where_overflow);
  const std::size_t excluded = tally(s, Judgement::error_not_certified) + tally(s, Judgement::reference_too_wide);
  double worst_finite = 0;  // the worst certified error among finite results
  for (const Score& score : sweep.scores[a])
    if (score.judgement == Judgement::certified) worst_finite = std::max(worst_finite, score.error);
  data = {
      {"worst_certified_error", worst_finite},
      {"max", error_json(s.max)},  // with a non-finite result where exp S is finite counted as ∞
      {"p99.9", error_json(s.p999)},
      {"certified", tally(s, Judgement::certified)},
      {"non_finite", non_finite},
      {"finite_where_overflow", finite_where_overflow},
      {"wrong", wrong},
      {"excluded", excluded},
  };
  std::string cell = tally(s, Judgement::certified) ? short_number(worst_finite) : "—";
  if (non_finite) cell += "; **" + std::to_string(non_finite) + " NaN/∞**";
  if (finite_where_overflow) cell += "; **" + std::to_string(finite_where_overflow) + " finite, exp S overflows**";
  if (excluded) cell += "; " + std::to_string(excluded) + " excl.";
  return cell;
}

/// An algorithm's failures by kind: their count, per family, and the example matrix.
nlohmann::json failures_json(const Failures& failures, const NamedExpBatch& algorithm, std::size_t a) {
  nlohmann::json kinds = nlohmann::json::object();
  for (const auto& [kind, per_family] : failures.counts) {
    std::size_t total = 0;
    for (const auto& [family, n] : per_family) total += n;
    const Failures::Example& e = failures.examples.at(kind);
    nlohmann::json example =
        matrix_case(e.sweep->S[e.k], algorithm.name, e.sweep->results[a][e.k], e.sweep->truth[e.k]);
    example["family"] = e.sweep->family->name;
    kinds[kind] = {{"count", total}, {"families", per_family}, {"example", example}};
  }
  return kinds;
}

}  // namespace

PeerTable peer_table(const std::vector<FamilySweep>& sweeps, const std::vector<NamedExpBatch>& algorithms) {
  PeerTable table;
  nlohmann::json columns = {"family"};
  for (const auto& algorithm : algorithms) columns.push_back(algorithm.name);
  nlohmann::json rows = nlohmann::json::array();
  std::vector<Failures> failures(algorithms.size());
  for (const auto& sweep : sweeps) {
    nlohmann::json row = {sweep.family->name};
    for (std::size_t a = 0; a < algorithms.size(); ++a) {
      const std::size_t wrong = record_failures(sweep, a, failures[a]);
      row.push_back(peer_cell(sweep, a, wrong, table.data[sweep.family->name][algorithms[a].name]));
    }
    rows.push_back(row);
  }
  for (std::size_t a = 0; a < algorithms.size(); ++a)
    table.failures[algorithms[a].name] = failures_json(failures[a], algorithms[a], a);
  table.markdown = {
      {"title",
       "Peer table: worst certified relative Frobenius error per family and algorithm (errors count only where "
       "Arb's ball certifies them); NaN/∞ = non-finite where exp S is finite; 'finite, exp S overflows' = a "
       "finite result where exp S overflows in double; excl. = excluded (uncertified error or reference); "
       "matrices in the evidence under 'failures'"},
      {"columns", columns},
      {"rows", rows},
      {"replaces", {"peers"}},
  };
  return table;
}

}  // namespace affinterp::claims::sym3
