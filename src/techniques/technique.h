#pragma once
// A shadow technique (docs/design.md §Types): a name, the basis whose filtered moment map it reads,
// how that map is stored, and shadow(b, z_f) -> G. Closed forms (moments/) and LPs (lp/) both
// implement it, so they appear in the same error tables.
#include <limits>
#include <map>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "basis/basis.h"
#include "lp/problem.h"
#include "moments/storage.h"
#include "util/config.h"

namespace mb {

struct FragmentInput {
  std::span<const double> moments;  // the filtered moment map at the fragment's texel
  double zf = 0;                    // the fragment depth, bias already applied (z_f - delta_f)
  double pcf = 0;                   // the reference (for the `pcf` sanity row)
  double oracle = 0;                // F_Z(z_f - delta_f) (the `oracle` row)
  // The kernel's depth distribution, for techniques that need it: layer-0 depths and weights, or
  // on a translucent map every atom of every tap (shadow/fragments.h, kernel_atoms), tap t's atoms
  // being [tap_offsets[t], tap_offsets[t + 1]) (empty tap_offsets: one atom per tap).
  std::span<const double> kernel_depths, kernel_weights;
  std::span<const uint32_t> tap_offsets;
  std::span<const double> kernel_alpha;  // each atom's opacity (shadow/fragments.h, kernel_atoms)
  // What a stored map holds for this fragment, as a shader reads it (after the format's
  // transform): the centre of an LP's moment box. Empty: the kernel's atoms stored one by one as
  // texels and filtered (filtered_stored_values); pss_lp_stored: the ray's mean of rounded prefix
  // sums.
  std::span<const double> stored_values;
};

struct TechniqueOption;

// Every hard-shadow technique's parameter, keyed by the option record its file declares
// (techniques/registry.h): a value for every registered record, a default-made TechniqueParams
// holding each record's default, which is written there only. A technique reads its own by record
// (`p.number(kEsmC)`) or key (`p.number("esm.c")`); a key no record declares is a logic_error.
// Adding an option to a technique touches that technique's file only. The LP's fields are typed:
// they are the lp: row's settings, shared by every consumer of the LP fragment solver, from the
// lp.* records (techniques/lp_options.h).
class TechniqueParams {
 public:
  TechniqueParams();
  double number(std::string_view key) const;
  int integer(std::string_view key) const;
  double number(const TechniqueOption& option) const;
  int integer(const TechniqueOption& option) const;
  // Sets a registered option (an integer option takes a whole number), unchecked against the
  // record's range as a program's own value: read_technique_options checks what a user gives.
  void set(std::string_view key, double value);
  void set(const TechniqueOption& option, double value);

  lp::Discretization lp;
  std::string lp_backend;
  std::string lp_moment_box;        // lp_fragment_solver.h, lp_moment_box
  std::string lp_moment_transform;  // its transform before a unorm format's rounding
  double lp_beta;                   // G + lp_beta (G+ - G), G+ the LP's maximum (lp.beta)

 private:
  struct Defaults {};
  explicit TechniqueParams(Defaults) {}  // empty: the default constructor's table is made so
  struct Value {
    OptionType type;
    double value;
  };
  const Value& value(std::string_view key, OptionType type) const;
  std::map<std::string, Value, std::less<>> values_;
};

class Technique {
 public:
  virtual ~Technique() = default;
  const std::string& name() const { return name_; }
  const Basis& basis() const { return basis_; }
  const MomentStorage& storage() const { return storage_; }
  virtual bool needs_distribution() const { return false; }
  // A proven bound on G - F_Z(z_f - delta_f) (docs/reference.md §3): 0 for a valid lower bound (the
  // LP, VSM, ESM), alpha for a bias towards a distribution on I, infinity where storage rounding or
  // the beta blend can over-darken. Reports show over-darkening only where this exceeds 1e-9.
  virtual double darkening_bound() const { return 0; }
  // Why a technique with an infinite darkening bound can over-darken, for reports.
  virtual std::string darkening_reason() const { return ""; }
  // Not thread-safe (LP backends keep state): make one instance per thread.
  virtual double shadow(const FragmentInput& input) = 0;
  // An LP technique's problem factory (basis and discretisation of I): evaluate_technique solves
  // such a technique per view with warm starts (eval/lp_view_solver.h); nullptr for closed forms.
  virtual const lp::ProblemFactory* lp_factory() const { return nullptr; }
  // Fragments the technique could not answer (LP infeasible or unstable), for the report.
  virtual size_t failures() const { return 0; }
  // Fragments answered by a fall-back instead of the technique's own test (ESM's failure
  // classifiers: seed 002's custom PCF), for the report.
  virtual size_t fallbacks() const { return 0; }

 protected:
  Technique(std::string name, Basis basis, MomentStorage storage)
      : name_(std::move(name)), basis_(std::move(basis)), storage_(std::move(storage)) {}

 private:
  std::string name_;
  Basis basis_;
  MomentStorage storage_;
};

// The technique `name` made by its registry row (techniques/registry.h): a name of that table or
// "lp:<basis>" (a named set such as power4, or functions separated by ';'). Unknown names are an
// InputError listing the valid ones.
std::unique_ptr<Technique> make_technique(const std::string& name, const TechniqueParams& params);
// Every registered name but the LP row (which takes a basis), in registry order.
std::vector<std::string> closed_form_technique_names();

}  // namespace mb
