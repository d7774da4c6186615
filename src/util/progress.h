#pragma once
// A progress bar with rate and ETA on stderr. No Debian package offers one (issue 3). Silent when
// quiet, or for work that finishes within a second. When stderr is not a terminal (a Slurm or
// nohup log) it writes a whole line now and then instead of redrawing: a run of hours shows its
// progress in the log (docs/sweeps.md, "Full scale").
#include <atomic>
#include <chrono>
#include <cstdint>
#include <mutex>
#include <string>

namespace mb {

// When a progress line goes to a log: the first after `first`, then one every `every`. Lines come
// as work advances, so `every` stays a minute under the 5 minutes a log may go silent: one more
// unit of work (a sweep's candidate) fits in between.
struct ProgressLog {
  std::chrono::seconds first{60}, every{240};
};

class ProgressBar {
 public:
  ProgressBar(std::string label, uint64_t total, bool quiet, ProgressLog log = {});
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
  bool enabled_, terminal_;
  ProgressLog log_;
  std::atomic<uint64_t> done_{0};
  std::chrono::steady_clock::time_point start_;
  // Read by every thread that advances, written under draw_mutex_.
  std::atomic<std::chrono::steady_clock::rep> last_draw_{0};
  std::atomic<bool> drawn_{false};
  std::mutex draw_mutex_;
  bool finished_ = false;
  std::string note_;
};

// "1h02m", "3m05s", "12.3s"
std::string format_duration(double seconds);

}  // namespace mb
