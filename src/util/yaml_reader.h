#pragma once
// Checked reading of YAML description files (scenes, datasets): every key must be read by the
// parser or it is an error naming file, line and key (docs/design.md §Style: "parse, then build").
#include <yaml-cpp/yaml.h>

#include <cstdint>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace mb {

// The YAML document of `file` (`what` names it in errors: "config file", "scene file"), refusing
// what yaml-cpp would accept silently or report vaguely: a missing file, a directory, an
// unreadable file, and a key given twice in one map (yaml-cpp keeps one of them).
YAML::Node load_yaml_file(const std::string& file, const std::string& what);

class YamlMap {
 public:
  // Loads a YAML file whose top level must be a map.
  static YamlMap load_file(const std::string& file, const std::string& what = "YAML file");
  YamlMap(YAML::Node node, std::string file, std::string path);

  const std::string& file() const { return file_; }
  // Where this map sits inside its file, e.g. "parts[2].transform" ("" at the top).
  const std::string& path() const { return path_; }
  bool has(const std::string& key) const;

  std::optional<double> number(const std::string& key, double min, double max);
  double number(const std::string& key, double fallback, double min, double max);
  std::optional<int64_t> integer(const std::string& key, int64_t min, int64_t max);
  int64_t integer(const std::string& key, int64_t fallback, int64_t min, int64_t max);
  bool boolean(const std::string& key, bool fallback);
  std::optional<std::string> string(const std::string& key);
  // A list of exactly `count` numbers (any length if count == 0).
  std::optional<std::vector<double>> numbers(const std::string& key, size_t count);
  std::vector<std::string> strings(const std::string& key);
  YamlMap map(const std::string& key);
  std::vector<YamlMap> maps(const std::string& key);
  // A scalar or a list: "scale: 2" and "scale: [1, 2, 1]" are both valid.
  bool is_sequence(const std::string& key) const;

  // Names offered as suggestions for a misspelled key without counting as read.
  void also_suggest(const std::vector<std::string>& keys) {
    suggest_.insert(keys.begin(), keys.end());
  }
  // Throws InputError for any key that no getter asked for, suggesting the closest known key.
  void finish() const;
  // An InputError located at `key` (or at the map itself when key is "").
  [[noreturn]] void fail(const std::string& key, const std::string& message) const;
  // "file:line:column" of `key` (of the map itself when it is absent), for errors found later.
  std::string where(const std::string& key) const;

 private:
  YAML::Node at(const std::string& key);
  std::string describe(const std::string& key) const;

  YAML::Node node_;
  std::string file_;
  std::string path_;
  std::set<std::string> read_;
  std::set<std::string> suggest_;
};

}  // namespace mb
