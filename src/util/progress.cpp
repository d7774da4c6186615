#include "util/progress.h"

#include <unistd.h>

#include <cstdio>

namespace mb {

ProgressBar::ProgressBar(std::string label, uint64_t total, bool quiet, ProgressLog log)
    : label_(std::move(label)),
      total_(total),
      enabled_(!quiet),
      terminal_(isatty(STDERR_FILENO)),
      log_(log) {
  start_ = std::chrono::steady_clock::now();
  last_draw_ = start_.time_since_epoch().count();
}

ProgressBar::~ProgressBar() {
  finish();
}

std::string format_duration(double seconds) {
  char buffer[32];
  if (seconds < 60) {
    std::snprintf(buffer, sizeof buffer, "%.1fs", seconds);
  } else if (seconds < 3600) {
    std::snprintf(buffer, sizeof buffer, "%dm%02ds", int(seconds) / 60, int(seconds) % 60);
  } else {
    std::snprintf(buffer, sizeof buffer, "%dh%02dm", int(seconds) / 3600, (int(seconds) / 60) % 60);
  }
  return buffer;
}

void ProgressBar::advance(uint64_t amount) {
  uint64_t done = done_.fetch_add(amount) + amount;
  if (!enabled_) return;
  const auto now = std::chrono::steady_clock::now();
  const auto due = [&] {
    const std::chrono::steady_clock::duration since(now.time_since_epoch().count() - last_draw_);
    if (terminal_)  // nothing for the first second: short work stays silent
      return now - start_ >= std::chrono::seconds(1) && since >= std::chrono::milliseconds(200);
    return since >= (drawn_ ? log_.every : log_.first);
  };
  if (!due()) return;
  std::unique_lock lock(draw_mutex_, std::try_to_lock);
  if (!lock.owns_lock() || !due()) return;  // another thread may have drawn meanwhile
  last_draw_ = now.time_since_epoch().count();
  draw(done, false);
}

void ProgressBar::draw(uint64_t done, bool final) {
  double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  double fraction = total_ ? double(done) / double(total_) : 1.0;
  int width = 30, filled = int(fraction * width);
  std::string bar(filled, '#');
  bar.resize(width, '.');
  double rate = elapsed > 0 ? done / elapsed : 0;
  std::string eta = final ? "done in " + format_duration(elapsed)
                          : "ETA " + format_duration(rate > 0 ? (total_ - done) / rate : 0);
  if (terminal_) {
    std::fprintf(stderr, "\r%s [%s] %llu/%llu (%.3g/min) %s%s%s   ", label_.c_str(), bar.c_str(),
                 (unsigned long long)done, (unsigned long long)total_, rate * 60, eta.c_str(),
                 note_.empty() ? "" : ", ", note_.c_str());
    if (final) std::fputc('\n', stderr);
  } else {  // one line each time, stamped with the elapsed time
    std::fprintf(stderr, "%s: %llu/%llu after %s (%.3g/min) %s%s%s\n", label_.c_str(),
                 (unsigned long long)done, (unsigned long long)total_,
                 format_duration(elapsed).c_str(), rate * 60, eta.c_str(),
                 note_.empty() ? "" : ", ", note_.c_str());
  }
  std::fflush(stderr);
  drawn_ = true;
}

void ProgressBar::set_note(std::string note) {
  std::lock_guard lock(draw_mutex_);
  note_ = std::move(note);
}

void ProgressBar::finish() {
  if (finished_) return;
  finished_ = true;
  std::lock_guard lock(draw_mutex_);
  if (enabled_ && drawn_) draw(done_.load(), true);
}

}  // namespace mb
