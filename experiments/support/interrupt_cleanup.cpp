#include "experiments/support/interrupt_cleanup.hpp"

#include <semaphore.h>

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

/// Removes `path`, again while files still appear in it (a thread may be writing into it meanwhile).
void remove_path(const fs::path& path) {
  for (int attempt = 0; attempt < 100; ++attempt) {
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
  r.mutex.lock();  // held until the end: nothing new is registered or settled
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

}  // namespace affinterp
