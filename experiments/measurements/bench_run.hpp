#pragma once
// What every measurement record of the engine shares: the benchmark run it was read from (its file, when it
// started and on what machine, so that the report can say "measured on <machine>, <date>" of a run older than
// the main job's), and the JSON of its optional parts: a number that may not have been measured (null), an
// interval [lo, hi] (a 95% bootstrap interval, or the least and the largest of a benchmark's runs) and a verdict.
#include "experiments/bench/bench_results.hpp"
#include "experiments/bench/measured.hpp"
#include "experiments/claims/verdict.hpp"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>

namespace affinterp::measurements {

using bench::Interval;
using claims::Verdict;

/// The benchmark run a record was measured on.
struct BenchRun {
  std::string file;      ///< the benchmark JSON's file name (reports/bench/)
  std::string date;      ///< when its first process started: the file's context "date" (ISO 8601)
  std::string machine;   ///< the CPU and its widest vector extension (bench/machine_label.hpp)
  std::string compiler;  ///< the compiler and the flags the benchmark was built with
  std::string flags;
};

/// The run `results` was read from.
BenchRun bench_run(const bench::BenchResults& results);

/// A record's run as the flat keys "file", "date", "machine", "compiler", "flags" of `record`, and back.
void write_run(nlohmann::json& record, const BenchRun& run);
BenchRun read_run(const nlohmann::json& record);

/// A number, or null when it was not measured.
nlohmann::json optional_json(const std::optional<double>& x);
std::optional<double> optional_number(const nlohmann::json& x);

/// An interval as [lo, hi], or null.
nlohmann::json interval_json(const std::optional<Interval>& x);
std::optional<Interval> optional_interval(const nlohmann::json& x);

/// A verdict as its name (verdict.hpp), or null; reading an unknown name throws std::runtime_error.
nlohmann::json verdict_json(const std::optional<Verdict>& v);
std::optional<Verdict> optional_verdict(const nlohmann::json& x);
Verdict verdict_from(const nlohmann::json& x);

}  // namespace affinterp::measurements
