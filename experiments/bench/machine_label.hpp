#pragma once
// The machine a benchmark ran on, named so that two machines a table mixes up can be told apart: virtual
// machines often report a bare "AMD EPYC" for Zen 3 (AVX2) and Zen 4 (AVX-512) alike, whose speeds differ
// markedly on the same binary, so the name carries the widest vector extension among the CPU's flags.
#include <nlohmann/json.hpp>

#include <string>

namespace affinterp::bench {

/// The widest vector extension among `flags` (/proc/cpuinfo's list, space-separated): "avx512f", "avx2", "avx",
/// "sse4_2" or "no AVX".
std::string widest_vector_isa(const std::string& flags);

/// "<cpu>, <widest vector extension>" from the CPU's model name and flags as a benchmark file's context records
/// them (affinterp_cpu, affinterp_cpu_flags; experiments/apps/bench/bench_context.cpp), or "<cpu>" alone where
/// the flags were not recorded (null).
std::string machine_label(const nlohmann::json& cpu, const nlohmann::json& flags);
/// machine_label of a recorded run's machine (history.hpp's RecordedRun::machine: "cpu", "cpu_flags").
std::string machine_label(const nlohmann::json& machine);

/// The key runs are pooled by (speed_verdict.hpp): runs with one key are one machine. "<cpu>, <widest vector
/// extension>, <compiler> <build flags>" from a recorded run's machine ("cpu", "cpu_flags", "compiler", "flags"):
/// the same model can come with another vector extension (a VM's bare "AMD EPYC"), and another compiler or version
/// moves speed ratios as much as another CPU, and so do the build's flags (warnings left out): -ffp-contract=off
/// alone moved bench_exp3's eigen-qr ÷ viete on one AVX-512 machine across thesis.eig.speedup's band. A part not
/// recorded reads "<part> not recorded".
std::string machine_key(const nlohmann::json& machine);
/// The build flags' part of machine_key: " <flag> <flag> …" (each space-separated word of "flags" but those starting
/// with -W), or ", build flags not recorded".
std::string build_options(const nlohmann::json& machine);

}  // namespace affinterp::bench
