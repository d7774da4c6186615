#include "sweep/run_identity.h"

#include <cstdint>
#include <cstdio>
#include <set>
#include <string>

namespace mb {

namespace {

const OptionSpec* find_spec(const std::vector<OptionSpec>& specs, const std::string& key) {
  for (const auto& s : specs)
    if (s.name == key) return &s;
  return nullptr;
}

// A line's key is compared unless its record says it changes no measured number; a key no record
// declares (an option since removed) is compared, so its run stays told apart.
bool compared(const std::vector<OptionSpec>& specs, const std::string& key) {
  const OptionSpec* s = find_spec(specs, key);
  return !s || s->effect != OptionEffect::None;
}

// "key: value" lines of a config YAML as a map, without comments.
Meta value_map(const std::string& yaml) {
  Meta out;
  size_t start = 0;
  while (start < yaml.size()) {
    size_t end = yaml.find('\n', start);
    if (end == std::string::npos) end = yaml.size();
    const std::string line = yaml.substr(start, end - start);
    const size_t colon = line.find(": ");
    if (!line.empty() && line[0] != '#' && colon != std::string::npos)
      out[line.substr(0, colon)] = line.substr(colon + 2);
    start = end + 1;
  }
  return out;
}

std::string default_text(const OptionSpec& spec) {
  return Config({spec}).value_text(spec.name);
}

}  // namespace

std::string config_values(const std::string& yaml, const std::vector<OptionSpec>& specs) {
  std::string kept;
  size_t start = 0;
  while (start < yaml.size()) {
    size_t end = yaml.find('\n', start);
    if (end == std::string::npos) end = yaml.size();
    const std::string line = yaml.substr(start, end - start);
    if (!line.empty() && line[0] != '#' && compared(specs, line.substr(0, line.find(':'))))
      kept += line + "\n";
    start = end + 1;
  }
  return kept;
}

std::string config_hash(const std::string& config_yaml, const std::vector<OptionSpec>& specs) {
  uint64_t h = 1469598103934665603ull;
  for (unsigned char c : config_values(config_yaml, specs)) h = (h ^ c) * 1099511628211ull;
  char buffer[24];
  std::snprintf(buffer, sizeof buffer, "%016llx", (unsigned long long)h);
  return buffer;
}

std::vector<OptionDifference> config_differences(const Meta& meta, const std::string& config_yaml,
                                                 const std::vector<OptionSpec>& specs) {
  const auto hash = meta.find("config_hash");
  if (hash != meta.end() && hash->second == config_hash(config_yaml, specs)) return {};
  const auto stored = meta.find("config");
  if (stored == meta.end()) return {{"config", "(not stored)", "(given)"}};
  const Meta have = value_map(stored->second), now = value_map(config_yaml);
  std::vector<OptionDifference> out;
  for (const auto& [key, value] : have) {
    if (!compared(specs, key)) continue;
    const auto it = now.find(key);
    // A declared key the other config lacks (written before the option existed: merge compares
    // two stored configs, either may be the older) counts at its default, as below.
    const OptionSpec* spec = find_spec(specs, key);
    const std::string after = it != now.end() ? it->second
                              : spec          ? default_text(*spec)
                                              : "(no such option)";
    if (after != value) out.push_back({key, value, after});
  }
  for (const auto& [key, value] : now) {
    if (have.count(key) || !compared(specs, key)) continue;
    const OptionSpec* spec = find_spec(specs, key);
    const std::string before = spec ? default_text(*spec) : "(no such option)";
    if (before != value) out.push_back({key, before, value});
  }
  return out;
}

bool same_config(const Meta& meta, const std::string& config_yaml,
                 const std::vector<OptionSpec>& specs) {
  return config_differences(meta, config_yaml, specs).empty();
}

Meta measurement_meta(const std::string& config_yaml, const std::vector<OptionSpec>& specs) {
  const Meta values = value_map(config_yaml);
  Meta out;
  for (const auto& s : specs) {
    if (s.effect != OptionEffect::Measures) continue;
    const auto it = values.find(s.name);
    out[s.name] = it != values.end() ? it->second : default_text(s);
  }
  return out;
}

std::string measurement_value(const Meta& meta, const std::string& key,
                              const std::vector<OptionSpec>& specs) {
  if (const auto it = meta.find(key); it != meta.end()) return it->second;
  if (const auto config = meta.find("config"); config != meta.end()) {
    const Meta stored = value_map(config->second);
    if (const auto it = stored.find(key); it != stored.end()) return it->second;
  }
  const OptionSpec* spec = find_spec(specs, key);
  return spec ? default_text(*spec) : "";
}

std::string configured_value(const Meta& meta, const std::string& key,
                             const std::vector<OptionSpec>& specs) {
  if (const auto config = meta.find("config"); config != meta.end()) {
    const Meta stored = value_map(config->second);
    if (const auto it = stored.find(key); it != stored.end()) return it->second;
  }
  const OptionSpec* spec = find_spec(specs, key);
  return spec ? default_text(*spec) : "";
}

std::vector<OptionDifference> measurement_differences(const Meta& a, const Meta& b,
                                                      const std::vector<OptionSpec>& specs) {
  std::vector<OptionDifference> out;
  auto compare = [&](const std::string& key) {
    const std::string x = measurement_value(a, key, specs), y = measurement_value(b, key, specs);
    if (x != y) out.push_back({key, x, y});
  };
  compare("dataset");  // the dataset's name (a sweep stores it, whatever file named it)
  for (const auto& s : specs)
    if (s.effect == OptionEffect::Measures && s.name != "dataset") compare(s.name);
  // A database from before the measurement keys: its prose sentence holds the same settings
  // (with %g's rounding).
  if (!a.count("lp.grid") || !b.count("lp.grid")) {
    const auto x = a.find("settings"), y = b.find("settings");
    const std::string sx = x == a.end() ? "" : x->second, sy = y == b.end() ? "" : y->second;
    if (sx != sy) out.push_back({"settings", sx, sy});
  }
  return out;
}

std::string differences_text(const std::vector<OptionDifference>& differences,
                             const std::string& first, const std::string& second) {
  std::string text;
  for (const auto& d : differences)
    text += (text.empty() ? "" : "; ") + d.key + " is " + d.first + " in " + first + ", " +
            d.second + " in " + second;
  return text;
}

std::optional<LpGridIdentity> lp_grid_of(const Meta& meta) {
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
