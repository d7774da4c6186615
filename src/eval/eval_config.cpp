#include "eval/eval_config.h"

#include <algorithm>
#include <cstdio>
#include <limits>

#include "lp/solution.h"
#include "techniques/registry.h"
#include "util/error.h"
#include "util/number_text.h"
#include "util/option_record.h"

namespace mb {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// The protocol's and the LP's keys as plain fields; shadow_settings_from turns them into the
// kernel, the bias and the LP discretisation.
struct ShadowOptions {
  int kernel_size = 9;
  double kernel_sigma = 2.4;
  std::string reference;
  double bias_slope = 1, bias_constant = 1e-4;
  int lp_grid = 256;
  double lp_lo = 0, lp_hi = 1;
  std::string lp_discretization;
  bool lp_quantize = false;
  std::string lp_backend, lp_moment_box;
  double lp_beta = 0;
  std::string blend;
  double light_angle = 0;
  int light_directions = 64;
};

const std::vector<OptionRecord<ShadowOptions>>& kernel_options() {
  static const std::vector<OptionRecord<ShadowOptions>> records{
      {{"kernel.size", OptionType::Integer, "9",
        "Filter taps per axis (odd), for PCF and moment maps. At most 127: every receiver's LP "
        "holds "
        "size^2 kernel atoms, and a kernel wider than the map only averages the far plane.",
        1, 127},
       &ShadowOptions::kernel_size},
      {{"kernel.sigma", OptionType::Number, "2.4", "Gaussian standard deviation in texels."},
       &ShadowOptions::kernel_sigma},
  };
  return records;
}

const std::vector<OptionRecord<ShadowOptions>>& bias_options() {
  static const std::vector<OptionRecord<ShadowOptions>> records{
      {{"reference",
        OptionType::String,
        "biased",
        "What G is compared against: biased = PCF at z_f - delta_f (the paper's protocol, errors "
        "are light leaking), "
        "receiver_plane = each tap against the fragment's plane (the ideal hard shadow; tables add "
        "the oracle floor).",
        -kInf,
        kInf,
        {"biased", "receiver_plane"}},
       &ShadowOptions::reference},
      {{"bias.slope", OptionType::Number, "1",
        "s in delta_f = c + s r (|dz/dx| + |dz/dy|) (docs/reference.md §3); 0 with bias.constant "
        "1e-3 is "
        "the old constant bias.",
        0, 1e6},
       &ShadowOptions::bias_slope},
      {{"bias.constant", OptionType::Number, "1e-4",
        "c in delta_f: absorbs curvature and rasterisation rounding.", 0, 1},
       &ShadowOptions::bias_constant},
  };
  return records;
}

const std::vector<OptionRecord<ShadowOptions>>& translucent_options() {
  static const std::vector<OptionRecord<ShadowOptions>> records{
      {{"translucent.blend",
        OptionType::String,
        "sorted",
        "Translucent occluders (docs/reference.md §7): how the moment maps blend a texel's "
        "surfaces. sorted: front to back, the exact E_Z[b] (seed 004 needs any OIT method); "
        "submission: in the scene's triangle order over the first opaque surface, as an unsorted "
        "GPU pass does. The reference is exact either way.",
        -kInf,
        kInf,
        {"sorted", "submission"}},
       &ShadowOptions::blend},
  };
  return records;
}

const std::vector<OptionRecord<ShadowOptions>>& light_options() {
  static const std::vector<OptionRecord<ShadowOptions>> records{
      {{"light.angle", OptionType::Number, "0",
        "Soft shadows (docs/soft-shadows.md): the directional light's angular diameter in degrees, "
        "for every view whose scene names none and of a dataset that lists no light_angles. 0 is "
        "the hard shadow of the paper's protocol; above 0 the reference is the area light's "
        "shadow. The sun is 0.53. Below 90 (a cone of half-angle under 45 degrees).",
        0, 89.99},
       &ShadowOptions::light_angle},
      {{"light.directions", OptionType::Integer, "64",
        "Soft shadows: directions N averaged for the area light's shadow, each one rasterized "
        "layer stack. Powers of two stratify best (docs/soft-shadows.md §1); the error of N "
        "against 4N falls at least as 1/sqrt(N).",
        1, 65536},
       &ShadowOptions::light_directions},
  };
  return records;
}

const std::vector<OptionRecord<ShadowOptions>>& lp_options() {
  static const std::vector<OptionRecord<ShadowOptions>> records{
      {{"lp.grid", OptionType::Integer, "256",
        "LP techniques: uniform grid points on the interval.", 2, 1e7},
       &ShadowOptions::lp_grid},
      {{"lp.lo", OptionType::Number, "0", "LP techniques: admissible interval, lower end."},
       &ShadowOptions::lp_lo},
      {{"lp.hi", OptionType::Number, "1", "LP techniques: admissible interval, upper end."},
       &ShadowOptions::lp_hi},
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
       &ShadowOptions::lp_discretization},
      {{"lp.quantize", OptionType::Boolean, "false",
        "LP techniques: round depths to the grid instead of adding them."},
       &ShadowOptions::lp_quantize},
      {{"lp.backend", OptionType::String, "fast", "LP backend.", -kInf, kInf, lp::backend_names()},
       &ShadowOptions::lp_backend},
      {{"lp.moment_box",
        OptionType::String,
        "none",
        "LP techniques: none (the kernel's exact moments) or a storage format (double, float32, "
        "unorm16 for power4/power2): Problem 1 over every distribution whose stored moments lie "
        "within that format's rounding of the kernel's (docs/reference.md §2; GLPK, no warm "
        "start).",
        -kInf,
        kInf,
        {"none", "double", "float32", "unorm16"}},
       &ShadowOptions::lp_moment_box},
      {{"lp.beta", OptionType::Number, "0",
        "LP techniques: G + beta (G+ - G), G+ the LP's maximum of the mass at or in front of z_f "
        "(docs/reference.md §2): seed 004's blend of its closed forms' bounds, for any basis. 0 is "
        "the sharp lower bound; above 0 an LP may over-darken. Grid discretisation only.",
        0, 1},
       &ShadowOptions::lp_beta},
  };
  return records;
}

}  // namespace

