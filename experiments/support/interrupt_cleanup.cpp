#include "experiments/support/interrupt_cleanup.hpp"

#include <semaphore.h>
#include <signal.h>

#include <atomic>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <mutex>
#include <set>
#include <system_error>
#include <thread>

namespace affinterp {

namespace fs = std::filesystem;

namespace {

struct Registry {
  std::mutex mutex;
  std::multiset<fs::path> paths;
  std::multiset<pid_t> groups;
};

/// Never destroyed: the removal thread may still use it while the process exits.
Registry& registry() {
  static Registry* r = new Registry;
  return *r;
}

sem_t interrupted;
std::atomic<int> received{0};
static_assert(std::atomic<int>::is_always_lock_free, "the handler may only touch lock-free atomics");

void record(int signal) {
  received.store(signal);
  sem_post(&interrupted);
}

/// Removes `path`, again while files still appear in it: the other threads keep running meanwhile, and a
/// claim's check may write sentences or figures into it or recreate its folders (fs::create_directories).
/// For up to 10 s, not half a second: on two loaded cores, removing a claims run's proofs and figures
/// while its threads write can take longer.
void remove_path(const fs::path& path) {
  for (int attempt = 0; attempt < 2000; ++attempt) {
    std::error_code error;
    fs::remove_all(path, error);
    if (!fs::exists(path, error)) return;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
}

[[noreturn]] void remove_then_reraise() {
  while (sem_wait(&interrupted) != 0 && errno == EINTR) {
  }
  const int signal = received.load();
  Registry& r = registry();
  r.mutex.lock();  // held until the end: nothing new is registered, started or settled
  // The deciders first (process groups of their own, which a terminal's signal does not reach): they
  // would outlive this process for up to their time limit.
  for (const pid_t group : r.groups) killpg(group, SIGKILL);
  for (const fs::path& path : r.paths) remove_path(path);
  std::signal(signal, SIG_DFL);
  std::raise(signal);
  std::_Exit(128 + signal);  // not reached: the default action ends the process
}

}  // namespace

void remove_registered_paths_on_interrupt() {
  static std::once_flag once;
  std::call_once(once, [] {
    sem_init(&interrupted, 0, 0);
    std::thread(remove_then_reraise).detach();
    struct sigaction action {};
    action.sa_handler = record;
    sigemptyset(&action.sa_mask);
    for (const int signal : {SIGINT, SIGTERM, SIGHUP}) {
      struct sigaction previous {};
      sigaction(signal, nullptr, &previous);
      if (previous.sa_handler != SIG_IGN) sigaction(signal, &action, nullptr);
    }
  });
}

RemovedOnInterrupt::RemovedOnInterrupt(fs::path path) : path_(std::move(path)) {
  Registry& r = registry();
  const std::lock_guard lock(r.mutex);
  r.paths.insert(path_);
}

RemovedOnInterrupt::~RemovedOnInterrupt() {
  if (!registered_) return;
  Registry& r = registry();
  const std::lock_guard lock(r.mutex);
  r.paths.erase(r.paths.find(path_));
}

void RemovedOnInterrupt::settle(const std::function<void()>& action) {
  Registry& r = registry();
  const std::lock_guard lock(r.mutex);
  action();
  r.paths.erase(r.paths.find(path_));
  registered_ = false;
}

KilledOnInterrupt::KilledOnInterrupt(const std::function<pid_t()>& start) {
  Registry& r = registry();
  const std::lock_guard lock(r.mutex);
  pid_ = start();
  r.groups.insert(pid_);
}

KilledOnInterrupt::~KilledOnInterrupt() {
  Registry& r = registry();
  const std::lock_guard lock(r.mutex);
  r.groups.erase(r.groups.find(pid_));
}

}  // namespace affinterp
