#include "sweep/run_identity.h"

#include <cstdint>
#include <cstdio>
#include <string>

#include "util/number_text.h"

namespace mb {

std::string config_values(const std::string& yaml) {
  std::string kept;
  size_t start = 0;
  while (start < yaml.size()) {
    size_t end = yaml.find('\n', start);
    if (end == std::string::npos) end = yaml.size();
    const std::string line = yaml.substr(start, end - start);
    if (!line.empty() && line[0] != '#' && line.rfind("threads:", 0) != 0) kept += line + "\n";
    start = end + 1;
  }
  return kept;
}

std::string config_hash(const std::string& config_yaml) {
  uint64_t h = 1469598103934665603ull;
  for (unsigned char c : config_values(config_yaml)) h = (h ^ c) * 1099511628211ull;
  char buffer[24];
  std::snprintf(buffer, sizeof buffer, "%016llx", (unsigned long long)h);
  return buffer;
}

namespace {

// "key: value" lines of config_values as a map.
std::map<std::string, std::string> value_map(const std::string& yaml) {
  std::map<std::string, std::string> out;
  const std::string values = config_values(yaml);
  size_t start = 0;
  while (start < values.size()) {
    const size_t end = values.find('\n', start);
    const std::string line = values.substr(start, end - start);
    const size_t colon = line.find(": ");
    if (colon != std::string::npos) out[line.substr(0, colon)] = line.substr(colon + 2);
    start = end + 1;
  }
  return out;
}

}  // namespace

bool same_config(const std::map<std::string, std::string>& meta, const std::string& config_yaml,
                 const std::string& defaults_yaml) {
  const auto hash = meta.find("config_hash");
  if (hash != meta.end() && hash->second == config_hash(config_yaml)) return true;
  const auto stored = meta.find("config");
  if (stored == meta.end()) return false;
  const auto have = value_map(stored->second), now = value_map(config_yaml);
  const auto defaults = value_map(defaults_yaml);
  for (const auto& [key, value] : have)
    if (!now.count(key) || now.at(key) != value) return false;
  for (const auto& [key, value] : now) {
    if (have.count(key)) continue;
    const auto d = defaults.find(key);
    if (d == defaults.end() || d->second != value) return false;
  }
  return true;
}

namespace {
constexpr const char* kMeasurementKeys[] = {"kernel.size", "kernel.sigma",  "reference",
                                            "bias.slope",  "bias.constant", "lp.grid",
                                            "lp.lo",       "lp.hi",         "lp.discretization",
                                            "lp.quantize", "lp.backend",    "lp.moment_box"};
}  // namespace

std::map<std::string, std::string> measurement_meta(const EvalSettings& s) {
  const auto& lp = s.technique.lp;
  return {{"kernel.size", std::to_string(s.kernel.size)},
          {"kernel.sigma", round_trip(s.kernel.sigma)},
          {"reference", reference_name(s.bias.reference)},
          {"bias.slope", round_trip(s.bias.slope)},
          {"bias.constant", round_trip(s.bias.constant)},
          {"lp.grid", std::to_string(lp.grid)},
          {"lp.lo", round_trip(lp.lo)},
          {"lp.hi", round_trip(lp.hi)},
          {"lp.discretization", lp.continuous ? "continuous" : "grid"},
          {"lp.quantize", lp.quantize ? "true" : "false"},
          {"lp.backend", s.technique.lp_backend},
          {"lp.moment_box", s.technique.lp_moment_box}};
}

std::string incomparable_key(const std::map<std::string, std::string>& a,
                             const std::map<std::string, std::string>& b) {
  auto value = [](const std::map<std::string, std::string>& m, const std::string& key) {
    const auto it = m.find(key);
    return it == m.end() ? std::string() : it->second;
  };
  if (value(a, "dataset") != value(b, "dataset")) return "dataset";
  if (a.count("lp.grid") && b.count("lp.grid")) {
    for (const char* key : kMeasurementKeys)
      if (value(a, key) != value(b, key)) return key;
    return "";
  }
  // An older database: its prose sentence holds the same settings (with %g's rounding).
  for (const char* key : {"reference", "settings"})
    if (value(a, key) != value(b, key)) return key;
  return "";
}

std::optional<LpGridIdentity> lp_grid_of(const std::map<std::string, std::string>& meta) {
  LpGridIdentity id;
  if (meta.count("lp.grid") && meta.count("lp.lo") && meta.count("lp.hi")) {
    id.grid = std::stoi(meta.at("lp.grid"));
    id.lo = std::stod(meta.at("lp.lo"));
    id.hi = std::stod(meta.at("lp.hi"));
    return id;
  }
  const auto settings = meta.find("settings");
  if (settings == meta.end()) return std::nullopt;
  const size_t at = settings->second.find("LP grid ");
  if (at == std::string::npos ||
      std::sscanf(settings->second.c_str() + at, "LP grid %d on [%lf, %lf]", &id.grid, &id.lo,
                  &id.hi) != 3)
    return std::nullopt;
  return id;
}

}  // namespace mb
