#include "sweep/run_identity.h"

#include <cstdint>
#include <cstdio>

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

bool same_config(const std::map<std::string, std::string>& meta, const std::string& config_yaml) {
  const auto hash = meta.find("config_hash");
  if (hash != meta.end() && hash->second == config_hash(config_yaml)) return true;
  const auto stored = meta.find("config");
  return stored != meta.end() && config_values(stored->second) == config_values(config_yaml);
}

}  // namespace mb
