// `affinterp exp3`: exp S of 3×3 symmetric matrices read from standard input, by any algorithm of the
// catalogue (thesis ch. 3, Eigen's, ours).
#include "experiments/apps/cli/command.hpp"
#include "experiments/apps/cli/sym3_io.hpp"

#include <iostream>
#include <memory>

namespace affinterp::cli {

namespace {

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
    if (!E.allFinite()) {
      throw CommandFailed("line " + std::to_string(line) + ": exp S is not finite in double with " +
                              std::string(algorithm->name) + " (exp overflows above about 709.78)",
                          1);
    }
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
      "line (exit status 1); the lines before it are already written.");
  cmd->add_option("--algorithm", options->algorithm, "Algorithm (see --list)")->capture_default_str();
  cmd->add_flag("--list", options->list, "List the algorithms and exit");
  cmd->callback([options] { run(*options); });
}

}  // namespace affinterp::cli
