// What the transparency techniques share (techniques/oit/oit_technique.h): a pixel's absorbance
// distribution, the normalisation of weighted techniques, and making a technique by its row.
#include "techniques/oit/oit_technique.h"

#include <algorithm>

#include "techniques/registry.h"
#include "util/error.h"

namespace mb {

void absorbance_distribution(const PixelFragments& px, std::span<const double> warped,
                             AbsorbanceDistribution& d) {
  std::vector<std::pair<double, double>>& atoms = d.scratch;
  atoms.clear();
  for (size_t l = 0; l < px.size(); ++l) {
    const double a = std::min(absorbance(px.alpha[l]), kMaxAbsorbance);
    if (a > 0) atoms.push_back({warped[l], a});
  }
  // Canonical order: the sums below are then the same for every submission order, bit for bit.
  std::sort(atoms.begin(), atoms.end());
  d.total = 0;
  d.depths.clear(), d.weights.clear();
  for (const auto& [u, a] : atoms) d.total += a;
  for (const auto& [u, a] : atoms) d.depths.push_back(u), d.weights.push_back(a / d.total);
}

AbsorbanceDistribution absorbance_distribution(const PixelFragments& px,
                                               std::span<const double> warped) {
  AbsorbanceDistribution d;
  absorbance_distribution(px, warped, d);
  return d;
}

void effective_transmittance(const OitTechnique& technique, const PixelFragments& px,
                             std::span<double> transmittance) {
  if (!technique.normalised()) return;
  // Gamma = (1 - T_total) / sum_l alpha_l T_l (weighted blended OIT's normalisation).
  double weight = 0;
  for (size_t l = 0; l < px.size(); ++l) weight += px.alpha[l] * transmittance[l];
  const double gamma = weight > 0 ? (1 - total_transmittance(px)) / weight : 0;
  for (double& t : transmittance) t *= gamma;
}

Rgb composite_with(const OitTechnique& technique, const PixelFragments& px,
                   std::span<const double> transmittance) {
  std::vector<double> weights(transmittance.begin(), transmittance.end());
  effective_transmittance(technique, px, weights);
  return composite(px, weights, total_transmittance(px));
}

std::vector<std::string> oit_technique_names() {
  std::vector<std::string> names;
  for (const TechniqueRow* row : family_rows(TechniqueFamily::Transmittance))
    if (!row->prefix()) names.push_back(row->name);
  return names;
}

std::unique_ptr<OitTechnique> make_oit_technique(const std::string& name, const OitParams& p) {
  if (const TechniqueRow* row = find_technique(name, TechniqueFamily::Transmittance))
    return row->make_oit(name, p);
  std::string valid;
  for (const TechniqueRow* r : family_rows(TechniqueFamily::Transmittance))
    valid += (valid.empty() ? "" : ", ") + r->display_name();
  throw InputError("oit technique '" + name + "': expected one of " + valid);
}

}  // namespace mb
