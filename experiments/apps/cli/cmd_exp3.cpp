// `affinterp exp3`: exp S of 3×3 symmetric matrices read from standard input, by any algorithm of the
// catalogue (thesis ch. 3, Eigen's, ours).
#include "experiments/apps/cli/command.hpp"
#include "experiments/apps/cli/sym3_io.hpp"

#include "theory/sym3/wide_range.hpp"

#include <cmath>
#include <cstdio>
#include <iostream>
#include <limits>
#include <memory>
#include <string_view>

namespace affinterp::cli {

namespace {

/// Why exp S came out non-finite: exp S overflows (its largest eigenvalue, computed at 1152 bits, exceeds
/// log of the largest double, up to log 3 more when the eigenvector is spread), or the algorithm failed.
std::string not_finite(const sym3::Mat3& S, std::string_view algorithm) {
  const double lambda = sym3::wide_range::eigenvalues(S)(2);
  const double threshold = std::log(std::numeric_limits<double>::max());  // 709.78…
  char text[320];
  if (lambda > threshold) {
    std::snprintf(text, sizeof text,
                  "exp S overflows double: its largest eigenvalue %.10g exceeds log(DBL_MAX) = %.8g, so an entry of "
                  "exp S exceeds DBL_MAX = %.4g",
                  lambda, threshold, std::numeric_limits<double>::max());
  } else {
    std::snprintf(text, sizeof text,
                  "%.*s gives a non-finite result although exp S is finite (largest eigenvalue %.10g, below "
                  "log(DBL_MAX) = %.8g)",
                  static_cast<int>(algorithm.size()), algorithm.data(), lambda, threshold);
  }
  return text;
}

struct Exp3Options {
  std::string algorithm = "affinterp";
  bool list = false;
};

void run(const Exp3Options& options) {
  if (options.list) {
    for (const auto& a : sym3::exp_algorithms()) std::cout << a.name << "\n";
    return;
  }
  const sym3::ExpAlgorithm* algorithm = sym3::find_exp(options.algorithm);
  if (!algorithm) throw CommandFailed("unknown algorithm '" + options.algorithm + "' (see exp3 --list)", usage_error);
  for_each_symmetric_matrix(std::cin, [&](const sym3::Mat3& S, std::size_t line) {
    const sym3::Mat3 E = algorithm->exp(S).transpose();  // row-major output
    if (!E.allFinite()) throw CommandFailed("line " + std::to_string(line) + ": " + not_finite(S, algorithm->name), 1);
    write_line(std::cout, std::span<const double>(E.data(), 9));
  });
}

}  // namespace

void add_exp3_command(CLI::App& app) {
  auto options = std::make_shared<Exp3Options>();
  CLI::App* cmd = app.add_subcommand(
      "exp3",
      "Matrix exponentials of 3×3 symmetric matrices: reads one matrix per line from standard input (9 numbers, "
      "row-major) and writes exp S per line (9 numbers, 17 significant digits). A line that is not 9 finite "
      "numbers of a symmetric matrix, or whose exponential is not finite in double, is an error naming the "
      "line (exit status 1; for an overflow it names the largest eigenvalue and the threshold log(DBL_MAX) "
      "≈ 709.78); the lines before it are already written. Ours covers the whole double range: subnormal, "
      "huge and mixed-scale entries.");
  cmd->add_option("--algorithm", options->algorithm, "Algorithm (see --list)")->capture_default_str();
  cmd->add_flag("--list", options->list, "List the algorithms and exit");
  cmd->callback([options] { run(*options); });
}

}  // namespace affinterp::cli
