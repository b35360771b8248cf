#pragma once
// One benchmark file from several whole processes of the same benchmark program: run in interleaved
// order with the other programs (A B A B ...), so that slow phases of a shared machine fall into the spread
// between processes, which the bootstrap then covers (bootstrap.hpp), instead of into one run's verdict.
#include <nlohmann/json.hpp>

#include <filesystem>
#include <vector>

namespace affinterp::bench {

/// The Google Benchmark JSON of `processes` (outputs of one program, in run order) as one document: the first
/// file's context with "affinterp_processes" (their count) and "affinterp_process_dates" (each one's "date"),
/// and every repetition of every file tagged with "affinterp_process" (its index, from 0); the per-process
/// aggregates are dropped (read_bench_results recomputes the medians), errors kept. Throws std::runtime_error
/// naming the file when one is absent or not a Google Benchmark output.
nlohmann::json merge_processes(const std::vector<std::filesystem::path>& processes);

}  // namespace affinterp::bench
