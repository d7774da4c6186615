#include "sweep/sweep_directory.h"

#include "sweep/run_identity.h"
#include "util/error.h"
#include "util/output_dir.h"

namespace mb {

namespace {

// Only what a sweep writes before its database exists: config.yaml, run_*.yaml, and the
// temporaries of atomic writes.
bool is_sweep_directory(const std::filesystem::path& dir) {
  if (!std::filesystem::is_directory(dir)) return false;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    const std::string name = entry.path().filename().string();
    const bool ours = name == "config.yaml" ||
                      (name.rfind("run_", 0) == 0 && name.find(".yaml") != std::string::npos) ||
                      name.find(".tmp-") != std::string::npos ||
                      name.rfind("results.sqlite", 0) == 0 ||
                      name.rfind(".results.sqlite.new-", 0) == 0;
    if (!ours) return false;
  }
  return true;
}

}  // namespace

ResultsStore open_sweep_directory(const std::filesystem::path& out, const SweepIdentity& identity,
                                  const std::map<std::string, std::string>& meta, bool resume,
                                  bool force) {
  namespace fs = std::filesystem;
  const fs::path db_path = out / "results.sqlite";
  if (resume && fs::exists(db_path)) {
    ResultsStore store = ResultsStore::open(db_path.string());
    auto have = store.meta();
    if (const auto differences = config_differences(have, identity.config_yaml, identity.specs);
        !differences.empty())
      throw InputError(db_path.string() + ": the sweep there was run with another config (hash " +
                       have["config_hash"] + ", now " + identity.config_hash +
                       "): " + differences_text(differences, "that sweep", "this one") +
                       "; resume with its values (its config.yaml), or start a new sweep "
                       "elsewhere");
    if (have["shard"] != identity.shard)
      throw InputError(db_path.string() + ": that sweep is shard " + have["shard"] + ", not " +
                       identity.shard);
    return store;
  }
  // A sweep killed before its database existed left at most its own files: --resume starts it
  // afresh there, so a sweep resumes from every instant (ResultsStore::create is atomic).
  if (fs::exists(out)) {
    if (resume) {
      if (!is_sweep_directory(out))
        throw InputError(out.string() +
                         ": holds no results.sqlite and files that are not a sweep's; not "
                         "resuming here");
    } else if (!force) {
      throw InputError(out.string() +
                       ": output directory exists (use --resume to continue its sweep, --force "
                       "to replace it)");
    } else {
      fs::remove_all(out);
    }
  }
  std::error_code ec;
  fs::create_directories(out, ec);
  if (ec) throw InputError(out.string() + ": cannot create the output directory: " + ec.message());
  write_file_atomically(out / "config.yaml", identity.config_yaml);
  std::map<std::string, std::string> all = meta;
  all["config_hash"] = identity.config_hash;
  all["shard"] = identity.shard;
  all["config"] = identity.config_yaml;
  return ResultsStore::create(db_path.string(), all);
}

}  // namespace mb
