#pragma once
// Single-scattering techniques (docs/scattering.md §3): each answers, for one view ray of a camera
// inside a homogeneous medium, the transmittance-weighted lit length
//   L = ∫_0^s exp(-sigma_t t) V(p + t w) dt
// of the ray against one light view's hard shadow map; the scatter stage multiplies it by
// sigma_s f E (docs/scattering.md §1). A technique sees the light view and the camera once
// (`prepare`, where a prefiltered one builds its rectified map) and then answers rays, each on its
// own, so that the answers are the same for any thread count.
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "raster/layer_stack.h"
#include "scene/light_view.h"
#include "scene/scene.h"
#include "techniques/technique.h"
#include "util/eigen.h"

namespace mb {

// A light view's hard shadow map as scattering reads it: layer 0 of its stack (the nearest surface
// per texel centre), a texel standing for its whole square (nearest lookup). Texels with no surface
// hold +infinity, so that every point over them is lit, and points outside the map are lit
// (docs/scattering.md §2).
struct LightDepthMap {
  const LightFrame* frame = nullptr;  // the view's projection, world -> raster
  int resolution = 0;
  std::vector<double> depth;  // per texel, row-major; +infinity where empty

  LightDepthMap(const LightFrame& frame, const LayerStack& stack);
  // The stored depth at raster (x, y): +infinity outside the map or over an empty texel.
  double at(double x, double y) const {
    if (!(x >= 0 && y >= 0 && x < resolution && y < resolution))
      return std::numeric_limits<double>::infinity();
    return depth[size_t(int(y)) * size_t(resolution) + size_t(int(x))];
  }
  // V at a world point: lit when its light depth is not beyond the stored depth.
  bool lit(const Eigen::Vector3d& world) const {
    const Eigen::Vector3d r = frame->to_raster(world);
    return r.z() <= at(r.x(), r.y());
  }
};

// What a technique is given once per light view and camera: the reference's depth map, and the
// scene, light view and camera themselves for a technique that renders a map of its own (a
// prefiltered one's rectified map, seed 004 §2.2-2.3).
struct ScatterSetup {
  const LightDepthMap* light = nullptr;
  const Scene* scene = nullptr;
  const LightViewDesc* view = nullptr;
  const CameraDesc* camera_desc = nullptr;
  Eigen::Vector3d camera = Eigen::Vector3d::Zero();  // the camera's position p
  double extinction = 0;                             // sigma_t of the scene's medium
  // Layer 0 of the same light view at scatter.light_resolution, which the prefiltered techniques
  // resample into their rectified map (docs/scattering.md §3.1).
  const LightDepthMap* rectify_light = nullptr;
};

// One pixel's view ray: from the camera p along the unit direction w to the first surface at
// distance `length` (scatter.max_distance where the pixel sees none).
struct ScatterRay {
  Eigen::Vector3d direction = Eigen::Vector3d::UnitZ();
  double length = 0;
  uint64_t pixel = 0;  // the pixel's index in its image, for seeded per-pixel randomness
};

// How the rectified map reads the light map (scatter.resample; docs/scattering.md §3.1): the
// nearest light texel's depth, or seed 004 §2.3's filtered moment sample (Algorithm 1).
enum class Resample { Point, Filtered };

// What the scattering rows are made with: each technique's own options (their records in the
// technique's file, e.g. raymarch's scatter.seed), read from the config by the scatter stage, and
// the family's scatter.* records (scatter/scatter_run.cpp, which hold their defaults).
struct ScatterParams {
  TechniqueParams technique;
  // The rectified map of the prefiltered rows (docs/scattering.md §3.1): its texels along r and
  // rows along phi (scatter.light_resolution), and the depth texels left free at either end of a
  // row's range of inclinations (scatter.guard_band).
  int light_resolution = 0;
  double guard_band = 0;
  Resample resample = Resample::Point;  // scatter.resample
  // scatter.beta: the blend G + beta (G+ - G) of the moment rows' bounds on the shadowed fraction.
  double beta = 0;
};

class ScatterTechnique {
 public:
  virtual ~ScatterTechnique() = default;
  const std::string& name() const { return name_; }
  // Called once per light view and camera before any ray (not concurrently with `lit_length`).
  virtual void prepare(const ScatterSetup& setup) { setup_ = setup; }
  // L of one ray; const and safe to call from several threads after `prepare`.
  virtual double lit_length(const ScatterRay& ray) const = 0;
  // Rays answered by a fall-back because the technique's own answer failed (an LP without a
  // certified answer), since it was made.
  virtual size_t failures() const { return 0; }
  // The basis and format its moment map is stored in when that is not double (pss_msm4_16bit,
  // pss_msm6_10bit): pss_lp_stored:<name> solves Problem 1 over that format's moment box.
  struct StoredFormat {
    std::vector<std::string> basis;
    MomentStorage storage;
  };
  virtual std::optional<StoredFormat> stored_format() const { return std::nullopt; }

 protected:
  explicit ScatterTechnique(std::string name) : name_(std::move(name)) {}
  ScatterSetup setup_;

 private:
  std::string name_;
};

// ∫_a^b exp(-sigma t) dt for 0 <= a <= b, in the form that keeps its relative accuracy for small
// sigma (b - a) (expm1).
inline double transmittance_integral(double a, double b, double sigma) {
  return std::exp(-sigma * a) * -std::expm1(-sigma * (b - a)) / sigma;
}

// The scattering technique `name` made by its registry row (techniques/registry.h, family
// Scattering); InputError naming the valid ones otherwise.
std::unique_ptr<ScatterTechnique> make_scatter_technique(const std::string& name,
                                                         const ScatterParams& params);

}  // namespace mb
