#include "util/yaml_reader.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "util/error.h"
#include "util/name_list.h"

namespace mb {

namespace {
std::string quoted(const YAML::Node& node) {
  if (node.IsScalar()) return "'" + node.Scalar() + "'";
  if (node.IsSequence()) return "a list";
  if (node.IsMap()) return "a map";
  return "nothing";
}
std::string range_text(double min, double max) {
  auto text = [](double v) {
    std::ostringstream s;
    s << v;
    return s.str();
  };
  return "[" + text(min) + ", " + text(max) + "]";
}
}  // namespace

namespace {
void check_duplicate_keys(const YAML::Node& node, const std::string& file) {
  if (node.IsMap()) {
    std::set<std::string> seen;
    for (const auto& item : node) {
      if (item.first.IsScalar() && !seen.insert(item.first.Scalar()).second)
        throw InputError(located(file, item.first.Mark().line + 1, item.first.Mark().column + 1,
                                 "key '" + item.first.Scalar() + "' is given twice in one map"));
      check_duplicate_keys(item.second, file);
    }
  } else if (node.IsSequence()) {
    for (const auto& item : node) check_duplicate_keys(item, file);
  }
}
}  // namespace

YAML::Node load_yaml_file(const std::string& file, const std::string& what) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!fs::exists(file, ec)) throw InputError(file + ": " + what + " not found");
  if (fs::is_directory(file, ec))
    throw InputError(file + ": is a directory, expected a " + what + " (YAML)");
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  if (!in.good() && !in.eof()) throw InputError(file + ": cannot read the " + what);
  YAML::Node root;
  try {
    root = YAML::Load(text.str());
  } catch (const YAML::Exception& e) {
    throw InputError(located(file, e.mark.line + 1, e.mark.column + 1, "YAML syntax: " + e.msg));
  }
  check_duplicate_keys(root, file);
  return root;
}

YamlMap YamlMap::load_file(const std::string& file, const std::string& what) {
  YAML::Node root = load_yaml_file(file, what);
  if (!root.IsMap()) throw InputError(file + ": expected a YAML map at the top level");
  return YamlMap(root, file, "");
}

YamlMap::YamlMap(YAML::Node node, std::string file, std::string path)
    : node_(std::move(node)), file_(std::move(file)), path_(std::move(path)) {}

bool YamlMap::has(const std::string& key) const {
  return bool(node_[key]);
}

std::string YamlMap::describe(const std::string& key) const {
  return "key '" + (path_.empty() ? key : path_ + "." + key) + "'";
}

namespace {

// The mark of the key itself, so the line number points at the offending key; the map's own when
// the key is absent or "".
YAML::Mark mark_of(const YAML::Node& node, const std::string& key) {
  YAML::Mark mark = node.Mark();
  if (!key.empty())
    for (auto it = node.begin(); it != node.end(); ++it)
      if (it->first.Scalar() == key) mark = it->first.Mark();
  return mark;
}

}  // namespace

void YamlMap::fail(const std::string& key, const std::string& message) const {
  const YAML::Mark mark = mark_of(node_, key);
  std::string what =
      key.empty() ? (path_.empty() ? "" : "'" + path_ + "': ") : describe(key) + ": ";
  throw InputError(located(file_, mark.line + 1, mark.column + 1, what + message));
}

std::string YamlMap::where(const std::string& key) const {
  const YAML::Mark mark = mark_of(node_, key);
  return file_ + ":" + std::to_string(mark.line + 1) + ":" + std::to_string(mark.column + 1);
}

YAML::Node YamlMap::at(const std::string& key) {
  read_.insert(key);
  return node_[key];
}

std::optional<double> YamlMap::number(const std::string& key, double min, double max) {
  YAML::Node v = at(key);
  if (!v) return std::nullopt;
  double x;
  if (!v.IsScalar() || !YAML::convert<double>::decode(v, x) || !std::isfinite(x))
    fail(key, "expected a finite number, got " + quoted(v));
  if (x < min || x > max)
    fail(key, "expected a number in " + range_text(min, max) + ", got " + v.Scalar());
  return x;
}

double YamlMap::number(const std::string& key, double fallback, double min, double max) {
  return number(key, min, max).value_or(fallback);
}

