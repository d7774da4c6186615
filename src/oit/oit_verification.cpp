#include "oit/oit_verification.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "scene/procedural.h"
#include "techniques/oit/oit_technique.h"
#include "techniques/registry.h"
#include "util/error.h"
#include "util/name_list.h"
#include "util/number_text.h"

namespace mb {

namespace {

// A pixel of 2-13 fragments at view depths in [2, 12] with alpha in [0.05, 0.9], as the tests
// draw them; colours do not enter the transmittance.
struct RandomPixel {
  std::vector<double> depth, alpha, warped;
  std::vector<Rgb> color;
};

RandomPixel random_pixel(SeededRandom& rng, int count) {
  RandomPixel p;
  for (int l = 0; l < count; ++l)
    p.depth.push_back(rng.uniform(2, 12)), p.alpha.push_back(rng.uniform(0.05, 0.9));
  p.color.assign(size_t(count), Rgb{0.5f, 0.5f, 0.5f});
  const auto [lo, hi] = std::minmax_element(p.depth.begin(), p.depth.end());
  const DepthWarp warp = DepthWarp::between(*lo, *hi);
  for (double z : p.depth) p.warped.push_back(warp(z));
  return p;
}

}  // namespace

std::vector<std::string> oit_verify_names() {
  std::vector<std::string> names;
  for (const TechniqueRow* row : family_rows(TechniqueFamily::Transmittance))
    if (row->oit_verify) names.push_back(row->name);
  return names;
}

void check_oit_verify_technique(const std::string& technique) {
  const auto names = oit_verify_names();
  if (std::find(names.begin(), names.end(), technique) != names.end()) return;
  throw InputError("verify.oit_techniques: '" + technique + "': expected one of " +
                   joined(names, ", ") + " (the certified LP engine takes up to seven functions)");
}

OitVerifyRow verify_mboit(const std::string& technique, int pixels, uint64_t seed) {
  check_oit_verify_technique(technique);
  OitParams closed, lp;
  const TechniqueRow& row_of = technique_row(technique, TechniqueFamily::Transmittance);
  const OitVerifyRecipe recipe = row_of.oit_verify(closed);
  OitVerifyRow row;
  row.technique = technique;
  row.lp_basis = recipe.lp_basis;
  row.kind = recipe.kind;
  row.lo = recipe.lo, row.hi = recipe.hi;
  row.tolerance = recipe.tolerance;
  // The closed form at its sharp setting (beta 0: A-, docs/transparency.md §6).
  for (const TechniqueOption* o : row_of.options)
    if (o->zero_is_sharp) closed.technique.set(*o, 0);
  lp.technique.lp = lp::Discretization{row.lo, row.hi, 256, false};
  lp.technique.lp.continuous = true;
  auto mboit = make_oit_technique(technique, closed);
  auto reference = make_oit_technique(row.lp_basis, lp);
  SeededRandom rng(seed);
  std::vector<double> t_closed, t_lp;
  for (int i = 0; i < pixels; ++i) {
    const RandomPixel p = random_pixel(rng, 2 + i % 12);
    const PixelFragments px{p.depth, p.alpha, p.color, kBackground};
    t_closed.resize(p.depth.size()), t_lp.resize(p.depth.size());
    mboit->transmittance(px, p.warped, t_closed);
    const size_t before = reference->failures();
    reference->transmittance(px, p.warped, t_lp);
    row.lp_failures += reference->failures() - before;
    ++row.pixels;
    for (size_t l = 0; l < p.depth.size(); ++l, ++row.fragments) {
      // T = e^{-A}: "never below" in absorbance is "never above" the LP's e^{-A-} in T.
      const double d =
          row.kind == "equal" ? std::abs(t_closed[l] - t_lp[l]) : t_closed[l] - t_lp[l];
      row.largest = std::max(row.largest, d);
      row.beyond += d > row.tolerance;
    }
  }
  return row;
}

}  // namespace mb
