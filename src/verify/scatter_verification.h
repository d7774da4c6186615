#pragma once
// `verify`'s scattering rows (docs/scattering.md §6): the prefiltered moment rows' bounds on a view
// ray's shadowed fraction against Problem 1 on the same row-prefiltered moments. pss_msm4 and
// pss_msm6 reconstruct Hamburger's bounds on R (scatter.beta 0: the sharp lower bound G, 1: the
// upper bound G + w_1); pss_lp:power4 and pss_lp:power6 solve the LP at the same beta on an
// interval wide enough for Hamburger's canonical nodes, so the two must agree to the row's
// tolerance. The rays are seeded random pixels of every light view and camera of a scattering
// dataset, each along its real rectified row, ending at the pixel's surface or at a seeded point in
// front of it.
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "raster/layer_stack.h"
#include "scatter/scatter_run.h"
#include "techniques/scatter/scatter_technique.h"

namespace mb {

struct ScatterVerifyRow {
  std::string technique, lp_technique;  // lp_technique: the pss_lp: row it was compared with
  double beta = 0;                      // scatter.beta of both
  // The check: "equal", |F_closed - F_LP| within the tolerance against the continuous LP on the
  // recipe's interval (its minimum at beta 0, its maximum by reflection at beta 1).
  std::string kind;
  double lo = 0, hi = 0;  // the LP's interval of normalised depth
  double tolerance = 0;   // in the shadowed fraction
  size_t rays = 0;
  // Rays not compared: the closed form answered by its fall-back (a singular Hankel matrix: a row
  // prefix of one depth), or the LP gave no certified answer.
  size_t undefined = 0, lp_failures = 0;
  size_t compared = 0, beyond = 0;
  // Over the compared rays: the largest |F_closed - F_LP|.
  double largest = 0;
  std::string worst;  // where it lies: scene/view/camera, pixel and ray length
  // Fails verify (exit 5): a compared ray beyond the tolerance, or no ray compared at all.
  bool passed() const { return beyond == 0 && compared > 0; }
};

// The scattering rows with a verify recipe (PrefilteredScatter::verify_recipe), in registry order;
// InputError naming them for any other.
std::vector<std::string> scatter_verify_names();
void check_scatter_verify_technique(const std::string& technique);

// The rays verify asks: per light view and camera, layer 0 of the view at the rectified map's
// resolution and seeded random view rays.
struct ScatterVerifyFrame {
  std::string where;  // scene/view/camera
  const Scene* scene = nullptr;
  const LightViewDesc* view = nullptr;
  const CameraDesc* camera = nullptr;
  const LightDepthMap* light = nullptr;
  double extinction = 0;
  std::vector<ScatterRay> rays;
  std::vector<int> x, y;  // each ray's pixel, for the report
};
struct ScatterVerifyFrames {
  std::vector<ScatterScene> scenes;
  std::vector<std::unique_ptr<LightViewDesc>> views;
  std::vector<std::unique_ptr<LayerStack>> stacks;
  std::vector<std::unique_ptr<LightFrame>> light_frames;
  std::vector<std::unique_ptr<LightDepthMap>> lights;
  std::vector<ScatterVerifyFrame> frames;
};
// `rays` per light view and camera of the dataset's scatter scenes, their maps at `resolution`:
// even rays end at the pixel's first surface (scatter.max_distance's default where it sees none),
// odd ones at a seeded fraction of that length.
std::unique_ptr<ScatterVerifyFrames> scatter_verify_frames(const DatasetDesc& dataset,
                                                           int resolution, int rays, uint64_t seed,
                                                           int threads);

using ScatterMaker = std::function<std::unique_ptr<ScatterTechnique>(const ScatterParams&)>;

// `technique`'s row (made by `make`, which a test may replace with a broken closed form) against
// its recipe's pss_lp row at `beta`, both at moment bias 0, their rectified maps at `resolution`
// with a guard band of resolution / 16 (scatter.guard_band's default share).
ScatterVerifyRow verify_scatter_row(const std::string& technique, const ScatterMaker& make,
                                    double beta, const std::vector<ScatterVerifyFrame>& frames,
                                    int resolution);
// verify_scatter_row with the row's own factory.
ScatterVerifyRow verify_scatter_row(const std::string& technique, double beta,
                                    const std::vector<ScatterVerifyFrame>& frames, int resolution);

}  // namespace mb
