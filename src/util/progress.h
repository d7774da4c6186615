#pragma once
// A progress bar with rate and ETA on stderr. No Debian package offers one (issue 3). Silent when
// stderr is not a terminal, when quiet, or for work that finishes within a second.
#include <atomic>
#include <chrono>
#include <cstdint>
#include <mutex>
#include <string>

namespace mb {

class ProgressBar {
 public:
  ProgressBar(std::string label, uint64_t total, bool quiet);
  ~ProgressBar();
  // Thread-safe; redraws at most a few times a second.
  void advance(uint64_t amount = 1);
  // Extra text after the counts (rates of the work, e.g. "41.2k LP/s"); thread-safe.
  void set_note(std::string note);
  void finish();

 private:
  void draw(uint64_t done, bool final);
  std::string label_;
  uint64_t total_;
  bool enabled_;
  std::atomic<uint64_t> done_{0};
  std::chrono::steady_clock::time_point start_, last_draw_;
  std::mutex draw_mutex_;
  bool drawn_ = false, finished_ = false;
  std::string note_;
};

// "1h02m", "3m05s", "12.3s"
std::string format_duration(double seconds);

}  // namespace mb
