// Ray marching (docs/scattering.md §3; seed 004 §2.1): N shadow-map tests at equidistant points of
// the view ray, shifted together by one seeded jitter per pixel (interleaved sampling), each
// weighting its N-th of the ray by that piece's transmittance integral. Its error's mean falls
// like 1/N (docs/scattering.md §3); the seed compares 32 and 128 samples with the moments.
#include <charconv>
#include <cmath>

#include "techniques/registry.h"
#include "techniques/scatter/scatter_technique.h"
#include "util/error.h"

namespace mb {

const TechniqueOption kRaymarchSeed{
    {"scatter.seed", OptionType::Integer, "1",
     "raymarch: seed of the per-pixel jitter (docs/scattering.md §3): the answers are a function "
     "of it and the pixel only, whatever the thread count.",
     0, 2147483647}};

namespace {

constexpr int kMaxSamples = 1 << 20;

// SplitMix64's finaliser (Steele et al. 2014): a well-mixed 64-bit value per (seed, pixel), so that
// each pixel's jitter depends on nothing but its index and the seed.
uint64_t mix(uint64_t z) {
  z += 0x9e3779b97f4a7c15ull;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

int samples_of(const std::string& name) {
  const std::string digits = name.substr(name.find(':') + 1);
  int n = 0;
  const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), n);
  if (digits.empty() || error != std::errc() || end != digits.data() + digits.size() || n < 1 ||
      n > kMaxSamples)
    throw InputError("technique '" + name +
                     "': expected raymarch:<N> with N samples, an integer in [1, " +
                     std::to_string(kMaxSamples) + "]");
  return n;
}

class RayMarch : public ScatterTechnique {
 public:
  RayMarch(const std::string& name, const ScatterParams& params)
      : ScatterTechnique(name),
        samples_(samples_of(name)),
        seed_(uint64_t(params.technique.integer(kRaymarchSeed))) {}
  double lit_length(const ScatterRay& ray) const override {
    const LightDepthMap& map = *setup_.light;
    const double sigma = setup_.extinction, step = ray.length / samples_;
    const double jitter = double(mix(mix(seed_) ^ ray.pixel) >> 11) * 0x1p-53;
    const Eigen::Vector3d r0 = map.frame->to_raster(setup_.camera);
    const Eigen::Vector3d dr = map.frame->to_raster(setup_.camera + ray.direction) - r0;
    double lit = 0;
    for (int k = 0; k < samples_; ++k) {
      const double t = (k + jitter) * step;
      const Eigen::Vector3d r = r0 + t * dr;
      if (r.z() <= map.at(r.x(), r.y()))
        lit += transmittance_integral(k * step, (k + 1) * step, sigma);
    }
    return lit;
  }

 private:
  int samples_;
  uint64_t seed_;
};

std::vector<TechniqueRow> rows() {
  return {{.name = "raymarch:",
           .family = TechniqueFamily::Scattering,
           .rank = 10,
           .summary = "ray marching: N shadow-map tests at equidistant points with one seeded "
                      "jitter per pixel (scatter.seed), each weighted by its piece's "
                      "transmittance (docs/scattering.md §3)",
           .storage = "shadow map (layer 0)",
           .bound = "none: a sample estimate, too bright or too dark",
           .unproven_reason = "a sample estimate: its error has either sign",
           .options = {&kRaymarchSeed},
           .default_run = true,
           .example = "raymarch:32",
           .make_scatter = [](const std::string& name,
                              const ScatterParams& params) -> std::unique_ptr<ScatterTechnique> {
             return std::make_unique<RayMarch>(name, params);
           },
           .parameter = "<N>"}};
}

const TechniqueRegistration kRegistered(rows);

}  // namespace

}  // namespace mb
