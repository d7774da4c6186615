#include "techniques/oit/mboit_row.h"

#include "techniques/oit/oit_technique.h"

namespace mb {

const TechniqueOption kMboitBeta{
    .spec = {"oit.beta", OptionType::Number, "0.25",
             "MBOIT's overestimation: A = A- + beta (A+ - A-) from the canonical representation "
             "(0.25 is the value of the authors' code; 0 gives their lower bound of absorbance).",
             0, 1},
    .zero_is_sharp = true};

TechniqueRow mboit_row(const std::string& prefix, const std::string& kind, int moments, int variant,
                       int rank_base, decltype(TechniqueRow::make_oit) make,
                       decltype(TechniqueRow::oit_verify) verify) {
  const OitStorageVariant& v = kOitStorageVariants[variant];
  const std::string storage = variant == 0 ? "double" : variant == 1 ? "float32" : "snorm16";
  return {
      .name = prefix + std::to_string(moments) + v.suffix,
      .family = TechniqueFamily::Transmittance,
      .rank = rank_base + moments + v.rank,
      .summary = "MBOIT with " + std::to_string(moments) + " " + kind +
                 " moments of the warped depth, " + storage,
      .storage = storage,
      .bound =
          "none: beta > 0 overestimates the absorbance (oit.beta), and the bias alpha "
          "moves the moments (docs/transparency.md §3)",
      .unproven_reason = "MBOIT: beta > 0 and the normalisation Gamma (docs/transparency.md §3)",
      .options = {&kMboitBeta},
      .family_options = {"oit.warp", "oit.depth_range"},
      .default_run = variant == 0,
      .make_oit = make,
      .oit_verify = verify};
}

}  // namespace mb
