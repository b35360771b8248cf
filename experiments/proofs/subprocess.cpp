#include "experiments/proofs/subprocess.hpp"

#include "experiments/support/interrupt_cleanup.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <vector>

namespace affinterp::proofs {

namespace {

/// Exit status a child uses when exec fails (the shell's convention for "command not found").
constexpr int exec_failed = 127;

/// The child's side: limits, standard streams, exec. Only async-signal-safe calls: the parent may have
/// other threads (both deciders start at once), so nothing here allocates.
[[noreturn]] void exec_child(char* const* argv, char* const* envp, const char* input, const ProcessLimits& limits,
                             int output_fd) {
  setpgid(0, 0);  // its own process group, so that a timeout kills every process the decider starts
  const rlim_t cap = limits.address_space_bytes;
  const rlimit as{cap, cap};
  setrlimit(RLIMIT_AS, &as);
  if (limits.cpu_seconds > 0) {  // SIGXCPU at the soft limit, SIGKILL a second later
    const auto soft = static_cast<rlim_t>(std::ceil(limits.cpu_seconds));
    const rlimit cpu{soft, soft + 1};
    setrlimit(RLIMIT_CPU, &cpu);
  }
  const int in = open(input, O_RDONLY);
  if (in < 0) _exit(exec_failed + 1);
  dup2(in, STDIN_FILENO);
  dup2(output_fd, STDOUT_FILENO);
  dup2(output_fd, STDERR_FILENO);
  execvpe(argv[0], argv, envp);
  _exit(exec_failed);
}

/// The environment of this process, with QEPCAD B's $qe (where it finds its help files) set if missing.
std::vector<std::string> child_environment() {
  std::vector<std::string> env;
  bool has_qe = false;
  for (char** e = environ; *e != nullptr; ++e) {
    env.emplace_back(*e);
    has_qe = has_qe || env.back().rfind("qe=", 0) == 0;
  }
  if (!has_qe) env.emplace_back("qe=/usr/lib/qepcad");
  return env;
}

std::vector<char*> pointers(std::vector<std::string>& strings) {
  std::vector<char*> p;
  for (std::string& s : strings) p.push_back(s.data());
  p.push_back(nullptr);
  return p;
}

}  // namespace

ProcessResult run_process(const std::vector<std::string>& argv, const std::filesystem::path& input,
                          const ProcessLimits& limits) {
  if (argv.empty()) throw std::invalid_argument("run_process(): no program");
  std::vector<std::string> args = argv, env = child_environment();
  const std::vector<char*> arg_pointers = pointers(args), env_pointers = pointers(env);
  const std::string input_path = input.empty() ? std::string("/dev/null") : input.string();
  int fds[2];
  if (pipe2(fds, O_CLOEXEC) != 0) throw std::runtime_error("run_process(): pipe failed");
  const auto start = std::chrono::steady_clock::now();
  // An interrupted run (Ctrl-C, SIGTERM) kills the decider's group too (interrupt_cleanup.hpp).
  const KilledOnInterrupt child([&] {
    const pid_t forked = fork();
    if (forked < 0) throw std::runtime_error("run_process(): fork failed");
    if (forked == 0) {
      close(fds[0]);
      exec_child(arg_pointers.data(), env_pointers.data(), input_path.c_str(), limits, fds[1]);
    }
    setpgid(forked, forked);  // also from the parent, so that killpg works even before the child ran
    return forked;
  });
  const pid_t pid = child.pid();
  close(fds[1]);

  ProcessResult result;
  const auto deadline = start + std::chrono::duration<double>(limits.wall_seconds);
  char buffer[65536];
  for (;;) {
    const auto left =
        std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) {
      result.timed_out = true;
      break;
    }
    pollfd p{fds[0], POLLIN, 0};
    const int ready = poll(&p, 1, static_cast<int>(std::min<long long>(left.count(), 1000)));
    if (ready < 0 && errno != EINTR) break;
    if (ready <= 0) continue;
    const ssize_t n = read(fds[0], buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;  // end of output: the child closed it (exited)
    result.output.append(buffer, static_cast<std::size_t>(n));
  }
  if (result.timed_out) killpg(pid, SIGKILL);
  close(fds[0]);
  int status = 0;
  rusage usage{};
  while (wait4(pid, &status, 0, &usage) < 0 && errno == EINTR) {
  }
  // A grandchild that kept the group alive after the decider exited is ended too.
  killpg(pid, SIGKILL);
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const auto seconds_of = [](const timeval& t) { return static_cast<double>(t.tv_sec) + 1e-6 * t.tv_usec; };
  result.cpu_seconds = seconds_of(usage.ru_utime) + seconds_of(usage.ru_stime);
  result.max_rss_kb = usage.ru_maxrss;
  result.exit_status = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  if (WIFSIGNALED(status) && (WTERMSIG(status) == SIGXCPU || WTERMSIG(status) == SIGKILL)) result.timed_out = true;
  result.not_found = !result.timed_out && WIFEXITED(status) && WEXITSTATUS(status) == exec_failed;
  return result;
}

}  // namespace affinterp::proofs
