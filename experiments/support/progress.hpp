#pragma once
// Progress of a long loop on standard error, when it is a terminal: a bar that advances in place on the
// current line and is wiped when the loop ends, so that whoever owns the line (the claims runner's
// "[i/n] id ...") can rewrite it with the result. Nothing is written to a file or a pipe (logs stay clean).
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <iostream>
#include <sstream>
#include <string>

namespace affinterp {

class Progress {
 public:
  Progress(std::string label, std::size_t total)
      : label_(std::move(label)), total_(total), terminal_(isatty(STDERR_FILENO) == 1) {}
  ~Progress() {
    if (const std::size_t width = shown_width_; width > 0)
      std::cerr << "\r" << std::string(width, ' ') << "\r" << std::flush;
  }
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  /// Records `count` more units done; thread-safe.
  void advance(std::size_t count = 1) {
    if (!terminal_) return;
    const std::size_t done = done_ += count;
    const int percent = total_ == 0 ? 100 : static_cast<int>(100 * std::min(done, total_) / total_);
    int shown = shown_;
    if (percent > shown && shown_.compare_exchange_strong(shown, percent)) {
      constexpr int bar = 30;
      const int filled = percent * bar / 100;
      std::ostringstream line;
      line << label_ << " [" << std::string(filled, '#') << std::string(bar - filled, '.') << "] " << percent << "% ("
           << std::min(done, total_) << "/" << total_ << ")";
      shown_width_ = std::max<std::size_t>(shown_width_, line.str().size());
      std::cerr << "\r" << line.str() << std::flush;
    }
  }

 private:
  std::string label_;
  std::size_t total_;
  bool terminal_;
  std::atomic<std::size_t> done_{0};
  std::atomic<int> shown_{-1};
  std::atomic<std::size_t> shown_width_{0};
};

}  // namespace affinterp
