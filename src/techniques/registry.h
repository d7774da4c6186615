#pragma once
// The technique registry: one row per technique (docs/design.md §Layout). A row names the
// technique, says what it stores and what bound it proves, declares the options it reads (bound
// to fields of TechniqueParams, so code reads fields and never keys), and makes it. `eval`,
// `sweep` references, `verify` targets, `solve --technique/--alpha`, `momentbench options` and the
// README's technique list all read this table. Adding a technique: its file, one factory
// declaration and one row in registry.cpp, a field of TechniqueParams per new option, its test.
#include <memory>
#include <optional>
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

// How `verify` checks a technique against the LP of its own basis (docs/reference.md §6).
struct VerifyRecipe {
  enum class Judge {
    Exact,       // double, alpha = 0: must match the sharp bound
    StorageBox,  // float32 / 16-bit: a lower bound of Problem 1 over its storage's moment box
    LowerBound,  // a valid, not sharp, bound: never above the LP
    Exceedance,  // not a lower bound: how often and how far above the sharp bound
  };
  Judge judge = Judge::Exact;
  // The LP's basis for these parameters (the technique's own functions, rescaled where that keeps
  // the LP's columns representable), and the LP's interval.
  std::vector<std::string> (*lp_basis)(const TechniqueParams&) = nullptr;
  double lo = 0, hi = 1;
  bool on_r = false;              // Problem 1 on all of R (Hamburger, VSM)
  bool cantelli_support = false;  // VSM: Cantelli's two extremal points join the LP's points
  double TechniqueParams::*alpha = nullptr;  // storage rows: their moment bias
};

struct TechniqueEntry {
  std::string name;  // as given in `techniques`; "lp:" matches every "lp:<basis>"
  std::string summary;
  std::string storage;  // the moment map's format
  std::string bound;    // its darkening bound (docs/reference.md §3) and why
  std::string reference = "the view's reference (PCF)";
  std::vector<const TechniqueOption*> options;  // the options it reads (registry.cpp)
  std::unique_ptr<Technique> (*make)(const std::string& name, const TechniqueParams& params);
  std::optional<VerifyRecipe> verify = std::nullopt;  // none: no LP ground truth
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
