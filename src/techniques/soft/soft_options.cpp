#include "techniques/soft/soft_technique.h"

namespace mb {

// The soft family's shared options, each with the seed it comes from (docs/soft-shadows.md §2).
const std::vector<OptionRecord<SoftParams>>& soft_option_records() {
  static const std::vector<OptionRecord<SoftParams>> records{
      {{"soft.pcss_search", OptionType::Integer, "15",
        "Soft shadows: texels a side of PCSS's blocker search (pcss, pcss_exact; seed 004 §3.6 "
        "uses 15x15); 0 takes it from the light's size as seed 001 does: the light's cone at the "
        "receiver's depth, 2 ceil(rim_shear z_f) + 1, at most 255.",
        0, 255},
       &SoftParams::pcss_search},
      {{"soft.sat_search", OptionType::Integer, "27",
        "Soft shadows: texels a side of the summed-area techniques' blocker search (seed 004 §3.6 "
        "uses 27x27).",
        1, 255},
       &SoftParams::sat_search},
      {{"soft.min_filter", OptionType::Number, "0",
        "Soft shadows: the narrowest penumbra box in texels (seed 001 clamps for antialiasing); "
        "0, none: every technique filters with the protocol's kernel besides (docs/soft-shadows.md "
        "§2).",
        0, 255},
       &SoftParams::min_filter},
      {{"soft.max_filter", OptionType::Integer, "31",
        "Soft shadows: the widest filter in texels; N = max(sat_search, max_filter + 2)^2 sets the "
        "fixed-point scale (2^32 - 1) / N of summed-area tables (seed 004 §3.2): 31 keeps 22 bits, "
        "rounding error 2.5e-7 below what msm_soft's alpha of 5e-6 absorbs.",
        1, 4093},
       &SoftParams::max_filter},
      {{"soft.sat",
        OptionType::String,
        "fixed32",
        "Summed-area tables: fixed32 (seed 004 §3.2: 32-bit integers modulo 2^32, scale "
        "(2^32 - 1) / N) or exact (128-bit integers of 2^53 times each value).",
        -std::numeric_limits<double>::infinity(),
        std::numeric_limits<double>::infinity(),
        {"fixed32", "exact"}},
       &SoftParams::sat},
      {{"soft.audit", OptionType::Integer, "500",
        "msm_soft: receivers per view whose blocker estimate is set beside its sharp bounds "
        "(docs/soft-shadows.md §3; blocker_audit.csv); 0: none.",
        0, 1000000},
       &SoftParams::audit},
  };
  return records;
}

SoftParams::SoftParams() {
  read_options(Config(option_specs(soft_option_records())), soft_option_records(), *this);
}

}  // namespace mb
