#pragma once
// What makes two sweep runs the same run, and their errors comparable (docs/sweeps.md
// "Identity"): the option records say it (OptionSpec::effect), never a hand list. A run's
// identity is the value of every option that changes a measured number, stored as the database's
// meta keys; `report` compares those. A resume and a merge also compare the options that choose
// what is measured (catalog, sample, screen.*). Options that change no measured number (threads)
// are compared by nobody. Databases written before this are read through their stored config and
// the twelve measurement keys they carry (the oldest through their `settings` sentence).
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "util/config.h"

namespace mb {

using Meta = std::map<std::string, std::string>;

// The `key: value` lines of a config YAML (as Config::to_yaml writes it), without comments and
// without the options of `specs` that change no measured number, in order.
std::string config_values(const std::string& config_yaml, const std::vector<OptionSpec>& specs);
// FNV-1a of config_values, as 16 hex digits.
std::string config_hash(const std::string& config_yaml, const std::vector<OptionSpec>& specs);

// One option that two runs set differently.
struct OptionDifference {
  std::string key, first, second;  // the key, its value in the first run and in the second
};

// The options a resume or merge compares (OptionEffect Measures and Selects in `specs`) whose
// value in `config_yaml` differs from the run the meta describes (its `config`). A key the stored
// config lacks (an option added since) counts at its default, which keeps the behaviour from
// before it existed; a stored key `specs` no longer declares is a difference. `first` is the
// stored value, `second` the one in `config_yaml`; empty when the config hashes agree.
std::vector<OptionDifference> config_differences(const Meta& meta, const std::string& config_yaml,
                                                 const std::vector<OptionSpec>& specs);
bool same_config(const Meta& meta, const std::string& config_yaml,
                 const std::vector<OptionSpec>& specs);

// The run's identity as meta keys: every option of `specs` that changes a measured number, its
// value as config.yaml writes it.
Meta measurement_meta(const std::string& config_yaml, const std::vector<OptionSpec>& specs);
// A measurement option's value in a database's meta: its meta key; else (a database written
// before the key was stored) its stored config's line; else the option's default in `specs`.
std::string measurement_value(const Meta& meta, const std::string& key,
                              const std::vector<OptionSpec>& specs);
// What the run's config set `key` to (its stored config's line, else the default in `specs`),
// before the sweep resolved it: a dataset's own `resolution` is stored as the maps' size, and
// configured 0.
std::string configured_value(const Meta& meta, const std::string& key,
                             const std::vector<OptionSpec>& specs);
// The measurement options of `specs` whose values differ between two databases, `dataset` first:
// `specs` are the options the runs read (sweep_target_specs of their target, or every option when
// their targets differ). Databases from before the measurement keys also differ by their
// `settings` sentence.
std::vector<OptionDifference> measurement_differences(const Meta& a, const Meta& b,
                                                      const std::vector<OptionSpec>& specs);
// "key: a here, b there; ..." for an error message.
std::string differences_text(const std::vector<OptionDifference>& differences,
                             const std::string& first, const std::string& second);

struct LpGridIdentity {
  int grid = 0;
  double lo = 0, hi = 0;
};
// The LP grid a database's candidates were judged on: its meta keys, or for older databases the
// `settings` sentence ("LP grid N on [lo, hi]"); nullopt when neither records it.
std::optional<LpGridIdentity> lp_grid_of(const Meta& meta);

}  // namespace mb
