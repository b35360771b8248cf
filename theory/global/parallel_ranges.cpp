#include "theory/global/parallel_ranges.hpp"

#include <algorithm>
#include <exception>
#include <thread>
#include <vector>

namespace affinterp::global {

void for_each_range(std::size_t count, std::size_t ranges, const std::function<void(std::size_t, std::size_t)>& body) {
  ranges = std::max<std::size_t>(1, std::min(ranges, count));
  std::vector<std::exception_ptr> failures(ranges);
  auto run = [&](std::size_t r) {
    try {
      body(count * r / ranges, count * (r + 1) / ranges);
    } catch (...) {
      failures[r] = std::current_exception();
    }
  };
  std::vector<std::thread> threads;
  for (std::size_t r = 1; r < ranges; ++r) threads.emplace_back(run, r);
  run(0);
  for (std::thread& thread : threads) thread.join();
  for (const std::exception_ptr& failure : failures)
    if (failure) std::rethrow_exception(failure);
}

void side_by_side(const std::function<void()>& here, const std::function<void()>& there) {
  for_each_range(2, 2, [&](std::size_t first, std::size_t) { first == 0 ? here() : there(); });
}

std::size_t ranges_for(std::size_t count, std::size_t grain) {
  return std::clamp<std::size_t>(count / std::max<std::size_t>(1, grain), 1,
                                 std::max(1u, std::thread::hardware_concurrency()));
}

}  // namespace affinterp::global
