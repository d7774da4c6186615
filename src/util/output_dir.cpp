#include "util/output_dir.h"

#include <unistd.h>

#include <fstream>

#include "util/error.h"

namespace mb {

namespace fs = std::filesystem;

StagedOutputDir::StagedOutputDir(fs::path target, bool force) : target_(std::move(target)), force_(force) {
  if (target_.empty()) throw InputError("--out: an output directory is required");
  if (fs::exists(target_) && !force_)
    throw InputError(target_.string() + ": output directory exists (use --force to replace it)");
  fs::path parent = fs::absolute(target_).parent_path();
  std::error_code ec;
  fs::create_directories(parent, ec);
  if (ec || access(parent.c_str(), W_OK) != 0)
    throw InputError(parent.string() + ": cannot write the output directory here");
  staging_ = parent / ("." + target_.filename().string() + ".staging-" + std::to_string(getpid()));
  fs::remove_all(staging_, ec);
  fs::create_directory(staging_, ec);
  if (ec) throw InputError(staging_.string() + ": cannot create: " + ec.message());
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
