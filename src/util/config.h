#pragma once
// Command configuration: every option is declared once (name, type, default, range, doc, what it
// is to a run's identity) in a table that drives validation, `--print-config` and the README's
// option list (docs/design.md §Style, after HiGHS). A key in a file or `--set` that is not
// declared is an error naming file and line.
#include <yaml-cpp/yaml.h>

#include <cstdint>
#include <limits>
#include <map>
#include <string>
#include <vector>

namespace mb {

enum class OptionType { Integer, Number, Boolean, String, StringList, NumberList, IntegerList };

// What an option is to a run's identity (docs/sweeps.md "Identity"). Most options change a
// measured number, so that is the default; a record that does not says so with one of the helpers
// below, and every positional initializer stays as it is.
enum class OptionEffect {
  Measures,  // changes a measured number: `sweep --resume`, `merge` and `report` compare it
  Selects,   // chooses which candidates or rows a sweep measures, not how (catalog, sample,
             // screen.*): a resume and a merge compare it, the series of one report may differ
  None,      // changes no measured number (threads, images, plot): nothing compares it
};

struct OptionSpec {
  std::string
      name;  // dotted, e.g. "raster.threads"; a YAML file may nest it as raster: {threads: }
  OptionType type;
  std::string default_value;  // YAML text
  std::string doc;
  double min =
      -std::numeric_limits<double>::infinity();  // numbers, integers, each item of a number list
  double max = std::numeric_limits<double>::infinity();
  std::vector<std::string> choices;  // for strings (and string lists): the allowed values, if any
  OptionEffect effect = OptionEffect::Measures;
};

// `spec`, declared as changing no measured number (OptionEffect::None).
OptionSpec measures_nothing(OptionSpec spec);
// `spec`, declared as choosing what a sweep measures (OptionEffect::Selects).
OptionSpec selects_runs(OptionSpec spec);
// "measured", "selects" or "no": the options tables' identity column.
const char* effect_name(OptionEffect effect);

class Config {
 public:
  explicit Config(std::vector<OptionSpec> specs);

  // Reads a YAML file; nested maps are flattened into dotted keys.
  void load_file(const std::string& file);
  // "key=value" as given to --set; the value is parsed as YAML.
  void set(const std::string& assignment);
  // A value given another way (a command's own flag, e.g. solve --grid), validated as --set's;
  // `origin` names it in errors.
  void set_node(const std::string& name, const YAML::Node& node, const std::string& origin);

  int64_t integer(const std::string& name) const;
  double number(const std::string& name) const;
  bool boolean(const std::string& name) const;
  std::string string(const std::string& name) const;
  std::vector<std::string> strings(const std::string& name) const;
  std::vector<double> numbers(const std::string& name) const;    // each item within [min, max]
  std::vector<int64_t> integers(const std::string& name) const;  // each item within [min, max]
  // The value as to_yaml writes it ("2.4", "[a, b]"); any option type.
  std::string value_text(const std::string& name) const;

  // The effective configuration as YAML that `load_file` reads back, one documented key a line.
  std::string to_yaml() const;
  // "key: value" for every option whose value differs from its default (for report headers).
  std::vector<std::string> non_default() const;
  const std::vector<OptionSpec>& specs() const { return specs_; }
  // Whether `name` is one of this configuration's options (a command declares only what it reads).
  bool declares(const std::string& name) const;
  // A markdown table of all options (for the README).
  std::string options_markdown() const;

 private:
  struct Value {
    YAML::Node node;
    std::string origin;  // "default", "file:line" or "--set"
  };
  const OptionSpec& spec(const std::string& name) const;
  void assign(const std::string& name, const YAML::Node& node, const std::string& origin);
  void flatten(const YAML::Node& node, const std::string& prefix, const std::string& file);
  std::string canonical(const std::string& name) const;

  std::vector<OptionSpec> specs_;
  std::map<std::string, Value> values_;
};

}  // namespace mb
