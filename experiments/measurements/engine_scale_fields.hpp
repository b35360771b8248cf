#pragma once
// The costs of engine_scale.hpp's rows by name: the keys claims.json writes each under and where its median and
// its fitted exponent live in the record, so that the measurement, the JSON and the figure name a cost once.
#include "experiments/measurements/engine_scale.hpp"

#include <array>

namespace affinterp::measurements {

template <class Row, class Exponents>
struct CostField {
  const char* value_key;  ///< the median's key; also the exponent's
  const char* cpu_key;    ///< the calling thread's CPU time's key; null: not recorded
  const char* runs_key;   ///< the runs' spread's key; null: not recorded
  Cost Row::*cost;
  std::optional<double> Exponents::*exponent;  ///< null: no exponent fitted
};

using EngineField = CostField<ScaleRow, ScaleExponents>;
using BackEndField = CostField<BackEndRow, BackEndExponents>;

inline constexpr std::array<EngineField, 7> engine_fields{{
    {"setup_F_ms", "setup_F_cpu_ms", "setup_F_range", &ScaleRow::setup_F, &ScaleExponents::setup_F},
    {"setup_R_ms", "setup_R_cpu_ms", "setup_R_range", &ScaleRow::setup_R, &ScaleExponents::setup_R},
    {"frame_F_ms", "frame_F_cpu_ms", "frame_F_range", &ScaleRow::frame_F, &ScaleExponents::frame_F},
    {"frame_R_ms", "frame_R_cpu_ms", "frame_R_range", &ScaleRow::frame_R, &ScaleExponents::frame_R},
    {"batch_F_ms", nullptr, "batch_F_range", &ScaleRow::batch_F, nullptr},
    {"batch_R_ms", nullptr, "batch_R_range", &ScaleRow::batch_R, &ScaleExponents::batch_R},
    {"peak_MB", nullptr, "peak_MB_range", &ScaleRow::peak_MB, &ScaleExponents::peak_MB},
}};

inline constexpr std::array<BackEndField, 8> back_end_fields{{
    {"setup_F_ms", "setup_F_cpu_ms", nullptr, &BackEndRow::setup_F, &BackEndExponents::setup_F},
    {"setup_R_ms", "setup_R_cpu_ms", nullptr, &BackEndRow::setup_R, &BackEndExponents::setup_R},
    {"frame_F_ms", "frame_F_cpu_ms", nullptr, &BackEndRow::frame_F, &BackEndExponents::frame_F},
    {"frame_R_ms", "frame_R_cpu_ms", nullptr, &BackEndRow::frame_R, &BackEndExponents::frame_R},
    {"factor_F_ms", "factor_F_cpu_ms", nullptr, &BackEndRow::factor_F, &BackEndExponents::factor_F},
    {"factor_R_ms", "factor_R_cpu_ms", nullptr, &BackEndRow::factor_R, &BackEndExponents::factor_R},
    {"solve_F_ms", "solve_F_cpu_ms", nullptr, &BackEndRow::solve_F, &BackEndExponents::solve_F},
    {"solve_R_ms", "solve_R_cpu_ms", nullptr, &BackEndRow::solve_R, &BackEndExponents::solve_R},
}};

}  // namespace affinterp::measurements