std::optional<int64_t> YamlMap::integer(const std::string& key, int64_t min, int64_t max) {
  YAML::Node v = at(key);
  if (!v) return std::nullopt;
  int64_t x;
  if (!v.IsScalar() || !YAML::convert<int64_t>::decode(v, x))
    fail(key, "expected an integer, got " + quoted(v));
  if (x < min || x > max)
    fail(key, "expected an integer in [" + std::to_string(min) + ", " + std::to_string(max) +
                  "], got " + v.Scalar());
  return x;
}

int64_t YamlMap::integer(const std::string& key, int64_t fallback, int64_t min, int64_t max) {
  return integer(key, min, max).value_or(fallback);
}

bool YamlMap::boolean(const std::string& key, bool fallback) {
  YAML::Node v = at(key);
  if (!v) return fallback;
  bool x;
  if (!v.IsScalar() || !YAML::convert<bool>::decode(v, x))
    fail(key, "expected true or false, got " + quoted(v));
  return x;
}

std::optional<std::string> YamlMap::string(const std::string& key) {
  YAML::Node v = at(key);
  if (!v) return std::nullopt;
  if (!v.IsScalar()) fail(key, "expected a string, got " + quoted(v));
  return v.Scalar();
}

std::optional<std::vector<double>> YamlMap::numbers(const std::string& key, size_t count) {
  YAML::Node v = at(key);
  if (!v) return std::nullopt;
  std::string expected =
      count ? "a list of " + std::to_string(count) + " numbers" : "a list of numbers";
  if (!v.IsSequence() || (count && v.size() != count))
    fail(key, "expected " + expected + ", got " + quoted(v));
  std::vector<double> out;
  for (const auto& item : v) {
    double x;
    if (!item.IsScalar() || !YAML::convert<double>::decode(item, x) || !std::isfinite(x))
      fail(key, "expected " + expected + ", got element " + quoted(item));
    out.push_back(x);
  }
  return out;
}

std::vector<std::string> YamlMap::strings(const std::string& key) {
  YAML::Node v = at(key);
  if (!v) return {};
  if (!v.IsSequence()) fail(key, "expected a list of strings, got " + quoted(v));
  std::vector<std::string> out;
  for (const auto& item : v) {
    if (!item.IsScalar()) fail(key, "expected a list of strings, got element " + quoted(item));
    out.push_back(item.Scalar());
  }
  return out;
}

YamlMap YamlMap::map(const std::string& key) {
  YAML::Node v = at(key);
  if (!v)
    return YamlMap(YAML::Node(YAML::NodeType::Map), file_, path_.empty() ? key : path_ + "." + key);
  if (!v.IsMap()) fail(key, "expected a map, got " + quoted(v));
  return YamlMap(v, file_, path_.empty() ? key : path_ + "." + key);
}

std::vector<YamlMap> YamlMap::maps(const std::string& key) {
  YAML::Node v = at(key);
  std::vector<YamlMap> out;
  if (!v) return out;
  if (!v.IsSequence()) fail(key, "expected a list of maps, got " + quoted(v));
  std::string base = path_.empty() ? key : path_ + "." + key;
  for (size_t i = 0; i < v.size(); ++i) {
    if (!v[i].IsMap())
      fail(key, "expected a list of maps, element " + std::to_string(i) + " is " + quoted(v[i]));
    out.emplace_back(v[i], file_, base + "[" + std::to_string(i) + "]");
  }
  return out;
}

bool YamlMap::is_sequence(const std::string& key) const {
  return node_[key] && node_[key].IsSequence();
}

void YamlMap::finish() const {
  std::vector<std::string> known(read_.begin(), read_.end());
  known.insert(known.end(), suggest_.begin(), suggest_.end());
  for (auto it = node_.begin(); it != node_.end(); ++it) {
    const std::string key = it->first.Scalar();
    if (read_.count(key)) continue;
    std::string hint = closest_match(key, known);
    std::string message = "unknown key '" + (path_.empty() ? key : path_ + "." + key) + "'";
    if (!hint.empty()) message += " (did you mean '" + hint + "'?)";
    const std::string all = joined(known, ", ");
    if (!all.empty()) message += "; valid keys here: " + all;
    YAML::Mark mark = it->first.Mark();
    throw InputError(located(file_, mark.line + 1, mark.column + 1, message));
  }
}

}  // namespace mb
