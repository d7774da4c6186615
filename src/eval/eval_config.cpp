#include "eval/eval_config.h"

#include <algorithm>
#include <cstdio>
#include <limits>

#include "lp/solution.h"
#include "techniques/registry.h"
#include "util/error.h"

namespace mb {

std::vector<OptionSpec> shadow_option_specs() {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  std::vector<OptionSpec> specs{
      {"kernel.size", OptionType::Integer, "9",
       "Filter taps per axis (odd), for PCF and moment maps."},
      {"kernel.sigma", OptionType::Number, "2.4", "Gaussian standard deviation in texels."},
      {"reference",
       OptionType::String,
       "biased",
       "What G is compared against: biased = PCF at z_f - delta_f (the paper's protocol, errors "
       "are light leaking), "
       "receiver_plane = each tap against the fragment's plane (the ideal hard shadow; tables add "
       "the oracle floor).",
       -kInf,
       kInf,
       {"biased", "receiver_plane"}},
      {"bias.slope", OptionType::Number, "1",
       "s in delta_f = c + s r (|dz/dx| + |dz/dy|) (docs/reference.md §3); 0 with bias.constant "
       "1e-3 is "
       "the old constant bias.",
       0, 1e6},
      {"bias.constant", OptionType::Number, "1e-4",
       "c in delta_f: absorbs curvature and rasterisation rounding.", 0, 1},
      {"lp.grid", OptionType::Integer, "256", "LP techniques: uniform grid points on the interval.",
       2, 1e7},
      {"lp.lo", OptionType::Number, "0", "LP techniques: admissible interval, lower end."},
      {"lp.hi", OptionType::Number, "1", "LP techniques: admissible interval, upper end."},
      {"lp.discretization",
       OptionType::String,
       "grid",
       "LP techniques: grid (Problem 1 on the grid and the kernel's depths, warm-started) or "
       "continuous (on all of [lp.lo, lp.hi], exchange method with a certificate; "
       "docs/reference.md "
       "§2).",
       -kInf,
       kInf,
       {"grid", "continuous"}},
      {"lp.quantize", OptionType::Boolean, "false",
       "LP techniques: round depths to the grid instead of adding them."},
      {"lp.backend", OptionType::String, "fast", "LP backend.", -kInf, kInf, lp::backend_names()},
      {"lp.moment_box",
       OptionType::String,
       "none",
       "LP techniques: none (the kernel's exact moments) or a storage format (double, float32, "
       "unorm16 for power4/power2): Problem 1 over every distribution whose stored moments lie "
       "within that format's rounding of the kernel's (docs/reference.md §2; GLPK, no warm start).",
       -kInf,
       kInf,
       {"none", "double", "float32", "unorm16"}},
  };
  // The technique options come from their registry rows, between the protocol's and the LP's.
  const auto techniques = technique_option_specs();
  const auto lp = std::find_if(specs.begin(), specs.end(),
                               [](const OptionSpec& s) { return s.name.rfind("lp.", 0) == 0; });
  specs.insert(lp, techniques.begin(), techniques.end());
  return specs;
}

GaussianKernel kernel_from(const Config& config) {
  return make_gaussian_kernel(int(config.integer("kernel.size")), config.number("kernel.sigma"));
}

lp::Discretization lp_discretization_from(const Config& config) {
  lp::Discretization d;
  d.grid = int(config.integer("lp.grid"));
  d.lo = config.number("lp.lo");
  d.hi = config.number("lp.hi");
  d.quantize = config.boolean("lp.quantize");
  d.continuous = config.string("lp.discretization") == "continuous";
  if (!(d.lo < d.hi)) throw InputError("lp.lo, lp.hi: expected lo < hi");
  return d;
}

EvalSettings shadow_settings_from(const Config& config, int threads) {
  EvalSettings s;
  s.kernel = kernel_from(config);
  s.bias.reference = parse_reference(config.string("reference"), "reference");
  s.bias.slope = config.number("bias.slope");
  s.bias.constant = config.number("bias.constant");
  auto& t = s.technique;
  read_technique_options(config, t);
  t.lp = lp_discretization_from(config);
  t.lp_backend = config.string("lp.backend");
  t.lp_moment_box = config.string("lp.moment_box");
  s.threads = threads;
  return s;
}

std::vector<std::string> with_oracle_row(std::vector<std::string> techniques,
                                         const BiasParams& bias) {
  if (bias.reference == Reference::ReceiverPlane &&
      std::find(techniques.begin(), techniques.end(), "oracle") == techniques.end())
    techniques.push_back("oracle");
  return techniques;
}

std::string describe_settings(const EvalSettings& s) {
  char buffer[512];
  std::snprintf(
      buffer, sizeof buffer,
      "kernel %dx%d Gaussian, sigma %g texels; reference %s; depth bias delta_f = %g + %g * %d * "
      "(|dz/dx| + |dz/dy|) for the reference and every technique; LP grid %d on [%g, %g]%s%s, "
      "backend %s%s%s",
      s.kernel.size, s.kernel.size, s.kernel.sigma,
      s.bias.reference == Reference::Biased
          ? "biased (PCF = F_Z(z_f - delta_f))"
          : "receiver_plane (each tap against the fragment's plane)",
      s.bias.constant, s.bias.slope, s.kernel.radius(), s.technique.lp.grid, s.technique.lp.lo,
      s.technique.lp.hi, s.technique.lp.quantize ? " (quantized depths)" : "",
      s.technique.lp.continuous ? " (seeding the continuous interval)" : "",
      s.technique.lp_backend.c_str(),
      s.technique.lp_moment_box == "none" ? "" : "; LP moment box of ",
      s.technique.lp_moment_box == "none" ? "" : s.technique.lp_moment_box.c_str());
  return buffer;
}

}  // namespace mb
