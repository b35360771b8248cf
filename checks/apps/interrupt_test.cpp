// Interrupted runs leave nothing behind: `affinterp interpolate --out OUT` and `affinterp claims --out R`,
// killed by SIGTERM or SIGINT in the middle (once their staging folder holds files), end by that signal,
// leave no `.OUT.staging-PID` folder and OUT's earlier files as they were; `affinterp prove` killed leaves no
// decider running; and a staging folder that a process no longer running left behind is removed by the next run,
// while a live process's is kept.
#include "checks/apps/cli_harness.hpp"

#include <gtest/gtest.h>

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace {

namespace fs = std::filesystem;
using affinterp::checks::read_text;
using affinterp::checks::run_cli;
using affinterp::checks::write_text;

fs::path scratch(const std::string& name) {
  return affinterp::checks::scratch_folder("affinterp_interrupt_test", name);
}

/// Starts `affinterp ARGS...` with its output discarded; returns its process id.
pid_t start(const std::vector<std::string>& args) {
  const pid_t pid = fork();
  if (pid == 0) {
    // As a shell starts a foreground job: with the default actions even where this test inherited SIGINT
    // ignored (an asynchronous job of a non-interactive shell, say).
    for (const int signal : {SIGINT, SIGTERM}) std::signal(signal, SIG_DFL);
    const int null = open("/dev/null", O_WRONLY);
    dup2(null, 1), dup2(null, 2);
    std::vector<char*> argv{const_cast<char*>(AFFINTERP_CLI)};
    for (const auto& arg : args) argv.push_back(const_cast<char*>(arg.c_str()));
    argv.push_back(nullptr);
    execv(AFFINTERP_CLI, argv.data());
    _exit(127);
  }
  return pid;
}

/// Waits (at most a minute) until `ready` holds or `pid` has ended; true when `ready` held.
template <class Ready>
bool wait_until(pid_t pid, Ready ready) {
  for (int tries = 0; tries < 6000; ++tries) {
    if (ready()) return true;
    if (waitpid(pid, nullptr, WNOHANG) != 0) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return false;
}

/// The files beside OUT (in its parent folder) other than OUT itself.
std::vector<std::string> beside(const fs::path& out) {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(out.parent_path()))
    if (entry.path() != out) names.push_back(entry.path().filename().string());
  return names;
}

/// Kills `pid` with `signal` `delay` after its staging folder for `out` holds `file` (relative), then
/// checks the process ended by that signal, no staging folder is left and OUT's earlier `files` are as
/// they were.
void interrupt_when_staged(pid_t pid, int signal, const fs::path& out, const fs::path& file,
                           const std::vector<std::pair<std::string, std::string>>& files,
                           std::chrono::milliseconds delay = std::chrono::milliseconds(0)) {
  std::string name = out.filename().string();  // built by appending: GCC 12 misreports "." + s
  name.insert(name.begin(), '.');
  const fs::path staging = out.parent_path() / (name + ".staging-" + std::to_string(pid));
  ASSERT_TRUE(wait_until(pid, [&] { return fs::exists(staging / file); })) << "the run ended before staging " << file;
  std::this_thread::sleep_for(delay);
  ASSERT_EQ(kill(pid, signal), 0);
  int status = 0;
  pid_t ended = 0;
  for (int tries = 0; tries < 3000 && (ended = waitpid(pid, &status, WNOHANG)) == 0; ++tries)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  if (ended == 0) {
    kill(pid, SIGKILL), waitpid(pid, nullptr, 0);
    FAIL() << "still running 30 s after the signal";
  }
  EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == signal)
      << "ended by "
      << (WIFSIGNALED(status) ? "signal " + std::to_string(WTERMSIG(status))
                              : "exit " + std::to_string(WEXITSTATUS(status)));
  EXPECT_TRUE(beside(out).empty()) << "left beside OUT: " << ::testing::PrintToString(beside(out));
  for (const auto& [name, text] : files) EXPECT_EQ(read_text(out / name), text) << name;
}

/// A long interpolate run (many frames of a generated shape) into `out`, which holds earlier files.
std::vector<std::string> long_interpolation(const fs::path& folder, const fs::path& out) {
  EXPECT_EQ(run_cli("shapes worm-curl --out " + folder.string()).status, 0);
  return {"interpolate",
          "--source",
          (folder / "source.obj").string(),
          "--target",
          (folder / "target.obj").string(),
          "--frames",
          "100000",
          "--no-figures",
          "--out",
          out.string()};
}

const std::vector<std::pair<std::string, std::string>> earlier{{"frame_0000.obj", "earlier\n"},
                                                               {"metrics.json", "{}\n"}};

fs::path with_earlier_outputs(const fs::path& folder) {
  const fs::path out = folder / "runs" / "out";
  fs::create_directories(out);
  for (const auto& [name, text] : earlier) write_text(out / name, text);
  return out;
}

TEST(Interrupted, InterpolateKilledBySigtermLeavesNothing) {
  const fs::path folder = scratch("term");
  const fs::path out = with_earlier_outputs(folder);
  interrupt_when_staged(start(long_interpolation(folder, out)), SIGTERM, out, "frame_0020.obj", earlier);
}

