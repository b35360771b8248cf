// `affinterp report`: render REPORT.md and the claims' pages again from claims.json, without rerunning any check.
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
  const fs::path out = options.out.empty() ? fs::absolute(options.in).parent_path() : fs::path(options.out);
  report::Pages pages;
  try {
    pages = report::render(document);
  } catch (const std::exception& e) {
    throw CommandFailed(options.in + " is not a claims.json document: " + e.what(), 1);
  }
  try {
    fs::create_directories(out);
    report::write_pages(pages, out);
  } catch (const std::exception& e) {
    throw CommandFailed(std::string("cannot write the report: ") + e.what(), 1);
  }
  std::cerr << "wrote " << (out / "REPORT.md").string() << " and " << pages.claims.size() << " pages in "
            << (out / "claims").string() << "\n";
}

}  // namespace

void add_report_command(CLI::App& app) {
  auto options = std::make_shared<ReportOptions>();
  CLI::App* cmd =
      app.add_subcommand("report", "Render REPORT.md and claims/ from an existing claims.json (no checks run).");
  cmd->add_option("--in", options->in, "The claims.json to render")->capture_default_str();
  cmd->add_option("--out", options->out, "Folder for REPORT.md and claims/ (default: the folder of --in)");
  cmd->callback([options] { run(*options); });
}

}  // namespace affinterp::cli
