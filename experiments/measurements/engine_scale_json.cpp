// engine_scale.hpp's record as claims.json holds it, and back: one key table (engine_scale_fields.hpp).
#include "experiments/measurements/engine_scale.hpp"
#include "experiments/measurements/engine_scale_fields.hpp"

#include <utility>

namespace affinterp::measurements {
namespace {

using nlohmann::json;

template <class Row, class Field, std::size_t N>
json row_json(const Row& row, const std::array<Field, N>& fields) {
  json out{{"triangles", row.triangles}};
  for (const Field& f : fields) {
    const Cost& cost = row.*f.cost;
    out[f.value_key] = optional_json(cost.value);
    if (f.cpu_key) out[f.cpu_key] = optional_json(cost.cpu_ms);
    if (f.runs_key) out[f.runs_key] = interval_json(cost.runs);
  }
  return out;
}

template <class Row, class Field, std::size_t N>
Row row_from(const json& j, const std::array<Field, N>& fields) {
  Row row;
  row.triangles = j.at("triangles");
  for (const Field& f : fields) {
    Cost& cost = row.*f.cost;
    cost.value = optional_number(j.value(f.value_key, json()));
    if (f.cpu_key) cost.cpu_ms = optional_number(j.value(f.cpu_key, json()));
    if (f.runs_key) cost.runs = optional_interval(j.value(f.runs_key, json()));
  }
  return row;
}

template <class Exponents, class Field, std::size_t N>
json exponents_json(const Exponents& exponents, const std::array<Field, N>& fields) {
  json out = json::object();
  for (const Field& f : fields)
    if (f.exponent) out[f.value_key] = optional_json(exponents.*f.exponent);
  return out;
}

template <class Exponents, class Field, std::size_t N>
Exponents exponents_from(const json& j, const std::array<Field, N>& fields) {
  Exponents exponents;
  for (const Field& f : fields)
    if (f.exponent) exponents.*f.exponent = optional_number(j.value(f.value_key, json()));
  return exponents;
}

json back_end_json(const BackEnd& b) {
  json rows = json::array();
  for (const BackEndRow& row : b.rows) rows.push_back(row_json(row, back_end_fields));
  return {{"name", b.name}, {"rows", rows}, {"exponents", exponents_json(b.exponents, back_end_fields)}};
}

BackEnd back_end_from(const json& j) {
  BackEnd b{j.at("name"), {}, exponents_from<BackEndExponents>(j.at("exponents"), back_end_fields)};
  for (const auto& row : j.at("rows")) b.rows.push_back(row_from<BackEndRow>(row, back_end_fields));
  return b;
}

json targets_json(const ScaleTargets& t) {
  return {{"triangles", t.triangles},   {"setup_ms", t.setup_ms}, {"frame_F_ms", t.frame_F_ms},
          {"batch_R_ms", t.batch_R_ms}, {"peak_MB", t.peak_MB},   {"growth_R", t.growth_R}};
}

ScaleTargets targets_from(const json& j) {
  return {j.at("triangles"),  j.at("setup_ms"), j.at("frame_F_ms"),
          j.at("batch_R_ms"), j.at("peak_MB"),  j.at("growth_R")};
}

json target_verdict_json(const TargetVerdict& v) {
  return {{"target", v.target},
          {"limit", v.limit},
          {"measured", optional_json(v.measured)},
          {"range", interval_json(v.range)},
          {"verdict", claims::to_string(v.verdict)},
          {"cause", v.cause ? json(*v.cause) : json()}};
}

TargetVerdict target_verdict_from(const json& j) {
  const json cause = j.value("cause", json());
  return {j.at("target"),
          j.at("limit"),
          optional_number(j.at("measured")),
          optional_interval(j.value("range", json())),
          verdict_from(j.at("verdict")),
          cause.is_string() ? std::optional(cause.get<std::string>()) : std::nullopt};
}

}  // namespace

void to_json(json& out, const EngineScale& s) {
  out = {{"blas", s.blas},
         {"cholmod_from_unknowns", s.cholmod_from_unknowns ? json{{"real", s.cholmod_from_unknowns->real},
                                                                  {"complex", s.cholmod_from_unknowns->complex}}
                                                           : json()},
         {"rows", json::array()},
         {"exponents", exponents_json(s.exponents, engine_fields)},
         {"exponents_from_triangles", s.exponents_from_triangles},
         {"growth_R", optional_json(s.growth_R)},
         {"back_ends", json::array()},
         {"targets", targets_json(s.targets)},
         {"verdict", verdict_json(s.verdict)},
         {"target_verdicts", json::array()},
         {"figures", s.figures}};
  write_run(out, s.run);
  for (const ScaleRow& row : s.rows) out["rows"].push_back(row_json(row, engine_fields));
  for (const BackEnd& b : s.back_ends) out["back_ends"].push_back(back_end_json(b));
  for (const TargetVerdict& v : s.target_verdicts) out["target_verdicts"].push_back(target_verdict_json(v));
}

void from_json(const json& j, EngineScale& s) {
  s = EngineScale{};
  s.run = read_run(j);
  s.blas = j.value("blas", "unknown");
  if (const json c = j.value("cholmod_from_unknowns", json()); c.is_object())
    s.cholmod_from_unknowns = CholmodSwitch{c.at("real"), c.at("complex")};
  for (const auto& row : j.at("rows")) s.rows.push_back(row_from<ScaleRow>(row, engine_fields));
  s.exponents = exponents_from<ScaleExponents>(j.at("exponents"), engine_fields);
  s.exponents_from_triangles = j.at("exponents_from_triangles");
  s.growth_R = optional_number(j.value("growth_R", json()));
  for (const auto& b : j.at("back_ends")) s.back_ends.push_back(back_end_from(b));
  s.targets = targets_from(j.at("targets"));
  s.verdict = optional_verdict(j.value("verdict", json()));
  for (const auto& v : j.value("target_verdicts", json::array())) s.target_verdicts.push_back(target_verdict_from(v));
  s.figures = j.value("figures", std::vector<std::string>{});
}

}  // namespace affinterp::measurements
