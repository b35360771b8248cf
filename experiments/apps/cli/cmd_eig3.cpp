// `affinterp eig3`: eigenvalues of 3×3 symmetric matrices read from standard input, by any algorithm
// of the catalogue (thesis §3.2, Eigen's, ours).
#include "experiments/apps/cli/command.hpp"
#include "experiments/apps/cli/sym3_io.hpp"

#include <iostream>
#include <memory>

namespace affinterp::cli {

namespace {

struct Eig3Options {
  std::string algorithm = "affinterp";
  bool list = false;
};

void run(const Eig3Options& options) {
  if (options.list) {
    for (const auto& a : sym3::eig_algorithms()) std::cout << a.name << "\n";
    return;
  }
  const sym3::EigAlgorithm* algorithm = sym3::find_eig(options.algorithm);
  if (!algorithm) throw CommandFailed("unknown algorithm '" + options.algorithm + "' (see eig3 --list)", usage_error);
  for_each_symmetric_matrix(std::cin, [&](const sym3::Mat3& S, std::size_t) {
    const sym3::Vec3 lambda = algorithm->eigenvalues(S);
    write_line(std::cout, std::span<const double>(lambda.data(), 3));
  });
}

}  // namespace

void add_eig3_command(CLI::App& app) {
  auto options = std::make_shared<Eig3Options>();
  CLI::App* cmd = app.add_subcommand(
      "eig3",
      "Eigenvalues of 3×3 symmetric matrices: reads one matrix per line from standard input (9 numbers, "
      "row-major) and writes the 3 eigenvalues in ascending order per line (17 significant digits). A line that "
      "is not 9 finite numbers of a symmetric matrix is an error naming the line (exit status 1); the lines "
      "before it are already written.");
  cmd->add_option("--algorithm", options->algorithm, "Algorithm (see --list)")->capture_default_str();
  cmd->add_flag("--list", options->list, "List the algorithms and exit");
  cmd->callback([options] { run(*options); });
}

}  // namespace affinterp::cli
