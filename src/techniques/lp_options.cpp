#include "techniques/lp_options.h"

#include <limits>

#include "lp/solution.h"
#include "util/error.h"
#include "util/option_record.h"

namespace mb {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// The records' fields, turned into lp::Discretization and the LP fields of TechniqueParams.
struct LpOptions {
  int lp_grid;
  double lp_lo, lp_hi;
  std::string lp_discretization;
  bool lp_quantize;
  std::string lp_backend, lp_moment_box, lp_moment_transform;
  double lp_beta;
};

const std::vector<OptionRecord<LpOptions>>& lp_records() {
  static const std::vector<OptionRecord<LpOptions>> records{
      {{"lp.grid", OptionType::Integer, "256",
        "LP techniques: uniform grid points on the interval.", 2, 1e7},
       &LpOptions::lp_grid},
      {{"lp.lo", OptionType::Number, "0", "LP techniques: admissible interval, lower end."},
       &LpOptions::lp_lo},
      {{"lp.hi", OptionType::Number, "1", "LP techniques: admissible interval, upper end."},
       &LpOptions::lp_hi},
      {{"lp.discretization",
        OptionType::String,
        "grid",
        "LP techniques: grid (Problem 1 on the grid and the kernel's depths, warm-started) or "
        "continuous (on all of [lp.lo, lp.hi], exchange method with a certificate; "
        "docs/reference.md "
        "§2).",
        -kInf,
        kInf,
        {"grid", "continuous"}},
       &LpOptions::lp_discretization},
      {{"lp.quantize", OptionType::Boolean, "false",
        "LP techniques: round depths to the grid instead of adding them."},
       &LpOptions::lp_quantize},
      {{"lp.backend", OptionType::String, "fast", "LP backend.", -kInf, kInf, lp::backend_names()},
       &LpOptions::lp_backend},
      {{"lp.moment_box",
        OptionType::String,
        "none",
        "LP techniques: none (the kernel's exact moments) or a storage format (double, float32, "
        "unorm8, unorm10, unorm16 after lp.moment_transform): Problem 1 over every distribution "
        "whose stored moments lie within that format's rounding of the kernel's "
        "(docs/reference.md §2, §8; GLPK, no warm start).",
        -kInf,
        kInf,
        {"none", "double", "float32", "unorm8", "unorm10", "unorm16"}},
       &LpOptions::lp_moment_box},
      {{"lp.moment_transform",
        OptionType::String,
        "seed",
        "LP techniques with a unorm lp.moment_box: the affine transform q = A b + c applied "
        "before rounding (docs/reference.md §8). seed: seed 000's theta_4 or theta_2, for power4 "
        "and power2 only (the default, so that unorm16 keeps the meaning it had before the other "
        "two existed); canonical: each channel scaled to its own range (the identity for power "
        "moments); optimized: the basis's own transform of the largest entropy gain, found once "
        "per basis (in a sweep, within the candidate's time). Only seed with none, double, "
        "float32.",
        -kInf,
        kInf,
        {"seed", "canonical", "optimized"}},
       &LpOptions::lp_moment_transform},
      {{"lp.beta", OptionType::Number, "0",
        "LP techniques: G + beta (G+ - G), G+ the LP's maximum of the mass at or in front of z_f "
        "(docs/reference.md §2): seed 004's blend of its closed forms' bounds, for any basis. 0 is "
        "the sharp lower bound; above 0 an LP may over-darken. On the grid or the continuous "
        "interval (the maximum by reflection); not with lp.moment_box.",
        0, 1},
       &LpOptions::lp_beta},
  };
  return records;
}

}  // namespace

lp::Discretization lp_discretization_from(const Config& config) {
  LpOptions o{};
  read_declared_options(config, lp_records(), o);
  lp::Discretization d;
  d.grid = o.lp_grid;
  d.lo = o.lp_lo;
  d.hi = o.lp_hi;
  d.quantize = o.lp_quantize;
  d.continuous = o.lp_discretization == "continuous";
  if (!(d.lo < d.hi)) throw InputError("lp.lo, lp.hi: expected lo < hi");
  return d;
}

std::string lp_backend_from(const Config& config) {
  LpOptions o{};
  read_declared_options(config, lp_records(), o);
  return o.lp_backend;
}

std::vector<OptionSpec> lp_option_specs() {
  return option_specs(lp_records());
}

void read_lp_params(const Config& config, TechniqueParams& t) {
  LpOptions o{};
  read_declared_options(config, lp_records(), o);
  t.lp = lp_discretization_from(config);
  t.lp_backend = o.lp_backend;
  t.lp_moment_box = o.lp_moment_box;
  t.lp_moment_transform = o.lp_moment_transform;
  t.lp_beta = o.lp_beta;
  if (t.lp_moment_transform != "seed" && t.lp_moment_box.rfind("unorm", 0) != 0)
    throw InputError(
        "lp.moment_transform: " + t.lp_moment_transform +
        " transforms a unorm format's stored values, and lp.moment_box = " + t.lp_moment_box +
        " has none; expected lp.moment_box = unorm8, unorm10 or unorm16, or "
        "lp.moment_transform = seed");
  if (t.lp_beta > 0 && t.lp_moment_box != "none")
    throw InputError("lp.beta: " + std::to_string(t.lp_beta) +
                     " needs the LP's maximum, which the moment box does not solve; expected "
                     "lp.beta = 0 with lp.moment_box = " +
                     t.lp_moment_box + ", or lp.moment_box = none");
}

}  // namespace mb
