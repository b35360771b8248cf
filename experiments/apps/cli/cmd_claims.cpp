// `affinterp claims`: run the checks, write claims.json, REPORT.md and a page per claim (claims/).
#include "experiments/apps/cli/command.hpp"
#include "experiments/bench/history.hpp"
#include "experiments/claims/claims_json.hpp"
#include "experiments/claims/registry.hpp"
#include "experiments/claims/runner.hpp"
#include "experiments/measurements/engine3_quality.hpp"
#include "experiments/measurements/engine3_scale.hpp"
#include "experiments/measurements/engine3_speed.hpp"
#include "experiments/measurements/engine_cli.hpp"
#include "experiments/measurements/engine_scale.hpp"
#include "experiments/measurements/engine_speed.hpp"
#include "experiments/support/environment.hpp"
#include "experiments/support/staged_output.hpp"
#include "reports/generator/report.hpp"

#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <thread>

namespace affinterp::cli {

namespace {

namespace fs = std::filesystem;
using namespace affinterp::claims;

struct ClaimsOptions {
  std::vector<std::string> only;
  bool list = false;
  std::uint64_t seed = 2012;
  std::string size = "full";
  unsigned threads = std::max(1u, std::thread::hardware_concurrency());
  std::string out = AFFINTERP_SOURCE_DIR "/reports";
  std::string bench_dir;
  bool figures = true;
};

void list_claims(const ClaimRegistry& registry) {
  for (const Claim& claim : registry.claims())
    std::cout << claim.id << "\t" << (claim.check ? "implemented" : "pending") << "\t" << claim.where << "\t"
              << claim.statement << "\n";
}

nlohmann::json read_previous(const fs::path& file) {
  std::ifstream in(file);
  if (!in) return nlohmann::json::object();
  return nlohmann::json::parse(in, nullptr, /*allow_exceptions=*/false);
}

void write_file(const fs::path& file, const std::string& text) {
  std::ofstream out(file);
  out << text;
  if (!out) throw CommandFailed("cannot write " + file.string(), 1);
}

/// A measurement's record as claims.json holds it (null: not measured).
template <class Record>
nlohmann::json record_json(const std::optional<Record>& record) {
  return record ? nlohmann::json(*record) : nlohmann::json();
}

/// The global engine's speed (the latest run, and every recorded run) and scale, the 3D engine's speed and its
/// frames against baselines, from the benchmark folder.
EngineTables engine_tables(const RunContext& context) {
  using namespace affinterp::measurements;
  try {
    std::optional<EngineSpeed> speed = engine_speed(context.bench_dir / "bench_interp.json");
    if (speed) speed->history = engine_speed_history(bench::runs_of(context.bench_dir));
    std::optional<Engine3Quality> quality3 = read_engine3_quality(context.bench_dir / "quality_3d.json");
    if (quality3 && quality3->closeup && context.draws_figures())
      quality3->figures = draw_engine3_closeup(context, *quality3->closeup);
    return {record_json(speed),
            record_json(engine_scale(context.bench_dir / "bench_scale.json", context)),
            record_json(engine_cli(context.bench_dir / "bench_cli_scale.json")),
            record_json(engine3_speed(context.bench_dir / "bench_3d.json")),
            record_json(engine3_scale(context.bench_dir / "bench_3d_scale.json")),
            record_json(quality3)};
  } catch (const std::runtime_error& e) {
    throw CommandFailed(std::string("benchmark outputs: ") + e.what(), 1);
  }
}

void run(const ClaimsOptions& options) {
  const ClaimRegistry& registry = registered_claims();
  if (options.list) return list_claims(registry);

  RunContext context;
  context.seed = options.seed;
  context.size = options.size == "quick" ? Size::quick : Size::full;
  context.threads = options.threads;
  context.bench_dir = options.bench_dir.empty() ? fs::path(options.out) / "bench" : fs::path(options.bench_dir);

  StagedOutput staged(options.out);
  if (options.figures) {
    context.figure_dir = staged.staging() / "figures";
    fs::create_directories(context.figure_dir);
  }
  // The proofs' sentence files and the deciders' outputs, to rerun with the tools alone.
  context.proof_dir = staged.staging() / "proofs";
  std::vector<ClaimResult> results;
  try {
    results = run_claims(registry, context, options.only, std::cerr);
  } catch (const std::invalid_argument& e) {
    throw CommandFailed(e.what(), usage_error);
  }
  std::size_t failed = 0;
  std::map<std::string, int> counts;
  for (const auto& r : results) {
    failed += !r.error.empty();
    ++counts[std::string(to_string(r.outcome.verdict))];
  }
  if (failed > 0)
    throw CommandFailed(std::to_string(failed) + " check(s) failed to run; " + options.out + " left unchanged", 1);

  const fs::path previous_file = fs::path(options.out) / "claims.json";
  const nlohmann::json document = claims_document(registry, results, context, environment_description(),
                                                  read_previous(previous_file), engine_tables(context));
  const report::Pages pages = report::render(document);
  write_file(staged.staging() / "claims.json", document.dump(2) + "\n");
  staged.commit();
  report::write_pages(pages, options.out);

  std::cerr << "wrote " << previous_file.string() << ", REPORT.md and claims/:";
  for (const auto& [verdict, n] : counts) std::cerr << " " << verdict << " " << n << ";";
  std::cerr << "\n";
}

}  // namespace

void add_claims_command(CLI::App& app) {
  auto options = std::make_shared<ClaimsOptions>();
  CLI::App* cmd =
      app.add_subcommand("claims", "Run the checks that decide the papers' claims; write claims.json and the report.");
  cmd->add_option("--only", options->only, "Run only these claim IDs (others keep their earlier entries)");
  cmd->add_flag("--list", options->list, "List the claim IDs and whether each has a check, then exit");
  cmd->add_option("--seed", options->seed, "Seed of every random sample")->capture_default_str();
  cmd->add_option("--size", options->size, "Sweep size: quick (CI) or full (the report's)")
      ->check(CLI::IsMember({"quick", "full"}))
      ->capture_default_str();
  cmd->add_option("--threads", options->threads, "Worker threads for sweeps")
      ->check(CLI::Range(1u, 256u))
      ->capture_default_str();
  cmd->add_option("--out", options->out, "Folder for claims.json, REPORT.md, claims/, figures/ and proofs/")
      ->capture_default_str();
  cmd->add_option("--bench-dir", options->bench_dir,
                  "Folder of Google Benchmark JSON outputs for the speed claims (default: OUT/bench)");
  cmd->add_flag("!--no-figures", options->figures, "Do not draw figures");
  cmd->callback([options] { run(*options); });
}

}  // namespace affinterp::cli
