#include "eval/eval_config.h"

#include <algorithm>
#include <cstdio>
#include <limits>

#include "util/error.h"

namespace mb {

std::vector<OptionSpec> shadow_option_specs() {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  return {
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
       "s in delta_f = c + s r (|dz/dx| + |dz/dy|) (REFERENCE.md §3); 0 with bias.constant 1e-3 is "
       "the old constant bias.",
       0, 1e6},
      {"bias.constant", OptionType::Number, "1e-4",
       "c in delta_f: absorbs curvature and rasterisation rounding.", 0, 1},
      {"hamburger4.alpha", OptionType::Number, "1e-10", "Moment bias of Hamburger 4MSM in double."},
      {"hamburger4_float.alpha", OptionType::Number, "5e-6",
       "Moment bias of Hamburger 4MSM in float32."},
      {"hamburger4_16bit.alpha", OptionType::Number, "3e-5",
       "Moment bias of Hamburger 4MSM from 16-bit maps."},
      {"hausdorff4.alpha", OptionType::Number, "1e-10", "Moment bias of Hausdorff 4MSM."},
      {"hamburger6.alpha", OptionType::Number, "1e-10", "Moment bias of six-moment Hamburger MSM."},
      {"tmsm.alpha", OptionType::Number, "1e-10",
       "Moment bias of trigonometric MSM in double (towards 0)."},
      {"tmsm_float.alpha", OptionType::Number, "5e-5",
       "Moment bias of trigonometric MSM in float32 (measured: tmsm.md §6)."},
      {"hamburger.beta", OptionType::Number, "0",
       "G + beta * (weight at z_f): 0 lower bound, 1 upper (seed 004).", 0, 1},
      {"esm.c", OptionType::Number, "80", "ESM exponent c.", 1e-6, 700},
      {"vsm.min_variance", OptionType::Number, "0", "VSM variance clamp.", 0, 1},
      {"evsm.c_positive", OptionType::Number, "40",
       "EVSM exponent of the positive warp exp(c z) (exp(2 c z) must fit float32 for "
       "evsm*_float: c <= 44).",
       1e-6, 300},
      {"evsm.c_negative", OptionType::Number, "5",
       "EVSM4 exponent of the negative warp -exp(-c z).", 1e-6, 300},
      {"lvsm.layers", OptionType::Integer, "4",
       "LVSM depth layers: [0, 1] split evenly, a VSM per layer on the depth clamped to it.", 1, 8},
      {"csm.terms", OptionType::Integer, "8",
       "CSM Fourier terms M (2M channels: cos and sin of (2k - 1) pi z).", 1, 16},
      {"csm.damping", OptionType::Number, "2",
       "CSM ringing suppression: term k scaled by exp(-damping (k/M)^2).", 0, 100},
      {"lp.grid", OptionType::Integer, "256", "LP techniques: uniform grid points on the interval.",
       2, 1e7},
      {"lp.lo", OptionType::Number, "0", "LP techniques: admissible interval, lower end."},
      {"lp.hi", OptionType::Number, "1", "LP techniques: admissible interval, upper end."},
      {"lp.discretization",
       OptionType::String,
       "grid",
       "LP techniques: grid (Problem 1 on the grid and the kernel's depths, warm-started) or "
       "continuous (on all of [lp.lo, lp.hi], exchange method with a certificate; REFERENCE.md "
       "§2).",
       -kInf,
       kInf,
       {"grid", "continuous"}},
      {"lp.quantize", OptionType::Boolean, "false",
       "LP techniques: round depths to the grid instead of adding them."},
      {"lp.backend", OptionType::String, "fast", "LP backend.", -kInf, kInf, {"fast", "glpk"}},
      {"lp.moment_box",
       OptionType::String,
       "none",
       "LP techniques: none (the kernel's exact moments) or a storage format (double, float32, "
       "unorm16 for power4/power2): Problem 1 over every distribution whose stored moments lie "
       "within that format's rounding of the kernel's (REFERENCE.md §2; GLPK, no warm start).",
       -kInf,
       kInf,
       {"none", "double", "float32", "unorm16"}},
  };
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
  t.hamburger4_alpha = config.number("hamburger4.alpha");
  t.hamburger4_float_alpha = config.number("hamburger4_float.alpha");
  t.hamburger4_16bit_alpha = config.number("hamburger4_16bit.alpha");
  t.hausdorff4_alpha = config.number("hausdorff4.alpha");
  t.hamburger6_alpha = config.number("hamburger6.alpha");
  t.tmsm_alpha = config.number("tmsm.alpha");
  t.tmsm_float_alpha = config.number("tmsm_float.alpha");
  t.beta = config.number("hamburger.beta");
  t.esm_c = config.number("esm.c");
  t.vsm_min_variance = config.number("vsm.min_variance");
  t.evsm_c_positive = config.number("evsm.c_positive");
  t.evsm_c_negative = config.number("evsm.c_negative");
  t.lvsm_layers = int(config.integer("lvsm.layers"));
  t.csm_terms = int(config.integer("csm.terms"));
  t.csm_damping = config.number("csm.damping");
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
