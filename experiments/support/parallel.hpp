#pragma once
// Deterministic data parallelism for sweeps: the index range is cut into fixed chunks, the chunks are
// shared among threads, and the per-chunk results come back in chunk order, so a reduction over them
// gives the same answer for any thread count.
#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace affinterp {

/// Calls fn(begin, end) on consecutive chunks of [0, n) of at most `chunk` indices, on up to `threads`
/// threads; returns the chunks' results in order. The first exception thrown by fn is rethrown.
template <class Fn>
auto parallel_chunks(std::size_t n, unsigned threads, std::size_t chunk, Fn fn) {
  using Result = decltype(fn(std::size_t{}, std::size_t{}));
  chunk = std::max<std::size_t>(chunk, 1);
  const std::size_t chunks = (n + chunk - 1) / chunk;
  std::vector<Result> results(chunks);
  std::atomic<std::size_t> next{0};
  std::exception_ptr failure;
  std::mutex failure_mutex;
  auto work = [&] {
    for (std::size_t c; (c = next++) < chunks;) {
      try {
        results[c] = fn(c * chunk, std::min(n, (c + 1) * chunk));
      } catch (...) {
        const std::lock_guard lock(failure_mutex);
        if (!failure) failure = std::current_exception();
        next = chunks;
      }
    }
  };
  std::vector<std::jthread> pool;
  for (unsigned t = 1; t < std::max(threads, 1u) && t < chunks; ++t) pool.emplace_back(work);
  work();
  pool.clear();
  if (failure) std::rethrow_exception(failure);
  return results;
}

}  // namespace affinterp
