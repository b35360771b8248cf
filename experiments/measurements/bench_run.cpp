#include "experiments/measurements/bench_run.hpp"

#include <stdexcept>

namespace affinterp::measurements {

BenchRun bench_run(const bench::BenchResults& results) {
  return {results.file.filename().string(), results.context.value("date", ""), results.machine, results.compiler,
          results.flags};
}

void write_run(nlohmann::json& record, const BenchRun& run) {
  record["file"] = run.file;
  record["date"] = run.date;
  record["machine"] = run.machine;
  record["compiler"] = run.compiler;
  record["flags"] = run.flags;
}

BenchRun read_run(const nlohmann::json& record) {
  return {record.value("file", ""), record.value("date", ""), record.value("machine", ""), record.value("compiler", ""),
          record.value("flags", "")};
}

nlohmann::json optional_json(const std::optional<double>& x) { return x ? nlohmann::json(*x) : nlohmann::json(); }

std::optional<double> optional_number(const nlohmann::json& x) {
  return x.is_number() ? std::optional(x.get<double>()) : std::nullopt;
}

nlohmann::json interval_json(const std::optional<Interval>& x) {
  return x ? nlohmann::json{x->lo, x->hi} : nlohmann::json();
}

std::optional<Interval> optional_interval(const nlohmann::json& x) {
  if (!x.is_array() || x.size() != 2) return std::nullopt;
  return Interval{x[0].get<double>(), x[1].get<double>()};
}

nlohmann::json verdict_json(const std::optional<Verdict>& v) {
  return v ? nlohmann::json(std::string(claims::to_string(*v))) : nlohmann::json();
}

std::optional<Verdict> optional_verdict(const nlohmann::json& x) {
  if (!x.is_string()) return std::nullopt;
  return verdict_from(x);
}

Verdict verdict_from(const nlohmann::json& x) {
  const std::optional<Verdict> v = x.is_string() ? claims::parse_verdict(x.get<std::string>()) : std::nullopt;
  if (!v) throw std::runtime_error("not a verdict: " + x.dump());
  return *v;
}

}  // namespace affinterp::measurements