std::vector<OptionSpec> shadow_option_specs() {
  // The protocol's keys, then every technique's (from their registry rows), then the LP's.
  std::vector<OptionSpec> specs = option_specs(kernel_options());
  for (auto& s : option_specs(bias_options())) specs.push_back(s);
  for (auto& s : option_specs(translucent_options())) specs.push_back(s);
  for (auto& s : option_specs(light_options())) specs.push_back(s);
  for (auto& s : option_specs(soft_option_records())) specs.push_back(s);
  for (auto& s : technique_option_specs()) specs.push_back(s);
  for (auto& s : option_specs(lp_options())) specs.push_back(s);
  return specs;
}

GaussianKernel kernel_from(const Config& config) {
  ShadowOptions o;
  read_options(config, kernel_options(), o);
  return make_gaussian_kernel(o.kernel_size, o.kernel_sigma);
}

lp::Discretization lp_discretization_from(const Config& config) {
  ShadowOptions o;
  read_options(config, lp_options(), o);
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
  ShadowOptions o;
  read_options(config, lp_options(), o);
  return o.lp_backend;
}

std::vector<OptionSpec> lp_option_specs() {
  return option_specs(lp_options());
}

void read_lp_params(const Config& config, TechniqueParams& t) {
  ShadowOptions o;
  read_options(config, lp_options(), o);
  t.lp = lp_discretization_from(config);
  t.lp_backend = o.lp_backend;
  t.lp_moment_box = o.lp_moment_box;
  t.lp_beta = o.lp_beta;
  if (t.lp_beta > 0 && (t.lp.continuous || t.lp_moment_box != "none"))
    throw InputError(
        "lp.beta: " + std::to_string(t.lp_beta) +
        " needs the LP's maximum, which is solved on the grid only; expected lp.beta = 0 with "
        "lp.discretization = continuous or an lp.moment_box");
}

EvalSettings shadow_settings_from(const Config& config, int threads) {
  EvalSettings s;
  s.kernel = kernel_from(config);
  ShadowOptions o;
  read_options(config, bias_options(), o);
  read_options(config, translucent_options(), o);
  s.blend = o.blend == "submission" ? BlendOrder::Submission : BlendOrder::Sorted;
  read_options(config, light_options(), o);
  s.light.angle_deg = o.light_angle;
  s.light.directions = o.light_directions;
  read_options(config, soft_option_records(), s.soft);
  s.bias.reference = parse_reference(o.reference, "reference");
  s.bias.slope = o.bias_slope;
  s.bias.constant = o.bias_constant;
  auto& t = s.technique;
  read_technique_options(config, t);
  read_lp_params(config, t);
  s.threads = threads;
  return s;
}

std::vector<std::string> with_oracle_row(std::vector<std::string> techniques,
                                         const BiasParams& bias) {
  if (bias.reference != Reference::ReceiverPlane) return techniques;
  for (const TechniqueRow* row : family_rows(TechniqueFamily::HardShadow))
    if (row->role == RowRole::BiasFloor &&
        std::find(techniques.begin(), techniques.end(), row->name) == techniques.end())
      techniques.push_back(row->name);
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
  std::string text = buffer;
  if (s.technique.lp_beta > 0)
    text += "; LP answers G + " + round_trip(s.technique.lp_beta) + " (G+ - G)";
  if (s.blend == BlendOrder::Submission)
    text += "; translucent moment maps blended in submission order (unsorted)";
  return text;
}

}  // namespace mb
