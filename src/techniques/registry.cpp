#include "techniques/registry.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "techniques/lp_options.h"
#include "util/error.h"
#include "util/number_text.h"

namespace mb {

namespace {

// Each technique file's row function, in registration order (the registry sorts the rows).
std::vector<std::vector<TechniqueRow> (*)()>& registered() {
  static std::vector<std::vector<TechniqueRow> (*)()> functions;
  return functions;
}

// The own options the rows of `families` read, once per key, in row order.
std::vector<const TechniqueOption*> row_options(std::initializer_list<TechniqueFamily> families) {
  std::vector<const TechniqueOption*> options;
  for (const TechniqueRow& row : technique_registry()) {
    if (std::find(families.begin(), families.end(), row.family) == families.end()) continue;
    for (const TechniqueOption* o : row.options)
      if (std::find_if(options.begin(), options.end(), [&](const TechniqueOption* known) {
            return known->spec.name == o->spec.name;
          }) == options.end())
        options.push_back(o);
  }
  return options;
}

std::vector<const TechniqueOption*> hard_options() {
  return row_options({TechniqueFamily::HardShadow});
}

std::vector<const TechniqueOption*> all_options() {
  return row_options({TechniqueFamily::HardShadow, TechniqueFamily::SoftShadow,
                      TechniqueFamily::Transmittance, TechniqueFamily::Scattering});
}

bool declares(const Config& config, const std::string& key) {
  const std::vector<OptionSpec>& specs = config.specs();
  return std::any_of(specs.begin(), specs.end(),
                     [&](const OptionSpec& s) { return s.name == key; });
}

void check_moment_bias(const std::string& key, double alpha) {
  if (!(alpha >= 0 && alpha < 1))
    throw InputError(key + ": expected alpha in [0, 1), got " + round_trip(alpha));
}

std::string names_of(TechniqueFamily family) {
  std::string names;
  for (const TechniqueRow* row : family_rows(family))
    names += (names.empty() ? "" : ", ") + row->display_name();
  return names;
}

}  // namespace

TechniqueRegistration::TechniqueRegistration(std::vector<TechniqueRow> (*rows)()) {
  registered().push_back(rows);
}

std::string family_title(TechniqueFamily family) {
  switch (family) {
    case TechniqueFamily::HardShadow:
      return "hard shadows";
    case TechniqueFamily::SoftShadow:
      return "soft shadows";
    case TechniqueFamily::Transmittance:
      return "transmittance";
    case TechniqueFamily::Scattering:
      return "single scattering";
  }
  return "";
}

bool TechniqueRow::matches(std::string_view given) const {
  return prefix() ? given.substr(0, name.size()) == name : given == name;
}

std::string TechniqueRow::display_name() const {
  return prefix() ? name + parameter : name;
}

const std::vector<TechniqueRow>& technique_registry() {
  static const std::vector<TechniqueRow> table = [] {
    std::vector<TechniqueRow> rows;
    for (auto rows_of : registered())
      for (TechniqueRow& row : rows_of()) rows.push_back(std::move(row));
    std::stable_sort(rows.begin(), rows.end(), [](const TechniqueRow& a, const TechniqueRow& b) {
      return std::pair(a.family, a.rank) < std::pair(b.family, b.rank);
    });
    return rows;
  }();
  return table;
}

std::vector<const TechniqueRow*> family_rows(TechniqueFamily family) {
  std::vector<const TechniqueRow*> rows;
  for (const TechniqueRow& row : technique_registry())
    if (row.family == family) rows.push_back(&row);
  return rows;
}

const TechniqueRow* find_technique(std::string_view name, std::optional<TechniqueFamily> family) {
  const TechniqueRow* found = nullptr;
  for (const TechniqueRow& row : technique_registry())
    if ((!family || row.family == *family) && row.matches(name) &&
        (!found || row.name.size() > found->name.size()))
      found = &row;
  return found;
}

RowRole technique_role(std::string_view name) {
  const TechniqueRow* row = find_technique(name);
  return row ? row->role : RowRole::Technique;
}

bool technique_solves_lp(std::string_view name) {
  const TechniqueRow* row = find_technique(name);
  return row && row->solves_lp;
}

const std::string& role_name(TechniqueFamily family, RowRole role) {
  for (const TechniqueRow* row : family_rows(family))
    if (row->role == role) return row->name;
  throw std::logic_error("no row of " + family_title(family) + " has the role asked for");
}

const TechniqueRow& technique_row(const std::string& name, TechniqueFamily family) {
  return technique_row(name, {family});
}

const TechniqueRow& technique_row(const std::string& name,
                                  std::initializer_list<TechniqueFamily> families) {
  for (TechniqueFamily family : families)
    if (const TechniqueRow* row = find_technique(name, family)) return *row;
  const TechniqueRow* row = find_technique(name);
  std::vector<std::string> names;
  std::string valid, titles;
  for (TechniqueFamily family : families) {
    for (const TechniqueRow* r : family_rows(family))
      if (!r->prefix()) names.push_back(r->name);
    valid += (valid.empty() ? "" : "; ") +
             (families.size() > 1 ? family_title(family) + ": " : std::string()) +
             names_of(family) +
             (family == TechniqueFamily::HardShadow
                  ? " (e.g. lp:power4, lp:trig4, lp:z;exp(-z);sin(pi z);z^3)"
                  : "");
    titles += (titles.empty() ? "" : " or ") + family_title(family);
  }
  const std::string guess = closest_match(name, names);
  throw InputError(
      "unknown technique '" + name + "'" +
      (row ? " (a technique of " + family_title(row->family) + ", expected one of " + titles + ")"
           : "") +
      (guess.empty() ? "" : " (did you mean '" + guess + "'?)") + "; valid: " + valid);
}

std::string default_techniques(TechniqueFamily family) {
  std::string list;
  for (const TechniqueRow* row : family_rows(family))
    if (row->default_run)
      list += (list.empty() ? "" : ", ") + (row->prefix() ? row->example : row->name);
  return "[" + list + "]";
}

std::vector<SweepReference> sweep_references(TechniqueFamily family) {
  std::vector<SweepReference> references;
  for (const TechniqueRow* row : family_rows(family))
    for (SweepReference reference : row->sweep_references) {
      if (reference.name.empty()) reference.name = row->name;
      references.push_back(std::move(reference));
    }
  return references;
}

std::string sweep_reference_list(TechniqueFamily family) {
  std::string list;
  for (const SweepReference& reference : sweep_references(family))
    list += (list.empty() ? "" : ", ") + reference.name;
  return "[" + list + "]";
}

std::string verify_default_list() {
  std::vector<const TechniqueRow*> rows;
  for (const TechniqueRow& row : technique_registry())
    if (row.verify && row.verify_place > 0) rows.push_back(&row);
  std::stable_sort(rows.begin(), rows.end(), [](const TechniqueRow* a, const TechniqueRow* b) {
    return a->verify_place < b->verify_place;
  });
  std::string list;
  for (const TechniqueRow* row : rows) list += (list.empty() ? "" : ", ") + row->name;
  return "[" + list + "]";
}

std::vector<OptionSpec> technique_option_specs(std::initializer_list<TechniqueFamily> families) {
  std::vector<OptionSpec> specs;
  for (const TechniqueOption* o : row_options(families)) specs.push_back(o->spec);
  return specs;
}

std::string technique_option_text(std::initializer_list<TechniqueFamily> families,
                                  const TechniqueParams& params) {
  std::string text;
  for (const TechniqueOption* o : row_options(families))
    text += (text.empty() ? "" : ", ") + o->spec.name + " " +
            (o->spec.type == OptionType::Integer ? std::to_string(params.integer(*o))
                                                 : round_trip(params.number(*o)));
  return text;
}

void read_technique_options(const Config& config, TechniqueParams& params) {
  for (const TechniqueOption* o : all_options())
    if (declares(config, o->spec.name))
      params.set(*o, o->spec.type == OptionType::Integer ? double(config.integer(o->spec.name))
                                                         : config.number(o->spec.name));
}

void set_moment_bias(TechniqueParams& params, double alpha) {
  for (const TechniqueOption* o : hard_options())
    if (o->moment_bias) params.set(*o, alpha);
}

TechniqueParams::TechniqueParams() {
  // Every record's default (written there only), parsed once.
  static const TechniqueParams defaults = [] {
    TechniqueParams p(Defaults{});
    std::vector<OptionSpec> specs;
    for (const TechniqueOption* o : all_options()) specs.push_back(o->spec);
    const Config config(specs);
    for (const TechniqueOption* o : all_options()) {
      if (o->spec.type != OptionType::Number && o->spec.type != OptionType::Integer)
        throw std::logic_error(o->spec.name + ": a technique option is a number or an integer");
      p.values_[o->spec.name] = {o->spec.type, o->spec.type == OptionType::Integer
                                                   ? double(config.integer(o->spec.name))
                                                   : config.number(o->spec.name)};
    }
    read_lp_params(Config(lp_option_specs()), p);
    return p;
  }();
  *this = defaults;
}

const TechniqueParams::Value& TechniqueParams::value(std::string_view key, OptionType type) const {
  const auto it = values_.find(key);
  if (it == values_.end())
    throw std::logic_error("technique option '" + std::string(key) +
                           "': no technique row declares it");
  if (it->second.type != type)
    throw std::logic_error("technique option '" + std::string(key) + "' is " +
                           (it->second.type == OptionType::Integer ? "an integer" : "a number"));
  return it->second;
}

double TechniqueParams::number(std::string_view key) const {
  return value(key, OptionType::Number).value;
}

int TechniqueParams::integer(std::string_view key) const {
  return int(value(key, OptionType::Integer).value);
}

double TechniqueParams::number(const TechniqueOption& option) const {
  return number(option.spec.name);
}

int TechniqueParams::integer(const TechniqueOption& option) const {
  return integer(option.spec.name);
}

void TechniqueParams::set(std::string_view key, double v) {
  const auto it = values_.find(key);
  if (it == values_.end())
    throw std::logic_error("technique option '" + std::string(key) +
                           "': no technique row declares it");
  if (it->second.type == OptionType::Integer && v != std::round(v))
    throw std::logic_error("technique option '" + std::string(key) + "' is an integer, got " +
                           round_trip(v));
  it->second.value = v;
}

void TechniqueParams::set(const TechniqueOption& option, double v) {
  set(option.spec.name, v);
}

std::vector<std::string> closed_form_technique_names() {
  std::vector<std::string> names;
  for (const TechniqueRow* row : family_rows(TechniqueFamily::HardShadow))
    if (!row->prefix()) names.push_back(row->name);
  return names;
}

std::string technique_table_markdown() {
  std::string out;
  for (TechniqueFamily family : {TechniqueFamily::HardShadow, TechniqueFamily::SoftShadow,
                                 TechniqueFamily::Transmittance, TechniqueFamily::Scattering}) {
    const std::vector<const TechniqueRow*> rows = family_rows(family);
    if (rows.empty()) continue;
    std::string title = family_title(family);
    title[0] = char(std::toupper(title[0]));
    out += (out.empty() ? "" : "\n") + title +
           ":\n\n| technique | what it is | storage | darkening bound | options |\n"
           "|---|---|---|---|---|\n";
    for (const TechniqueRow* row : rows) {
      std::string options;
      for (const TechniqueOption* o : row->options)
        options += (options.empty() ? "`" : ", `") + o->spec.name + "`";
      for (const std::string& key : row->family_options)
        options += (options.empty() ? "`" : ", `") + key + "`";
      out += "| `" + row->display_name() + "` | " + row->summary + " | " + row->storage + " | " +
             row->bound + " | " + (options.empty() ? "-" : options) + " |\n";
    }
  }
  return out;
}

std::unique_ptr<Technique> make_technique(const std::string& name, const TechniqueParams& p) {
  for (const TechniqueOption* o : hard_options())
    if (o->moment_bias) check_moment_bias(o->spec.name, p.number(*o));
  return technique_row(name, TechniqueFamily::HardShadow).make(name, p);
}

}  // namespace mb
