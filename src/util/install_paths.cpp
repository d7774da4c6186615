#include "util/install_paths.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>

#include "util/error.h"

extern char** environ;

namespace mb {

namespace fs = std::filesystem;

namespace {

bool holds_datasets(const fs::path& root) {
  std::error_code ec;
  return !root.empty() && fs::is_directory(root / "configs" / "datasets", ec);
}

}  // namespace

fs::path data_root() {
  std::vector<fs::path> tried;
  if (const char* home = std::getenv("MOMENTBENCH_HOME"); home && *home) {
    if (holds_datasets(home)) return home;
    throw InputError(std::string("MOMENTBENCH_HOME=") + home +
                     ": expected a directory holding configs/datasets");
  }
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    tried.push_back(exe.parent_path().parent_path() / "share" / "momentbench");
    if (holds_datasets(tried.back())) return tried.back();
  }
  tried.push_back(MOMENTBENCH_SOURCE_DIR);
  if (holds_datasets(tried.back())) return tried.back();
  std::string places;
  for (const auto& p : tried) places += (places.empty() ? "" : ", ") + p.string();
  throw InputError("cannot find momentbench's data (configs/datasets) in " + places +
                   "; set MOMENTBENCH_HOME to an installed share/momentbench");
}

int run_program(const std::string& program, const std::vector<std::string>& arguments, bool quiet) {
  std::vector<char*> argv;
  argv.push_back(const_cast<char*>(program.c_str()));
  for (const auto& a : arguments) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  if (quiet) posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  pid_t pid = 0;
  const int started = posix_spawn(&pid, program.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (started != 0) return 127;
  int status = 0;
  while (waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) return 127;
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

}  // namespace mb