TEST(Interrupted, InterpolateStoppedBySigintLeavesNothing) {
  const fs::path folder = scratch("int");
  const fs::path out = with_earlier_outputs(folder);
  interrupt_when_staged(start(long_interpolation(folder, out)), SIGINT, out, "frame_0020.obj", earlier);
}

TEST(Interrupted, ClaimsKilledBySigtermLeaveNothing) {
  const fs::path report = scratch("claims") / "runs" / "report";
  fs::create_directories(report);
  write_text(report / "claims.json", "{\"earlier\": true}\n");
  write_text(report / "REPORT.md", "earlier\n");
  const pid_t pid = start({"claims", "--size", "quick", "--threads", "1", "--out", report.string()});
  interrupt_when_staged(pid, SIGTERM, report, "figures",
                        {{"claims.json", "{\"earlier\": true}\n"}, {"REPORT.md", "earlier\n"}},
                        std::chrono::milliseconds(1500));  // checks running, figures being drawn
}

/// The processes whose parent is `pid` (from /proc), with their names.
std::vector<std::pair<pid_t, std::string>> children_of(pid_t pid) {
  std::vector<std::pair<pid_t, std::string>> children;
  std::error_code ignored;
  for (const auto& entry : fs::directory_iterator("/proc", ignored)) {
    std::ifstream stat(entry.path() / "stat");
    std::string line;
    if (!std::getline(stat, line)) continue;
    // pid (comm) state ppid ...: comm may hold spaces and parentheses, so read from the last ')'.
    const auto close = line.rfind(')');
    if (close == std::string::npos) continue;
    std::istringstream rest(line.substr(close + 2));
    char state = 0;
    pid_t parent = 0;
    rest >> state >> parent;
    if (parent == pid)
      children.emplace_back(std::stoi(line), line.substr(line.find('(') + 1, close - line.find('(') - 1));
  }
  return children;
}

/// True while `pid` runs (a zombie has ended).
bool running(pid_t pid) {
  std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
  std::string line;
  if (!std::getline(stat, line)) return false;
  const auto close = line.rfind(')');
  return close != std::string::npos && close + 2 < line.size() && line[close + 2] != 'Z';
}

// `affinterp prove` killed while a decider runs: the deciders are killed with it (they run in process groups of
// their own, which no terminal signal reaches). It needs the real deciders, so it runs in the `proof` tier
// (test interrupt.prove, AFFINTERP_DECIDERS_RUN set); the unit tier's PATH has stand-ins that exit at once.
TEST(Interrupted, ProveKilledWhileADeciderRunsLeavesNoDeciderRunning) {
  if (std::getenv("AFFINTERP_DECIDERS_RUN") == nullptr) GTEST_SKIP() << "runs in the proof tier (interrupt.prove)";
  const fs::path answers = scratch("deciding") / "answers";
  fs::create_directories(answers);
  fs::copy(fs::path(AFFINTERP_SOURCE_DIR) / "reports/proofs/thesis.thm-2.2.1", answers / "thesis.thm-2.2.1",
           fs::copy_options::recursive);
  const pid_t pid = start({"prove", "thesis.thm-2.2.1", "--all", "--jobs", "1", "--answers", answers.string()});
  std::vector<std::pair<pid_t, std::string>> deciders;
  ASSERT_TRUE(wait_until(pid, [&] {
    deciders = children_of(pid);
    return !deciders.empty();
  })) << "prove ended before a decider started";
  ASSERT_EQ(kill(pid, SIGTERM), 0);
  int status = 0;
  for (int tries = 0; tries < 3000 && waitpid(pid, &status, WNOHANG) == 0; ++tries)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGTERM);
  for (const auto& [child, name] : deciders) {
    for (int tries = 0; tries < 500 && running(child); ++tries)
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    EXPECT_FALSE(running(child)) << name << " (" << child << ") still runs after its parent was killed";
  }
}

TEST(Interrupted, AStaleStagingFolderIsRemovedByTheNextRun) {
  const fs::path folder = scratch("stale");
  ASSERT_EQ(run_cli("shapes worm-curl --out " + folder.string()).status, 0);
  const fs::path out = folder / "runs" / "out";
  const pid_t gone = fork();
  if (gone == 0) _exit(0);
  waitpid(gone, nullptr, 0);  // a process id that no longer runs
  const fs::path stale = out.parent_path() / (".out.staging-" + std::to_string(gone));
  const fs::path live = out.parent_path() / (".out.staging-" + std::to_string(getpid()));
  const fs::path other = out.parent_path() / (".other.staging-" + std::to_string(gone));
  for (const auto& staging : {stale, live, other}) {
    fs::create_directories(staging / "figures");
    write_text(staging / "figures" / "x.png", "left behind\n");
  }
  const auto result = run_cli("interpolate --source " + (folder / "source.obj").string() + " --target " +
                              (folder / "target.obj").string() + " --frames 3 --no-figures --out " + out.string());
  ASSERT_EQ(result.status, 0) << result.error;
  EXPECT_FALSE(fs::exists(stale)) << "left by a process that is gone";
  EXPECT_TRUE(fs::exists(live)) << "a running process's staging folder is its own";
  EXPECT_TRUE(fs::exists(other)) << "another output's staging folder is not this run's business";
  fs::remove_all(folder);
}

}  // namespace
