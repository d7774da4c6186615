#include "util/output_dir.h"

#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <fstream>

#include "util/error.h"

namespace mb {

namespace fs = std::filesystem;

namespace {

// Staging directories of `name` whose process is gone (killed, crashed, powered off) are never
// committed: remove them, so they do not pile up beside the outputs. A live process's is kept.
void remove_dead_stagings(const fs::path& parent, const std::string& name) {
  const std::string prefix = "." + name + ".staging-";
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(parent, ec)) {
    const std::string file = entry.path().filename().string();
    if (file.rfind(prefix, 0) != 0) continue;
    const std::string digits = file.substr(prefix.size());
    if (digits.empty() || digits.find_first_not_of("0123456789") != std::string::npos) continue;
    const long pid = std::stol(digits);
    if (pid > 0 && kill(pid_t(pid), 0) == -1 && errno == ESRCH) fs::remove_all(entry.path(), ec);
  }
}

}  // namespace

StagedOutputDir::StagedOutputDir(fs::path target, bool force)
    : target_(std::move(target)), force_(force) {
  if (target_.empty()) throw InputError("--out: an output directory is required");
  if (fs::exists(target_) && !force_)
    throw InputError(target_.string() + ": output directory exists (use --force to replace it)");
  fs::path parent = fs::absolute(target_).parent_path();
  std::error_code ec;
  fs::create_directories(parent, ec);
  if (ec || access(parent.c_str(), W_OK) != 0)
    throw InputError(target_.string() + ": cannot create the output directory: " + parent.string() +
                     (ec ? " cannot be created (" + ec.message() + ")" : " is not writable"));
  if (fs::exists(target_) && !fs::is_directory(target_))
    throw InputError(target_.string() + ": exists and is not a directory; --out needs a directory");
  remove_dead_stagings(parent, target_.filename().string());
  // Appended piece by piece: GCC 12 warns (-Warray-bounds, a false positive) on "." + a temporary.
  std::string staging = ".";
  staging.append(target_.filename().string()).append(".staging-").append(std::to_string(getpid()));
  staging_ = parent / staging;
  fs::remove_all(staging_, ec);
  fs::create_directory(staging_, ec);
  if (ec)
    throw InputError(target_.string() + ": cannot create the output directory: " + ec.message());
}

StagedOutputDir::~StagedOutputDir() {
  if (!committed_) {
    std::error_code ec;
    fs::remove_all(staging_, ec);
  }
}

void StagedOutputDir::commit() {
  if (fs::exists(target_)) {
    if (!force_) throw InputError(target_.string() + ": output directory appeared while running");
    fs::remove_all(target_);
  }
  fs::rename(staging_, target_);
  committed_ = true;
}

void write_file_atomically(const fs::path& path, const std::string& content) {
  fs::path temporary = path;
  temporary += ".tmp-" + std::to_string(getpid());
  {
    std::ofstream out(temporary, std::ios::binary);
    out << content;
    out.flush();
    if (!out) throw InputError(path.string() + ": cannot write");
  }
  fs::rename(temporary, path);
}

}  // namespace mb
