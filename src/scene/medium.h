#pragma once
// A homogeneous participating medium (docs/scattering.md §1): it fills
// all space, the camera sits inside it, and a directional light reaches every point it does not
// shadow with its full irradiance (no extinction along the light's path, as seed 004 §2.2).
#include <optional>
#include <string>

namespace mb {

class YamlMap;

enum class PhaseKind { Isotropic, HenyeyGreenstein };

struct MediumDesc {
  double extinction = 0;  // sigma_t > 0, per scene unit
  double albedo = 0;      // rho in [0, 1]: sigma_s = rho sigma_t
  PhaseKind phase = PhaseKind::Isotropic;
  double g = 0;       // Henyey-Greenstein's asymmetry in (-1, 1); > 0 scatters forward
  std::string where;  // "file:line:column" of its albedo (or of the map), for errors found later

  double scattering() const { return albedo * extinction; }
  // The phase function, normalised over the sphere (1 / (4 pi) for isotropic), of the cosine
  // between the light's propagation direction and the direction from the scattering point towards
  // the camera: cos = 1 when the camera looks straight into the light, where g > 0 (forward
  // scattering, away from the light) is brightest.
  double phase_value(double cos_angle) const;
};

// `medium: {extinction, albedo, phase, g}` of a scene or dataset file, if the map has one; bad
// values are InputErrors naming file, line, key, value and what was expected.
std::optional<MediumDesc> parse_medium(YamlMap& parent);

}  // namespace mb
