// `affinterp report`: render REPORT.md again from claims.json, without rerunning any check.
#include "experiments/apps/cli/command.hpp"
#include "reports/generator/report.hpp"

#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>

namespace affinterp::cli {

namespace {

namespace fs = std::filesystem;

struct ReportOptions {
  std::string in = AFFINTERP_SOURCE_DIR "/reports/claims.json";
  std::string out;
};

void run(const ReportOptions& options) {
  std::ifstream in(options.in);
  if (!in) throw CommandFailed("cannot read " + options.in, 1);
  const nlohmann::json document = nlohmann::json::parse(in, nullptr, /*allow_exceptions=*/false);
  if (document.is_discarded() || !document.contains("claims"))
    throw CommandFailed(options.in + " is not a claims.json document", 1);
  const fs::path out = options.out.empty() ? fs::path(options.in).parent_path() / "REPORT.md" : fs::path(options.out);
  const fs::path temporary = fs::path(out.string() + ".tmp");
  {
    std::ofstream file(temporary);
    file << report::render_markdown(document);
    if (!file) throw CommandFailed("cannot write " + temporary.string(), 1);
  }
  fs::rename(temporary, out);
  std::cerr << "wrote " << out.string() << "\n";
}

}  // namespace

void add_report_command(CLI::App& app) {
  auto options = std::make_shared<ReportOptions>();
  CLI::App* cmd = app.add_subcommand("report", "Render REPORT.md from an existing claims.json (no checks run).");
  cmd->add_option("--in", options->in, "The claims.json to render")->capture_default_str();
  cmd->add_option("--out", options->out, "Where to write the report (default: REPORT.md beside --in)");
  cmd->callback([options] { run(*options); });
}

}  // namespace affinterp::cli
