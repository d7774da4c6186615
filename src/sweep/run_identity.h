#pragma once
// What makes two sweep runs the same run (docs/design.md §Data flow): the option values of the
// effective config, never its prose. The hash covers every `key: value` line of config.yaml except
// `threads` (which never changes a result), so rewording an option's documentation keeps a sweep
// resumable; databases written when the hash also covered the comments are still recognised by
// comparing their stored config's values.
#include <map>
#include <string>

namespace mb {

// The `key: value` lines of a config YAML (as Config::to_yaml writes it), without comments and
// without `threads`, in order.
std::string config_values(const std::string& config_yaml);
// FNV-1a of config_values, as 16 hex digits.
std::string config_hash(const std::string& config_yaml);
// True when the database's meta (`config_hash`, `config`) describes the run of `config_yaml`: the
// same hash, or (databases from before the value-only hash) the same values.
bool same_config(const std::map<std::string, std::string>& meta, const std::string& config_yaml);

}  // namespace mb
