#pragma once
// The technique registry: one row per technique of every family (docs/design.md §Layout). A row
// names the technique (or a family of names such as lp:<basis>), says which phenomenon it answers,
// what it stores and what darkening bound it proves, declares the options it reads, and makes it.
// Each technique's file declares its own row (TechniqueRegistration); `eval`, `oit`, `sweep`
// references and targets, `verify`, `solve --technique/--alpha`, `momentbench options` and the
// user guide's technique list all read this table, and test a row's properties, never its name.
// Adding a technique of any family: its file (its code and its row) and its test.
#include <initializer_list>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "techniques/technique.h"
#include "util/config.h"

namespace mb {

class SoftTechnique;
struct SoftSetup;
class OitTechnique;
struct OitParams;
class ScatterTechnique;
struct ScatterParams;

// The phenomenon a technique answers, in the order lists show them.
enum class TechniqueFamily { HardShadow, SoftShadow, Transmittance, Scattering };
// "hard shadows", "soft shadows", ... for lists and errors.
std::string family_title(TechniqueFamily family);

// A technique's own option, of any family: its record (key, type Number or Integer, default, range,
// doc), declared once in the technique's file and listed by the rows that read it. TechniqueParams
// holds a value for every such record; the technique reads it back by the record
// (`p.number(kEsmC)`). A family's shared options (soft.sat, oit.warp, scatter.max_distance) are the
// family's own records instead, named by the rows in `family_options`.
struct TechniqueOption {
  OptionSpec spec;
  // An MSM moment bias alpha: must lie in [0, 1); `solve --alpha` replaces every one of them.
  bool moment_bias = false;
  // A relaxation whose value 0 gives the sharp bound, as a moment bias 0 does (a beta blend, a
  // variance clamp): verify sets both to 0 for the rows it judges Exact (docs/reference.md §6).
  bool zero_is_sharp = false;
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
  // Hamburger's reconstruction from this many power moments on R (4 or 6; 0: none): verify also
  // judges its upper bound G + w_1 against the LP's, six moments over their rounding box.
  int hamburger_moments = 0;
  const TechniqueOption* alpha = nullptr;  // storage rows: their moment bias
  // The row's own option that verify sets to its verify.* value `verify_key` (a scale the LP can
  // represent; verify refuses a value given for the row's option itself).
  const TechniqueOption* replaced = nullptr;
  const char* verify_key = nullptr;
};

// How `verify` checks a transmittance row against the LP of the same information on seeded random
// pixels (docs/transparency.md §6).
struct OitVerifyRecipe {
  std::string lp_basis;   // the lp: technique it is compared with
  std::string kind;       // "equal" or "never below"
  double lo = 0, hi = 0;  // the LP's interval (of the warped depth u)
  double tolerance = 0;   // in T
};

// What a row is to the commands beside its factory: properties they test instead of names.
enum class RowRole {
  Technique,       // an estimate, measured against the reference
  Reference,       // the reference itself (a sanity row: error 0, no image of its error)
  BiasFloor,       // F_Z(z_f - delta_f): added to every table under the receiver-plane reference
  ExactReference,  // soft shadows: the heuristic with nothing sampled, every soft row's second
                   // reference; transmittance: the sorted composite itself; scattering: the
                   // rectified row's own visibility, the moment rows' second reference
};

// What a sweep measures of a row beside its candidates, and what the seeds found of it: the
// sweep's default `references` and `oit_references` list every row's, in row order, and the
// report's findings print each claim beside the measured number (report/sweep_report.cpp).
struct SweepReference {
  std::string name;  // the technique as run: "" for the row's own name, or a family row's instance
  // The seed paper ranked this basis (seed 000 §3.2): "power" for power moments, and its mean
  // error there.
  std::string moments;
  double seed_error = 0;
  // A classic technique's expected standing against the candidates, and its place in the
  // report's list of them (1, 2, ...).
  std::string expectation;
  int place = 0;
};

struct TechniqueRow {
  // As given in `techniques`; a name ending in ':' is a family matching every "<name><basis>".
  std::string name;
  TechniqueFamily family = TechniqueFamily::HardShadow;
  // The row's place in lists (documentation, `options techniques`, --print-config), within its
  // family.
  int rank = 0;
  std::string summary;
  std::string storage;  // the moment map's format
  std::string bound;    // its darkening bound (docs/reference.md §3) and why
  // Families whose techniques claim a bound per row, not per instance (soft shadows,
  // transmittance): why the row proves none, "" when it proves 0 (or, solving the LP, the LP's).
  std::string unproven_reason;
  std::vector<const TechniqueOption*> options;  // its own options (TechniqueParams)
  std::vector<std::string> family_options;  // keys its family's own records declare (soft.*, oit.*)
  RowRole role = RowRole::Technique;
  // A row others may be measured against (scatter.reference): what errors against it mean, for
  // the report's sentence; empty for a row that is no reference.
  std::string as_reference;
  bool default_run = false;     // in its command's default `techniques`
  std::string example;          // a family row's name in examples and default lists
  bool audits_blocker = false;  // eval audits its blocker search (docs/soft-shadows.md §3)
  bool solves_lp = false;       // answers through the LP fragment solver (lp.*)
  // The factory of its family (one of them is set).
  std::unique_ptr<Technique> (*make)(const std::string& name,
                                     const TechniqueParams& params) = nullptr;
  std::unique_ptr<SoftTechnique> (*make_soft)(const std::string& name,
                                              const SoftSetup& setup) = nullptr;
  std::unique_ptr<OitTechnique> (*make_oit)(const std::string& name,
                                            const OitParams& params) = nullptr;
  std::unique_ptr<ScatterTechnique> (*make_scatter)(const std::string& name,
                                                    const ScatterParams& params) = nullptr;
  // InputError before any work when `name` of a family row cannot be made with these settings.
  void (*check)(const std::string& name, const TechniqueParams& params) = nullptr;
  std::optional<VerifyRecipe> verify = std::nullopt;                 // none: no LP ground truth
  OitVerifyRecipe (*oit_verify)(const OitParams& params) = nullptr;  // none: not verified
  // Its place in `verify.techniques`' default list (1, 2, ...; 0: not checked by default).
  int verify_place = 0;
  std::vector<SweepReference> sweep_references;
  // The catalog's functions that span (with the constant) what the row's moments span, where the
  // catalog has them: a transparency sweep's report places the row's basis among its candidates
  // (docs/transparency.md §7), named by `catalog_basis_label`.
  std::vector<std::string> catalog_basis;
  std::string catalog_basis_label;
  bool prefix() const { return !name.empty() && name.back() == ':'; }
  bool matches(std::string_view given) const;
  // What follows a family row's name in lists ("raymarch:<N>").
  std::string parameter = "<basis>";
  // "lp:<basis>" for a family row, the name otherwise.
  std::string display_name() const;
};

// A technique file's rows, registered before main runs (each file holds one such object).
struct TechniqueRegistration {
  explicit TechniqueRegistration(std::vector<TechniqueRow> (*rows)());
};

// Every row, by family and rank.
const std::vector<TechniqueRow>& technique_registry();
// The rows of one family, by rank.
std::vector<const TechniqueRow*> family_rows(TechniqueFamily family);
// The row of `name` (a family row matches "<prefix><basis>"; the longest prefix wins), of `family`
// when given (lp:<basis> is a row of several), or nullptr.
const TechniqueRow* find_technique(std::string_view name,
                                   std::optional<TechniqueFamily> family = std::nullopt);
// The role of `name`'s row in the first of `families` that has one (RowRole::Technique for a name
// of no row), and whether it solves the LP: for reports, which test a row's properties, never a
// name. The family is named since a name (lp:<basis>) may be a row of several.
RowRole technique_role(std::string_view name, std::initializer_list<TechniqueFamily> families);
bool technique_solves_lp(std::string_view name, std::initializer_list<TechniqueFamily> families);
// The name of `family`'s first row with `role` (its reference, ...), for the reports' words; a
// logic_error when the family has none.
const std::string& role_name(TechniqueFamily family, RowRole role);
// The row of `name` in `family`, or an InputError listing that family's names.
const TechniqueRow& technique_row(const std::string& name, TechniqueFamily family);
// The row of `name` in the first of `families` that has one, or an InputError listing each
// family's names (eval runs hard and soft shadows alike).
const TechniqueRow& technique_row(const std::string& name,
                                  std::initializer_list<TechniqueFamily> families);
// The names of a family's rows that `make` runs by default, as a YAML list ("[a, b]").
std::string default_techniques(TechniqueFamily family);
// Every SweepReference of a family's rows, in row order, with its name filled in.
std::vector<SweepReference> sweep_references(TechniqueFamily family);
// The names of a family's SweepReferences, and of the rows with a verify recipe in
// verify_place order, as YAML lists ("[a, b]"): the defaults of `references` and
// `verify.techniques`.
std::string sweep_reference_list(TechniqueFamily family);
std::string verify_default_list();
// The own options of the rows of `families` (the families a command runs), once per key (shared
// keys such as esm.c appear in several rows), in row order.
std::vector<OptionSpec> technique_option_specs(std::initializer_list<TechniqueFamily> families);
// "key value, key value" of the own options of `families`' rows in `params`, for a report's
// settings line ("oit.beta 0.25").
std::string technique_option_text(std::initializer_list<TechniqueFamily> families,
                                  const TechniqueParams& params);
// Reads every technique option `config` declares into `params`, validated (InputError naming the
// key); the others keep their records' defaults.
void read_technique_options(const Config& config, TechniqueParams& params);
// Sets every moment bias alpha of `params` (solve --alpha).
void set_moment_bias(TechniqueParams& params, double alpha);
// `momentbench options techniques`: a Markdown table of every row, a section per family.
std::string technique_table_markdown();

}  // namespace mb
