#include "scene/medium.h"

#include <cmath>
#include <limits>
#include <numbers>

#include "util/number_text.h"
#include "util/yaml_reader.h"

namespace mb {

double MediumDesc::phase_value(double cos_angle) const {
  constexpr double kSphere = 4 * std::numbers::pi;
  if (phase == PhaseKind::Isotropic) return 1 / kSphere;
  // Henyey and Greenstein (1941): (1 - g^2) / (4 pi (1 + g^2 - 2 g cos)^(3/2)), whose integral
  // over the sphere is 1 for every g in (-1, 1) (tests/scene_medium_test.cpp checks it).
  const double c = std::clamp(cos_angle, -1.0, 1.0);
  const double denominator = 1 + g * g - 2 * g * c;
  return (1 - g * g) / (kSphere * denominator * std::sqrt(denominator));
}

std::optional<MediumDesc> parse_medium(YamlMap& parent) {
  if (!parent.has("medium")) return std::nullopt;
  YamlMap m = parent.map("medium");
  MediumDesc medium;
  const double inf = std::numeric_limits<double>::infinity();
  if (!m.has("extinction")) m.fail("", "a medium needs `extinction` (sigma_t > 0, per scene unit)");
  medium.extinction = *m.number("extinction", -inf, inf);
  if (!(medium.extinction > 0))
    m.fail("extinction", "expected the extinction coefficient sigma_t > 0 (per scene unit), got " +
                             round_trip(medium.extinction));
  medium.albedo = m.number("albedo", 1, -inf, inf);
  if (!(medium.albedo >= 0 && medium.albedo <= 1))
    m.fail("albedo", "expected the scattering albedo in [0, 1], got " + round_trip(medium.albedo));
  const std::string phase = m.string("phase").value_or("isotropic");
  if (phase == "henyey_greenstein")
    medium.phase = PhaseKind::HenyeyGreenstein;
  else if (phase != "isotropic")
    m.fail("phase", "expected isotropic or henyey_greenstein, got '" + phase + "'");
  medium.g = m.number("g", 0, -inf, inf);
  if (!(medium.g > -1 && medium.g < 1))
    m.fail("g", "expected Henyey-Greenstein's asymmetry g in (-1, 1), got " + round_trip(medium.g));
  if (m.has("g") && medium.phase == PhaseKind::Isotropic && medium.g != 0)
    m.fail("g", "g applies to phase henyey_greenstein only (phase is isotropic), got " +
                    round_trip(medium.g));
  medium.where = m.where("albedo");
  m.finish();
  return medium;
}

}  // namespace mb
