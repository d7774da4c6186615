#include "verify/verify_options.h"

#include "oit/oit_verification.h"
#include "techniques/registry.h"
#include "verify/scatter_verification.h"

namespace mb {

namespace {

// Names as a YAML list.
std::string yaml_list(const std::vector<std::string>& names) {
  std::string list;
  for (const std::string& name : names) list += (list.empty() ? "" : ", ") + name;
  return "[" + list + "]";
}

// Every transmittance row with a verify recipe.
std::string oit_verify_default() {
  return yaml_list(oit_verify_names());
}

}  // namespace

const std::vector<OptionRecord<VerifySettings>>& verify_options() {
  static const std::vector<OptionRecord<VerifySettings>> records{
      {selects_runs(
           {"verify.techniques", OptionType::StringList, verify_default_list(),
            "Closed forms to check (docs/reference.md §6; EVSM as a lower bound of its basis)."}),
       &VerifySettings::techniques},
      {selects_runs(
           {"verify.oit_techniques", OptionType::StringList, oit_verify_default(),
            "MBOIT closed forms (double, beta 0) to check against the LP on seeded random pixels "
            "(docs/transparency.md §6); [] for none."}),
       &VerifySettings::oit_techniques},
      {{"verify.oit_pixels", OptionType::Integer, "20",
        "Seeded random pixels (2-13 fragments) per MBOIT row.", 1, 1e6},
       &VerifySettings::oit_pixels},
      {selects_runs({"verify.scatter_techniques", OptionType::StringList,
                     yaml_list(scatter_verify_names()),
                     "Prefiltered scattering rows whose bounds (scatter.beta 0 and 1) are checked "
                     "against pss_lp on the same row-prefiltered moments (docs/scattering.md "
                     "§6); [] for none."}),
       &VerifySettings::scatter_techniques},
      {{"verify.scatter_dataset", OptionType::String, "scattering_tiny",
        "Dataset (name or file) whose light views and cameras give the scattering rows' "
        "rectified maps: the small house, seconds to render."},
       &VerifySettings::scatter_dataset},
      {{"verify.scatter_rays", OptionType::Integer, "200",
        "Seeded random view rays per light view and camera for the scattering rows: 200 on "
        "scattering_tiny's one camera keep the LPs to seconds.",
        1, 1e6},
       &VerifySettings::scatter_rays},
      {{"verify.scatter_resolution", OptionType::Integer, "256",
        "Texels a row (and rows) of the scattering rows' rectified maps, guard band 1/16 of it "
        "as scatter.guard_band's default: the LP's cost grows with a row's texels.",
        8, 8192},
       &VerifySettings::scatter_resolution},
      {{"verify.random", OptionType::Integer, "2000",
        "Seeded random distributions (1-8 atoms, mixtures).", 0, 1e8},
       &VerifySettings::random},
      {{"verify.fragments", OptionType::Integer, "2000",
        "Real receiver kernels sampled from the dataset (0: none).", 0, 1e8},
       &VerifySettings::fragments},
      {{"verify.seed", OptionType::Integer, "2015",
        "Seed of the random instances and the fragment sample.", 0, 1e18},
       &VerifySettings::seed},
      {{"verify.grids", OptionType::IntegerList, "[256, 1024, 4096]",
        "LP grid sizes, ascending; the last decides unless the discretization is "
        "continuous.",
        2, 1 << 24},
       &VerifySettings::grids},
      {{"verify.discretization",
        OptionType::String,
        "continuous",
        "continuous: Problem 1 on the whole interval (R for Hamburger and VSM) by the "
        "exchange method with a certificate decides (docs/reference.md §2); grid: the "
        "finest grid decides.",
        0,
        0,
        {"continuous", "grid"}},
       &VerifySettings::discretization},
      {{"verify.moment_box",
        OptionType::String,
        "storage",
        "Float32 and 16-bit rows: storage = judged as lower bounds of Problem 1 over "
        "every distribution on [0, 1] whose stored values lie within the format's "
        "rounding of theirs (docs/reference.md §2), exceeding it reported; strict = "
        "exceeding it also fails verify; off = against the exact moments, reported as "
        "bias.",
        0,
        0,
        {"storage", "strict", "off"}},
       &VerifySettings::moment_box},
      {{"verify.tolerance", OptionType::Number, "1e-6",
        "Largest |G_closed_form - G_LP| beyond the instance's own rounding allowance "
        "(the first-order effect of moments rounded to double): the closed forms' "
        "arithmetic at alpha = 0.",
        0, 1},
       &VerifySettings::tolerance},
      {{"verify.esm_c", OptionType::Number, "10",
        "ESM exponent for verify: with c = 80 the LP cannot resolve E[e^{c(z-1)}] below "
        "its 1e-9 tolerance.",
        1e-6, 700},
       &VerifySettings::esm_c},
      {{"verify.evsm_c", OptionType::Number, "5",
        "EVSM's positive exponent for verify: with c = 40 its LP columns exp(80 (z - 1)) "
        "vanish below the LP's tolerance over most of [0, 1].",
        1e-6, 300},
       &VerifySettings::evsm_c},
      {{"verify.csm_terms", OptionType::Integer, "3",
        "CSM's Fourier terms M for verify: M = 8 gives 16 channels, beyond the LP's 15 "
        "functions; M <= 3 keeps the fast backend, up to 7 runs on GLPK.",
        1, 7},
       &VerifySettings::csm_terms},
      {measures_nothing(
           {"verify.worst", OptionType::Integer, "5", "Worst cases listed per solver.", 0, 1000}),
       &VerifySettings::worst},
  };
  return records;
}

VerifySettings::VerifySettings() {
  read_defaults(verify_options(), *this);
}

}  // namespace mb
