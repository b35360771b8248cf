// The engine's records in the committed claims.json read back through their from_json and written again to the
// same JSON (one pair of functions writes and reads each), and the report naming the run each was measured on.
#include "experiments/measurements/engine_cli.hpp"
#include "experiments/measurements/engine_scale.hpp"
#include "experiments/measurements/engine_speed.hpp"
#include "reports/generator/report.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <string>

namespace affinterp::measurements::records_test {
namespace {

nlohmann::json committed_claims() {
  std::ifstream in(AFFINTERP_SOURCE_DIR "/reports/claims.json");
  return nlohmann::json::parse(in);
}

template <class Record>
void expect_read_back_as_written(const nlohmann::json& written) {
  ASSERT_TRUE(written.is_object());
  EXPECT_EQ(nlohmann::json(written.get<Record>()), written);
}

TEST(Records, TheCommittedOnesReadBackAsWritten) {
  const nlohmann::json doc = committed_claims();
  expect_read_back_as_written<EngineSpeed>(doc["engine_speed"]);
  expect_read_back_as_written<EngineScale>(doc["engine_scale"]);
  expect_read_back_as_written<EngineCli>(doc["engine_cli"]);
}

TEST(Records, TheReportSaysWhichRunEachWasMeasuredOn) {
  nlohmann::json doc = {{"claims", nlohmann::json::array()}, {"environment", nlohmann::json::object()}};
  EngineScale scale;
  scale.run = {"bench_scale.json", "2026-02-01T10:00:00+00:00", "test cpu, avx2", "g++", "-O3"};
  EngineCli cli;
  cli.run = {"bench_cli_scale.json", "2026-02-02T11:00:00+00:00", "other cpu, avx512f", "g++", "-O3"};
  doc["engine_scale"] = scale;
  doc["engine_cli"] = cli;
  const std::string md = report::render(doc).summary;
  EXPECT_NE(md.find("`build/bin/bench_scale`, measured on test cpu, avx2, 2026-02-01 10:00:00+00:00"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("`build/bin/bench_cli_scale`, measured on other cpu, avx512f, 2026-02-02 11:00:00+00:00"),
            std::string::npos)
      << md;
}

}  // namespace
}  // namespace affinterp::measurements::records_test
