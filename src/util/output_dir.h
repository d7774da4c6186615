#pragma once
// Output that appears whole or not at all: a command writes into a staging directory beside the
// target and renames it into place only after everything succeeded.
#include <filesystem>
#include <string>

namespace mb {

class StagedOutputDir {
 public:
  // Fails (InputError) when `target` exists and `force` is false, or its parent is not writable.
  StagedOutputDir(std::filesystem::path target, bool force);
  ~StagedOutputDir();  // removes the staging directory unless committed
  StagedOutputDir(const StagedOutputDir&) = delete;
  StagedOutputDir& operator=(const StagedOutputDir&) = delete;

  const std::filesystem::path& staging() const { return staging_; }
  const std::filesystem::path& target() const { return target_; }
  std::filesystem::path operator/(const std::string& name) const { return staging_ / name; }
  // Moves the staging directory to the target (replacing it when forced).
  void commit();

 private:
  std::filesystem::path target_, staging_;
  bool force_, committed_ = false;
};

// Writes a whole file through a temporary name and a rename, so readers never see half of it.
void write_file_atomically(const std::filesystem::path& path, const std::string& content);

}  // namespace mb
