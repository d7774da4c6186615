#include "util/config.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>

#include "util/error.h"
#include "util/name_list.h"
#include "util/number_text.h"
#include "util/yaml_reader.h"

namespace mb {

namespace {
const char* type_name(OptionType type) {
  switch (type) {
    case OptionType::Integer:
      return "an integer";
    case OptionType::Number:
      return "a finite number";
    case OptionType::Boolean:
      return "true or false";
    case OptionType::String:
      return "a string";
    case OptionType::StringList:
      return "a list of strings";
    case OptionType::NumberList:
      return "a list of finite numbers";
    case OptionType::IntegerList:
      return "a list of integers";
  }
  return "";
}

// The shortest text that reads back as the same double: 2.4, not 2.3999999999999999.
std::string number_text(double v) {
  return round_trip(v);
}

std::string emit(const YAML::Node& node) {
  YAML::Emitter out;
  out.SetSeqFormat(YAML::Flow);
  out << node;
  return out.c_str();
}
// A list of numbers (or integers) from its items, each within [min, max]; an error names the key,
// the item and what was expected.
YAML::Node number_list(const std::vector<std::string>& items, const OptionSpec& s,
                       const std::string& origin) {
  const bool integers = s.type == OptionType::IntegerList;
  // Appended piece by piece: GCC 12 warns (-Warray-bounds, a false positive) on "[" + a temporary.
  std::string range = "[";
  range.append(number_text(s.min)).append(", ").append(number_text(s.max)).append("]");
  YAML::Node stored(YAML::NodeType::Sequence);
  for (size_t k = 0; k < items.size(); ++k) {
    const std::string where = origin + ": key '" + s.name + "': item " + std::to_string(k + 1) +
                              " '" + items[k] + "': expected ";
    if (integers) {
      int64_t v;
      if (!YAML::convert<int64_t>::decode(YAML::Node(items[k]), v) || v < s.min || v > s.max)
        throw InputError(where + "an integer in " + range);
      stored.push_back(v);
      continue;
    }
    double v;
    if (!YAML::convert<double>::decode(YAML::Node(items[k]), v) || !std::isfinite(v))
      throw InputError(where + "a finite number");
    if (v < s.min || v > s.max) throw InputError(where + "a number in " + range);
    stored.push_back(number_text(v));
  }
  return stored;
}

}  // namespace

OptionSpec measures_nothing(OptionSpec spec) {
  spec.effect = OptionEffect::None;
  return spec;
}

OptionSpec selects_runs(OptionSpec spec) {
  spec.effect = OptionEffect::Selects;
  return spec;
}

const char* effect_name(OptionEffect effect) {
  switch (effect) {
    case OptionEffect::Measures:
      return "measured";
    case OptionEffect::Selects:
      return "selects";
    case OptionEffect::None:
      return "no";
  }
  return "";
}

Config::Config(std::vector<OptionSpec> specs) : specs_(std::move(specs)) {
  for (const auto& s : specs_) assign(s.name, YAML::Load(s.default_value), "default");
}

const OptionSpec& Config::spec(const std::string& name) const {
  for (const auto& s : specs_)
    if (s.name == name) return s;
  throw std::logic_error("option '" + name + "' read but never declared");
}

std::string Config::canonical(const std::string& name) const {
  for (const auto& s : specs_)
    if (s.name == name) return name;
  std::vector<std::string> names;
  for (const auto& s : specs_) names.push_back(s.name);
  std::string hint = closest_match(name, names);
  throw InputError("unknown key '" + name + "'" +
                   (hint.empty() ? "" : " (did you mean '" + hint + "'?)"));
}

namespace {

[[noreturn]] void throw_unexpected(const std::string& origin, const std::string& name,
                                   const YAML::Node& node, const std::string& why) {
  std::string value = node.IsScalar() ? node.Scalar() : node.IsSequence() ? "a list" : "a map";
  throw InputError(origin + ": key '" + name + "': expected " + why + ", got '" + value + "'");
}

// The items of a list option: a YAML list of scalars, or one comma-separated scalar as --set
// gives it ("techniques=vsm,esm", "bounds.depths=0.2,0.5"); empty or null is the empty list.
std::vector<std::string> option_list_items(const YAML::Node& node, const OptionSpec& s,
                                           const std::string& origin) {
  std::vector<std::string> items;
  if (node.IsScalar() && !node.Scalar().empty()) {
    std::stringstream in(node.Scalar());
    for (std::string item; std::getline(in, item, ',');) items.push_back(item);
  } else if (node.IsSequence()) {
    for (const auto& item : node) {
      if (!item.IsScalar())
        throw InputError(origin + ": key '" + s.name + "': expected " + type_name(s.type) +
                         ", but item " + std::to_string(items.size() + 1) + " is a YAML " +
                         (item.IsMap() ? "map" : "list") +
                         " (quote items that hold ': ' or brackets, e.g. \"lp:z;z^2\")");
      items.push_back(item.Scalar());
    }
  } else if (!(node.IsNull() || (node.IsScalar() && node.Scalar().empty()))) {
    throw_unexpected(origin, s.name, node, type_name(s.type));
  }
  return items;
}

}  // namespace

void Config::assign(const std::string& name, const YAML::Node& node, const std::string& origin) {
  const OptionSpec& s = spec(name);
  auto bad = [&](const std::string& why) { throw_unexpected(origin, name, node, why); };
  auto check_choice = [&](const std::string& v) {
    if (s.choices.empty()) return;
    for (const auto& c : s.choices)
      if (c == v) return;
    const std::string all = joined(s.choices, ", ");
    std::string hint = closest_match(v, s.choices);
    throw InputError(origin + ": key '" + name + "': unknown value '" + v + "'" +
                     (hint.empty() ? "" : " (did you mean '" + hint + "'?)") + "; valid: " + all);
  };
  auto list_items = [&] { return option_list_items(node, s, origin); };
  YAML::Node stored;
  switch (s.type) {
    case OptionType::Integer: {
      int64_t v;
      if (!node.IsScalar() || !YAML::convert<int64_t>::decode(node, v)) bad(type_name(s.type));
      if (v < s.min || v > s.max)
        bad("an integer in [" + number_text(s.min) + ", " + number_text(s.max) + "]");
      stored = YAML::Node(v);
      break;
    }
    case OptionType::Number: {
      double v;
      if (!node.IsScalar() || !YAML::convert<double>::decode(node, v) || !std::isfinite(v))
        bad(type_name(s.type));
      if (v < s.min || v > s.max)
        bad("a number in [" + number_text(s.min) + ", " + number_text(s.max) + "]");
      stored = YAML::Node(number_text(v));
      break;
    }
    case OptionType::Boolean: {
      bool v;
      if (!node.IsScalar() || !YAML::convert<bool>::decode(node, v)) bad(type_name(s.type));
      stored = YAML::Node(v ? "true" : "false");
      break;
    }
    case OptionType::String:
      if (!node.IsScalar()) bad(type_name(s.type));
      check_choice(node.Scalar());
      stored = YAML::Node(node.Scalar());
      break;
    case OptionType::StringList:
      stored = YAML::Node(YAML::NodeType::Sequence);
      for (const auto& item : list_items()) {
        check_choice(item);
        stored.push_back(item);
      }
      break;
    case OptionType::NumberList:
    case OptionType::IntegerList:
      stored = number_list(list_items(), s, origin);
      break;
  }
  values_[name] = Value{stored, origin};
}

void Config::flatten(const YAML::Node& node, const std::string& prefix, const std::string& file) {
  for (auto it = node.begin(); it != node.end(); ++it) {
    std::string key = prefix.empty() ? it->first.Scalar() : prefix + "." + it->first.Scalar();
    YAML::Mark mark = it->first.Mark();
    std::string where = located(file, mark.line + 1, mark.column + 1, "");
    where.resize(where.size() - 2);  // drop the ": " that `located` appends before a message
    bool declared = false, is_prefix = false;
    for (const auto& s : specs_) {
      declared |= s.name == key;
      is_prefix |= s.name.rfind(key + ".", 0) == 0;
    }
    if (it->second.IsMap() && is_prefix && !declared) {
      flatten(it->second, key, file);
    } else if (declared) {
      assign(key, it->second, where);
    } else {
      try {
        canonical(key);
      } catch (const InputError& e) {
        throw InputError(where + ": " + e.what());
      }
    }
  }
}

void Config::load_file(const std::string& file) {
  YAML::Node root = load_yaml_file(file, "config file");
  if (root.IsNull()) return;  // an empty file changes nothing
  if (!root.IsMap()) throw InputError(file + ": expected a YAML map of options at the top level");
  flatten(root, "", file);
}

void Config::set_node(const std::string& name, const YAML::Node& node, const std::string& origin) {
  assign(canonical(name), node, origin);
}

void Config::set(const std::string& assignment) {
  auto eq = assignment.find('=');
  if (eq == std::string::npos || eq == 0)
    throw InputError("--set '" + assignment + "': expected key=value");
  std::string key = assignment.substr(0, eq);
  try {
    key = canonical(key);
  } catch (const InputError& e) {
    throw InputError(std::string("--set: ") + e.what());
  }
  YAML::Node node;
  try {
    node = YAML::Load(assignment.substr(eq + 1));
  } catch (const YAML::Exception& e) {
    throw InputError("--set '" + assignment + "': " + e.msg);
  }
  if (node.IsNull()) node = YAML::Node(std::string());
  assign(key, node, "--set");
}

int64_t Config::integer(const std::string& name) const {
  if (spec(name).type != OptionType::Integer)
    throw std::logic_error(name + " is not an integer option");
  return values_.at(name).node.as<int64_t>();
}
double Config::number(const std::string& name) const {
  if (spec(name).type != OptionType::Number)
    throw std::logic_error(name + " is not a number option");
  return values_.at(name).node.as<double>();
}
bool Config::declares(const std::string& name) const {
  return std::any_of(specs_.begin(), specs_.end(),
                     [&](const OptionSpec& s) { return s.name == name; });
}

bool Config::boolean(const std::string& name) const {
  if (spec(name).type != OptionType::Boolean)
    throw std::logic_error(name + " is not a boolean option");
  return values_.at(name).node.as<bool>();
}
std::string Config::string(const std::string& name) const {
  if (spec(name).type != OptionType::String)
    throw std::logic_error(name + " is not a string option");
  return values_.at(name).node.Scalar();
}
std::vector<std::string> Config::strings(const std::string& name) const {
  if (spec(name).type != OptionType::StringList)
    throw std::logic_error(name + " is not a list option");
  std::vector<std::string> out;
  for (const auto& item : values_.at(name).node) out.push_back(item.Scalar());
  return out;
}

std::vector<double> Config::numbers(const std::string& name) const {
  if (spec(name).type != OptionType::NumberList)
    throw std::logic_error(name + " is not a number-list option");
  std::vector<double> out;
  for (const auto& item : values_.at(name).node) out.push_back(item.as<double>());
  return out;
}

std::vector<int64_t> Config::integers(const std::string& name) const {
  if (spec(name).type != OptionType::IntegerList)
    throw std::logic_error(name + " is not an integer-list option");
  std::vector<int64_t> out;
  for (const auto& item : values_.at(name).node) out.push_back(item.as<int64_t>());
  return out;
}

std::string Config::value_text(const std::string& name) const {
  spec(name);  // a key never declared is a logic error
  return emit(values_.at(name).node);
}

namespace {
// The documentation of an option with its range and choices, as --print-config and the README's
// tables show it.
std::string documented(const OptionSpec& s) {
  std::ostringstream out;
  out << s.doc;
  if (s.type == OptionType::Integer || s.type == OptionType::Number ||
      s.type == OptionType::NumberList || s.type == OptionType::IntegerList) {
    if (std::isfinite(s.min) || std::isfinite(s.max))
      out << " Range [" << number_text(s.min) << ", " << number_text(s.max) << "].";
  }
  if (!s.choices.empty()) {
    out << " One of:";
    for (const auto& c : s.choices) out << " " << c;
    out << ".";
  }
  return out.str();
}
}  // namespace

std::string Config::to_yaml() const {
  std::ostringstream out;
  for (const auto& s : specs_)
    out << "# " << documented(s) << "\n" << s.name << ": " << emit(values_.at(s.name).node) << "\n";
  return out.str();
}

std::vector<std::string> Config::non_default() const {
  std::vector<std::string> out;
  for (const auto& s : specs_) {
    Config defaults_only({s});
    std::string now = emit(values_.at(s.name).node);
    if (now != emit(defaults_only.values_.at(s.name).node)) out.push_back(s.name + ": " + now);
  }
  return out;
}

std::string Config::options_markdown() const {
  std::ostringstream out;
  out << "| key | type | default | identity | meaning |\n|---|---|---|---|---|\n";
  for (const auto& s : specs_)
    out << "| `" << s.name << "` | " << type_name(s.type) << " | `" << s.default_value << "` | "
        << effect_name(s.effect) << " | " << documented(s) << " |\n";
  return out.str();
}

}  // namespace mb
