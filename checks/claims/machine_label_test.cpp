// The machine's name in the speed tables (experiments/bench/machine_label.hpp): the CPU's model with its widest
// vector extension, so that a Zen 3 and a Zen 4 that both call themselves "AMD EPYC" are two machines.
#include "experiments/bench/machine_label.hpp"

#include <gtest/gtest.h>

namespace affinterp::bench::machine_label_test {
namespace {

TEST(MachineLabel, NamesTheWidestVectorExtensionAmongTheFlags) {
  EXPECT_EQ(widest_vector_isa("fpu sse2 avx fma avx2 bmi2 avx512f avx512vl"), "avx512f");
  EXPECT_EQ(widest_vector_isa("fpu sse2 sse4_2 avx fma avx2 bmi2"), "avx2");
  EXPECT_EQ(widest_vector_isa("avx"), "avx");
  EXPECT_EQ(widest_vector_isa("sse2 sse4_1 sse4_2"), "sse4_2");
  EXPECT_EQ(widest_vector_isa("sse2"), "no AVX");
  EXPECT_EQ(widest_vector_isa("sse2 avx512_bf16 avx2"), "avx2") << "whole flags only: avx512_bf16 is not avx512f";
}

TEST(MachineLabel, JoinsTheModelAndItsVectorExtension) {
  EXPECT_EQ(machine_label("AMD EPYC", "fpu avx avx2 avx512f"), "AMD EPYC, avx512f");
  EXPECT_EQ(machine_label("AMD EPYC", "fpu avx avx2"), "AMD EPYC, avx2");
  EXPECT_EQ(machine_label("AMD EPYC", nullptr), "AMD EPYC") << "an older file without the flags";
  EXPECT_EQ(machine_label(nullptr, nullptr), "unknown (run a current bench executable)");
  EXPECT_EQ(machine_label(nlohmann::json{{"cpu", "AMD EPYC"}, {"cpu_flags", "avx avx2"}, {"cores", 2}}),
            "AMD EPYC, avx2")
      << "a recorded run's machine";
}

}  // namespace
}  // namespace affinterp::bench::machine_label_test
