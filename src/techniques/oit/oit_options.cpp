#include "techniques/oit/oit_options.h"

#include <algorithm>
#include <limits>

#include "techniques/lp_options.h"
#include "techniques/registry.h"
#include "util/option_record.h"

namespace mb {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// The records' fields, turned into OitParams' typed ones.
struct OitOptions {
  std::string warp, depth_range;
};

const std::vector<OptionRecord<OitOptions>>& oit_records() {
  static const std::vector<OptionRecord<OitOptions>> records{
      {{"oit.warp",
        OptionType::String,
        "logarithmic",
        "Depth warp onto [0, 1] that every moment-based technique takes its moments of "
        "(docs/transparency.md §2): logarithmic, the seed's; linear, to measure what it gains.",
        -kInf,
        kInf,
        {"logarithmic", "linear"}},
       &OitOptions::warp},
      {{"oit.depth_range",
        OptionType::String,
        "fragments",
        "The depth range the warp maps onto [0, 1] (docs/transparency.md §2): fragments, the "
        "frame's nearest and farthest transparent fragment; bounding_sphere, seed 003's, the "
        "bounding sphere of the scene's transparent geometry along the view (wider: it holds "
        "geometry the frame does not see).",
        -kInf,
        kInf,
        {"fragments", "bounding_sphere"}},
       &OitOptions::depth_range},
  };
  return records;
}

bool declares(const Config& config, const std::string& key) {
  const std::vector<OptionSpec>& specs = config.specs();
  return std::any_of(specs.begin(), specs.end(),
                     [&](const OptionSpec& s) { return s.name == key; });
}

// The oit.* values of `config` where it declares them, the records' defaults otherwise.
void read_oit_options(const Config& config, OitParams& params) {
  static const Config defaults(option_specs(oit_records()));
  OitOptions o{};
  for (const auto& r : oit_records())
    read_option(declares(config, r.spec.name) ? config : defaults, r.spec.name, r.field, o);
  params.warp = warp_kind(o.warp);
  params.depth_range = depth_range_kind(o.depth_range);
}

}  // namespace

std::vector<OptionSpec> oit_option_specs() {
  std::vector<OptionSpec> specs = option_specs(oit_records());
  for (auto& s : technique_option_specs({TechniqueFamily::Transmittance})) specs.push_back(s);
  return specs;
}

OitParams::OitParams() {
  // beta, warp and depth_range from their records' defaults (written there only), parsed once.
  static const OitParams defaults = [] {
    OitParams p(Defaults{});
    read_oit_options(Config(option_specs(oit_records())), p);
    return p;
  }();
  *this = defaults;
}

OitParams oit_params_from(const Config& config) {
  OitParams params;
  read_oit_options(config, params);
  read_technique_options(config, params.technique);
  read_lp_params(config, params.technique);
  return params;
}

}  // namespace mb
