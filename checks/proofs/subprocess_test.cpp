// The limits deciders run under: a CPU-time limit, a wall-clock limit that ends the whole process group, a
// missing program.
#include "experiments/proofs/subprocess.hpp"

#include <gtest/gtest.h>

namespace subprocess_test {

using namespace affinterp::proofs;

TEST(RunProcess, CapturesOutputAndStatus) {
  const ProcessResult r = run_process({"sh", "-c", "echo out; echo err >&2; exit 3"}, {}, {});
  EXPECT_EQ(r.output, "out\nerr\n");
  EXPECT_EQ(r.exit_status, 3);
  EXPECT_FALSE(r.timed_out);
}

TEST(RunProcess, WallLimitKillsTheProcessGroup) {
  // The child starts a grandchild that would outlive it; both end at the limit.
  const ProcessResult r = run_process({"sh", "-c", "sleep 30 & sleep 30; echo never"}, {}, {.wall_seconds = 0.5});
  EXPECT_TRUE(r.timed_out);
  EXPECT_LT(r.seconds, 5);
  EXPECT_EQ(r.output.find("never"), std::string::npos);
}

TEST(RunProcess, CpuLimitEndsABusyDeciderWhateverTheWallClockAllows) {
  const ProcessResult r = run_process({"sh", "-c", "while :; do :; done"}, {}, {.wall_seconds = 120, .cpu_seconds = 1});
  EXPECT_TRUE(r.timed_out);
  EXPECT_LT(r.seconds, 60);
}

TEST(RunProcess, CpuLimitSparesAnIdleWait) {
  const ProcessResult r = run_process({"sh", "-c", "sleep 2; echo done"}, {}, {.wall_seconds = 30, .cpu_seconds = 1});
  EXPECT_FALSE(r.timed_out);
  EXPECT_EQ(r.output, "done\n");
}

TEST(RunProcess, MissingProgram) {
  const ProcessResult r = run_process({"affinterp-no-such-decider"}, {}, {});
  EXPECT_TRUE(r.not_found);
}

}  // namespace subprocess_test
