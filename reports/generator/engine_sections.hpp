#pragma once
// The global engine's sections of the summary page, from the typed records of experiments/measurements/: its speed
// on the octopus against its targets (one run, and every recorded run), its cost from 1k to 1M triangles against
// the 1M targets, and a frame through the CLI against the engine's; each names the run it was measured on.
#include "experiments/measurements/engine_cli.hpp"
#include "experiments/measurements/engine_scale.hpp"
#include "experiments/measurements/engine_speed.hpp"

#include <optional>
#include <sstream>

namespace affinterp::report {

void write_engine_speed(std::ostringstream& md, const std::optional<measurements::EngineSpeed>& speed);
void write_engine_scale(std::ostringstream& md, const std::optional<measurements::EngineScale>& scale);
void write_engine_cli(std::ostringstream& md, const std::optional<measurements::EngineCli>& cli);

/// "measured on <machine>, <date>" of a record's benchmark run.
std::string measured_on(const measurements::BenchRun& run);

/// A speed verdict as a table cell: yes (reproduced: met), **no** (not-reproduced), undecided, or — when none.
std::string met_cell(const std::optional<measurements::Verdict>& verdict);

}  // namespace affinterp::report
