#pragma once
// What makes two sweep runs the same run (docs/design.md §Data flow): the option values of the
// effective config, never its prose. The hash covers every `key: value` line of config.yaml except
// `threads` (which never changes a result), so rewording an option's documentation keeps a sweep
// resumable; databases written when the hash also covered the comments are still recognised by
// comparing their stored config's values.
#include <map>
#include <optional>
#include <string>

#include "eval/evaluation.h"

namespace mb {

// The `key: value` lines of a config YAML (as Config::to_yaml writes it), without comments and
// without `threads`, in order.
std::string config_values(const std::string& config_yaml);
// FNV-1a of config_values, as 16 hex digits.
std::string config_hash(const std::string& config_yaml);
// True when the database's meta (`config_hash`, `config`) describes the run of `config_yaml`: the
// same hash, or the same values, where a key the stored config lacks (an option added since) counts
// as the same when its value is its default in `defaults_yaml` (the defaults' config YAML; the
// option's default keeps the behaviour from before it existed).
bool same_config(const std::map<std::string, std::string>& meta, const std::string& config_yaml,
                 const std::string& defaults_yaml = "");

// What the errors of a run are measured with, as separate results-database meta keys with exact
// values (kernel.size, kernel.sigma, reference, bias.slope, bias.constant, lp.grid, lp.lo, lp.hi,
// lp.discretization, lp.quantize, lp.backend, lp.moment_box): databases are comparable when these
// and the dataset agree.
std::map<std::string, std::string> measurement_meta(const EvalSettings& settings);
// The first key by which two databases' errors are measured differently ("" when comparable).
// Databases written before measurement_meta existed are compared by their `settings` sentence.
std::string incomparable_key(const std::map<std::string, std::string>& a,
                             const std::map<std::string, std::string>& b);

struct LpGridIdentity {
  int grid = 0;
  double lo = 0, hi = 0;
};
// The LP grid a database's candidates were judged on: its meta keys, or for older databases the
// `settings` sentence ("LP grid N on [lo, hi]"); nullopt when neither records it.
std::optional<LpGridIdentity> lp_grid_of(const std::map<std::string, std::string>& meta);

}  // namespace mb
