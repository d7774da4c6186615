#pragma once
// The technique registry: one row per technique (docs/design.md §Layout). A row names the
// technique, says what it stores and what bound it proves, declares the options it reads (bound
// to fields of TechniqueParams, so code reads fields and never keys), and makes it. `eval`,
// `sweep` references, `verify` targets, `solve --technique/--alpha`, `momentbench options` and the
// README's technique list all read this table. Adding a technique: its file, one factory
// declaration and one row in registry.cpp, a field of TechniqueParams per new option, its test.
#include <memory>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "techniques/technique.h"
#include "util/config.h"

namespace mb {

struct TechniqueOption {
  OptionSpec spec;
  std::variant<double TechniqueParams::*, int TechniqueParams::*> field;
  // An MSM moment bias alpha: must lie in [0, 1); `solve --alpha` replaces every one of them.
  bool moment_bias = false;
};

struct TechniqueEntry {
  std::string name;  // as given in `techniques`; "lp:" matches every "lp:<basis>"
  std::string summary;
  std::string storage;  // the moment map's format
  std::string bound;    // its darkening bound (docs/reference.md §3) and why
  std::string reference = "the view's reference (PCF)";
  std::vector<const TechniqueOption*> options;  // the options it reads (registry.cpp)
  std::unique_ptr<Technique> (*make)(const std::string& name, const TechniqueParams& params);
};

// Every technique, in the order documentation lists them.
const std::vector<TechniqueEntry>& technique_registry();
// The row of `name` ("lp:..." finds the LP row), or nullptr.
const TechniqueEntry* find_technique(std::string_view name);
// Every technique's option, once per key (shared keys such as esm.c appear in several rows).
std::vector<OptionSpec> technique_option_specs();
// Reads every technique option of `config` into `params`' fields, validated (InputError naming
// the key).
void read_technique_options(const Config& config, TechniqueParams& params);
// Sets every moment bias alpha of `params` (solve --alpha).
void set_moment_bias(TechniqueParams& params, double alpha);
// The README's technique list: a Markdown table of every row.
std::string technique_table_markdown();

}  // namespace mb
