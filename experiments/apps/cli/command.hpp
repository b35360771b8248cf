#pragma once
// The affinterp CLI: one file per command, each adding itself to the application.
#include <CLI/CLI.hpp>

#include <cstddef>
#include <stdexcept>
#include <string>

namespace affinterp::cli {

/// A command's failure: a one-line message for standard error and the exit status to return.
struct CommandFailed : std::runtime_error {
  CommandFailed(const std::string& message, int status) : std::runtime_error(message), status(status) {}
  int status;
};

/// Exit status for bad command-line usage.
inline constexpr int usage_error = 2;

/// "1 frame", "30 frames": the count in a command's closing line.
inline std::string frames_count(std::size_t n) { return std::to_string(n) + (n == 1 ? " frame" : " frames"); }

void add_claims_command(CLI::App& app);
void add_report_command(CLI::App& app);
void add_exp3_command(CLI::App& app);
void add_eig3_command(CLI::App& app);
void add_shapes_command(CLI::App& app);
void add_interpolate_command(CLI::App& app);
void add_view_command(CLI::App& app);
void add_decide_command(CLI::App& app);
void add_bench_command(CLI::App& app);
void add_prove_command(CLI::App& app);
void add_pair_command(CLI::App& app);
void add_blend_command(CLI::App& app);

}  // namespace affinterp::cli
