#pragma once
// Progress of a long loop on standard error: a percentage that advances in place on the current line,
// and is wiped when the loop ends, so that whoever owns the line (the claims runner's "[i/n] id ...")
// can rewrite it with the result.
#include <atomic>
#include <cstddef>
#include <iostream>
#include <string>

namespace affinterp {

class Progress {
 public:
  Progress(std::string label, std::size_t total) : label_(std::move(label)), total_(total) {}
  ~Progress() {
    if (shown_ >= 0) std::cerr << "\r" << std::string(label_.size() + 8, ' ') << "\r" << std::flush;
  }
  /// Records `count` more units done; thread-safe.
  void advance(std::size_t count = 1) {
    const std::size_t done = done_ += count;
    const int percent = total_ == 0 ? 100 : static_cast<int>(100 * done / total_);
    int shown = shown_;
    if (percent / 10 > shown / 10 && shown_.compare_exchange_strong(shown, percent))
      std::cerr << "\r" << label_ << ": " << percent << "%" << std::flush;
  }

 private:
  std::string label_;
  std::size_t total_;
  std::atomic<std::size_t> done_{0};
  std::atomic<int> shown_{-10};
};

}  // namespace affinterp
