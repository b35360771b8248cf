#include "experiments/bench/history.hpp"

#include "experiments/bench/machine_label.hpp"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <optional>
#include <stdexcept>
#include <tuple>

namespace affinterp::bench {

namespace {

namespace fs = std::filesystem;

/// The machine as a benchmark file's context states it (experiments/apps/bench/bench_context.cpp adds the
/// affinterp_ keys; Google Benchmark the rest). Keys a file did not record are null.
nlohmann::json machine_of(const nlohmann::json& context) {
  const auto get = [&](const char* key) { return context.contains(key) ? context[key] : nlohmann::json(); };
  return {{"cpu", get("affinterp_cpu")},
          {"cpu_flags", get("affinterp_cpu_flags")},
          {"cores", get("num_cpus")},
          {"mhz_per_cpu", get("mhz_per_cpu")},
          {"host_name", get("host_name")},
          {"caches", get("caches")},
          {"compiler", get("affinterp_compiler")},
          {"flags", get("affinterp_flags")},
          {"eigen", get("affinterp_eigen")},
          {"os", get("affinterp_os")}};
}

nlohmann::json dates_of(const nlohmann::json& context) {
  if (context.contains("affinterp_process_dates")) return context["affinterp_process_dates"];
  return nlohmann::json::array({context.value("date", "")});
}

nlohmann::json interval_json(const std::optional<Interval>& ci) {
  return ci ? nlohmann::json{ci->lo, ci->hi} : nlohmann::json();
}

/// The words of `text` in lower case joined by '-', without trademark signs: "Intel(R) Xeon(R) Processor" →
/// "intel-xeon-processor".
std::string slug(const std::string& text) {
  std::string out, word;
  for (std::size_t i = 0; i <= text.size(); ++i) {
    if (i < text.size() && std::isalnum(static_cast<unsigned char>(text[i]))) {
      word += static_cast<char>(std::tolower(static_cast<unsigned char>(text[i])));
      continue;
    }
    if (!word.empty() && word != "r" && word != "tm") {
      if (!out.empty()) out += '-';
      out += word;
    }
    word.clear();
  }
  return out.empty() ? "unknown" : out;
}

}  // namespace

std::optional<RecordedRun> current_run(const fs::path& bench_dir, const std::string& note) {
  std::optional<RecordedRun> run;
  for (const Program& program : kSpeedPrograms) {
    const std::optional<BenchResults> results =
        read_bench_results(bench_dir / (std::string(program.name) + ".json"), std::string(program.counter));
    if (!results) continue;
    if (!run) {
      run.emplace();
      run->date = results->context.value("date", "");
      run->machine = machine_of(results->context);
      run->note = note;
      run->recorded = false;
    }
    const nlohmann::json dates = dates_of(results->context);
    run->programs[std::string(program.name)] = {{"processes", dates.size()}, {"dates", dates}};
    for (auto& [key, figure] : speed_figures(program, *results)) {
      for (const std::string& benchmark : figure_reads(key).benchmarks)
        if (const auto found = results->repetitions.find(benchmark); found != results->repetitions.end())
          run->repetitions[benchmark] = found->second;
      run->figures.emplace(key, std::move(figure));
    }
  }
  if (run) {  // <date>-<cpu>-<widest vector extension>
    run->id = run->date.substr(0, 10);
    run->id += '-';
    run->id += slug(machine_label(run->machine));
  }
  return run;
}

nlohmann::json to_json(const RecordedRun& run) {
  nlohmann::json figures = nlohmann::json::object();
  for (const auto& [key, figure] : run.figures)
    figures[key] = {{"program", figure.program},
                    {"unit", figure.unit},
                    {"value", figure.measured.value},
                    {"ci95", interval_json(figure.measured.ci95)},
                    {"repetitions", figure.measured.repetitions},
                    {"processes", figure.measured.processes}};
  return {{"date", run.date},         {"machine", run.machine}, {"note", run.note},
          {"programs", run.programs}, {"figures", figures},     {"repetitions", run.repetitions}};
}

RecordedRun run_from_json(const nlohmann::json& json, const std::string& id) {
  for (const char* key : {"date", "machine", "programs", "figures"})
    if (!json.is_object() || !json.contains(key)) throw std::runtime_error(std::string("no \"") + key + "\"");
  RecordedRun run;
  run.id = id;
  run.date = json["date"].get<std::string>();
  run.machine = json["machine"];
  run.note = json.value("note", "");
  run.programs = json["programs"];
  for (const auto& [key, f] : json["figures"].items()) {
    Measured m{f.at("value").get<double>(), std::nullopt, f.at("repetitions").get<std::size_t>(),
               f.value("processes", std::size_t{1})};
    if (f.at("ci95").is_array()) m.ci95 = Interval{f["ci95"][0].get<double>(), f["ci95"][1].get<double>()};
    run.figures[key] = {f.at("program").get<std::string>(), f.value("unit", ""), m};
  }
  if (json.contains("repetitions")) run.repetitions = json["repetitions"].get<std::map<std::string, ByProcess>>();
  return run;
}

std::vector<RecordedRun> read_history(const fs::path& history_dir) {
  std::vector<RecordedRun> runs;
  if (!fs::is_directory(history_dir)) return runs;
  for (const auto& file : fs::directory_iterator(history_dir)) {
    if (file.path().extension() != ".json") continue;
    std::ifstream in(file.path());
    const nlohmann::json json = nlohmann::json::parse(in, nullptr, /*allow_exceptions=*/false);
    try {
      if (json.is_discarded()) throw std::runtime_error("not JSON");
      runs.push_back(run_from_json(json, file.path().stem().string()));
    } catch (const std::exception& e) {
      throw std::runtime_error(file.path().string() + ": not a history entry (" + e.what() + ")");
    }
  }
  std::ranges::sort(
      runs, [](const RecordedRun& a, const RecordedRun& b) { return std::tie(a.date, a.id) < std::tie(b.date, b.id); });
  return runs;
}

std::vector<RecordedRun> runs_of(const fs::path& bench_dir) {
  std::vector<RecordedRun> runs = read_history(bench_dir / "history");
  if (std::optional<RecordedRun> current = current_run(bench_dir))
    if (std::ranges::none_of(runs, [&](const RecordedRun& r) { return r.programs == current->programs; }))
      runs.push_back(std::move(*current));
  return runs;
}

fs::path record(const RecordedRun& run, const fs::path& history_dir) {
  for (const RecordedRun& old : read_history(history_dir))
    if (old.programs == run.programs) return history_dir / (old.id + ".json");
  fs::create_directories(history_dir);
  fs::path file = history_dir / (run.id + ".json");
  for (int n = 2; fs::exists(file); ++n) file = history_dir / (run.id + "-" + std::to_string(n) + ".json");
  const fs::path temporary = file.string() + ".tmp";
  {
    std::ofstream out(temporary);
    out << to_json(run).dump(2) << "\n";
    if (!out) throw std::runtime_error("cannot write " + temporary.string());
  }
  fs::rename(temporary, file);
  return file;
}

}  // namespace affinterp::bench
