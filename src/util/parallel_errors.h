#pragma once
// An exception thrown inside an OpenMP region terminates the program ("terminate called
// recursively" with several threads). Loop bodies run through `capture`, which keeps the first
// exception; after the region, `rethrow` raises it on the calling thread, where commands report it.
#include <exception>
#include <mutex>

namespace mb {

class ParallelErrors {
 public:
  template <class Body>
  void capture(Body&& body) noexcept {
    if (failed()) return;  // the run is lost anyway: skip the remaining work
    try {
      body();
    } catch (...) {
      std::lock_guard<std::mutex> lock(mutex_);
      if (!first_) first_ = std::current_exception();
    }
  }
  bool failed() noexcept {
    std::lock_guard<std::mutex> lock(mutex_);
    return bool(first_);
  }
  void rethrow() const {
    if (first_) std::rethrow_exception(first_);
  }

 private:
  std::mutex mutex_;
  std::exception_ptr first_;
};

}  // namespace mb
