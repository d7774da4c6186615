#pragma once
// What every report starts with: how it was made (docs/design.md §Style, "reports that say how").
#include <string>
#include <vector>

namespace mb {

struct RunMetadata {
  std::string git_sha;
  std::string compiler;
  std::string version;
  int threads = 1;
  std::string command_line;
  std::string started_utc;
};

RunMetadata collect_run_metadata(int threads, const std::vector<std::string>& argv);
// YAML lines: "git_sha: ...", one key a line.
std::string to_yaml(const RunMetadata& meta);

// Threads to use: `requested` if > 0, else OpenMP's default (all cores).
int resolve_thread_count(int requested);

}  // namespace mb
