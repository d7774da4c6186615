#include "util/run_metadata.h"

#include <omp.h>

#include <chrono>
#include <ctime>
#include <sstream>

#include "git_sha.h"

namespace mb {

RunMetadata collect_run_metadata(int threads, const std::vector<std::string>& argv) {
  RunMetadata meta;
  meta.git_sha = MOMENTBENCH_GIT_SHA;
#if defined(__clang__)
  meta.compiler = "clang " __clang_version__;
#elif defined(__GNUC__)
  meta.compiler = "gcc " __VERSION__;
#else
  meta.compiler = "unknown";
#endif
  meta.version = MOMENTBENCH_VERSION;
  meta.threads = threads;
  for (const auto& a : argv) meta.command_line += (meta.command_line.empty() ? "" : " ") + a;
  std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  char buffer[32];
  std::strftime(buffer, sizeof buffer, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&now));
  meta.started_utc = buffer;
  return meta;
}

std::string to_yaml(const RunMetadata& meta) {
  std::ostringstream out;
  out << "git_sha: " << meta.git_sha << "\n"
      << "version: " << meta.version << "\n"
      << "compiler: \"" << meta.compiler << "\"\n"
      << "threads: " << meta.threads << "\n"
      << "command_line: \"" << meta.command_line << "\"\n"
      << "started_utc: " << meta.started_utc << "\n";
  return out.str();
}

int resolve_thread_count(int requested) {
  return requested > 0 ? requested : omp_get_max_threads();
}

}  // namespace mb
