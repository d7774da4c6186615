#include "eval/eval_config.h"

#include <algorithm>
#include <cstdio>
#include <limits>

#include "techniques/lp_options.h"
#include "techniques/registry.h"
#include "util/error.h"
#include "util/number_text.h"
#include "util/option_record.h"

namespace mb {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// The protocol's keys as plain fields; shadow_settings_from turns them into the kernel and the
// bias.
// Filled from the records below (their defaults are written there only).
struct ShadowOptions {
  int kernel_size{};
  double kernel_sigma{};
  std::string reference;
  double bias_slope{}, bias_constant{};
  std::string blend;
  double light_angle{};
  int light_directions{};
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

// The light's extent: every shadow measurement reads it (a hard-shadow sweep, to refuse an area
// light).
const std::vector<OptionRecord<ShadowOptions>>& light_options() {
  static const std::vector<OptionRecord<ShadowOptions>> records{
      {{"light.angle", OptionType::Number, "0",
        "Soft shadows (docs/soft-shadows.md): the directional light's angular diameter in degrees, "
        "for every view whose scene names none and of a dataset that lists no light_angles. 0 is "
        "the hard shadow of the paper's protocol; above 0 the reference is the area light's "
        "shadow. The sun is 0.53. Below 90 (a cone of half-angle under 45 degrees).",
        0, 89.99},
       &ShadowOptions::light_angle},
  };
  return records;
}

// What only an area light reads (light.angle > 0): its sampling, beside the soft.* records.
const std::vector<OptionRecord<ShadowOptions>>& area_light_options() {
  static const std::vector<OptionRecord<ShadowOptions>> records{
      {{"light.directions", OptionType::Integer, "64",
        "Soft shadows: directions N averaged for the area light's shadow, each one rasterized "
        "layer stack. Powers of two stratify best (docs/soft-shadows.md §1); the error of N "
        "against 4N falls at least as 1/sqrt(N).",
        1, 65536},
       &ShadowOptions::light_directions},
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
  for (auto& s : option_specs(area_light_options())) specs.push_back(s);
  for (auto& s : option_specs(soft_option_records())) specs.push_back(s);
  for (auto& s : technique_option_specs({TechniqueFamily::HardShadow, TechniqueFamily::SoftShadow}))
    specs.push_back(s);
  for (auto& s : lp_option_specs()) specs.push_back(s);
  return specs;
}

std::vector<OptionSpec> hard_shadow_option_specs() {
  std::vector<OptionSpec> specs = option_specs(kernel_options());
  for (auto& s : option_specs(bias_options())) specs.push_back(s);
  for (auto& s : option_specs(translucent_options())) specs.push_back(s);
  for (auto& s : option_specs(light_options())) specs.push_back(s);
  for (auto& s : technique_option_specs({TechniqueFamily::HardShadow})) specs.push_back(s);
  for (auto& s : lp_option_specs()) specs.push_back(s);
  return specs;
}

EvalSettings::EvalSettings() {
  static const EvalSettings defaults = shadow_settings_from(Config(shadow_option_specs()), 1);
  *this = defaults;
}

GaussianKernel kernel_from(const Config& config) {
  ShadowOptions o;
  read_options(config, kernel_options(), o);
  return make_gaussian_kernel(o.kernel_size, o.kernel_sigma);
}

EvalSettings shadow_settings_from(const Config& config, int threads) {
  EvalSettings s{EvalSettings::Unset{}};
  s.kernel = kernel_from(config);
  ShadowOptions o;
  read_options(config, bias_options(), o);
  read_options(config, translucent_options(), o);
  s.blend = o.blend == "submission" ? BlendOrder::Submission : BlendOrder::Sorted;
  read_options(config, light_options(), o);
  read_declared_options(config, area_light_options(), o);
  s.light.angle_deg = o.light_angle;
  s.light.directions = o.light_directions;
  read_declared_options(config, soft_option_records(), s.soft);
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
  if (s.technique.lp_moment_box.rfind("unorm", 0) == 0)
    text += " after the " + s.technique.lp_moment_transform + " transform";
  if (s.technique.lp_beta > 0)
    text += "; LP answers G + " + round_trip(s.technique.lp_beta) + " (G+ - G)";
  if (s.blend == BlendOrder::Submission)
    text += "; translucent moment maps blended in submission order (unsorted)";
  return text;
}

}  // namespace mb
