#pragma once
// The light views and cameras `scatter` measures (docs/scattering.md §4), each prepared once: the
// light view's layer 0 at scatter.reference_resolution (and at scatter.light_resolution for the
// prefiltered rows), a camera's view rays and the surfaces they end at, and per pixel sigma_s f E
// and S_max. `scatter` prepares one light view and camera at a time; a scattering sweep keeps them
// all, since every candidate is measured on the same rays.
#include <memory>
#include <vector>

#include "raster/render_camera.h"
#include "scatter/scatter_run.h"

namespace mb {

// A light view's depth maps as the scattering rows read them (the layer stacks are not kept).
struct ScatterLight {
  LightViewDesc view;  // its resolution: scatter.reference_resolution
  std::unique_ptr<LightFrame> frame, rectify_frame;
  std::unique_ptr<LightDepthMap> map, rectify_map;  // rectify_map null: `map` serves the rows
  const LightDepthMap& rectify() const { return rectify_map ? *rectify_map : *map; }
};
std::shared_ptr<const ScatterLight> render_scatter_light(const Scene& scene, LightViewDesc view,
                                                         const ScatterRunOptions& options,
                                                         int threads);

// One light view and camera: its view rays, the surface radiance they end at (attenuated), and
// per pixel sigma_s f E and S_max (irradiance E = 1).
struct ScatterFrame {
  const ScatterScene* scene = nullptr;
  std::shared_ptr<const ScatterLight> light;
  const CameraDesc* camera = nullptr;
  int width = 0, height = 0;
  std::vector<ScatterRay> rays;
  std::vector<Eigen::Vector3d> surface;
  std::vector<double> factor, s_max;
  size_t epipole_pixels = 0;  // rays within scatter.epipole_degrees of the light's axis
  ScatterSetup setup() const;
  std::string name() const;  // "<scene>/<view>/<camera>"
};
ScatterFrame make_scatter_frame(const ScatterScene& scene,
                                std::shared_ptr<const ScatterLight> light, const CameraDesc& camera,
                                const CameraImage& image, const ScatterRunOptions& options);

// Every light view and camera of `scenes` (which must outlive the frames), in scatter's order:
// scene, light view, camera.
std::vector<ScatterFrame> prepare_scatter_frames(const std::vector<ScatterScene>& scenes,
                                                 const ScatterRunOptions& options, int threads);

// I of every pixel of `frame` under `technique` (prepared for it): its lit length times sigma_s f
// E, in parallel over image rows; each pixel is answered on its own, so any thread count gives
// the same bits.
std::vector<double> frame_inscatter(const ScatterTechnique& technique, const ScatterFrame& frame,
                                    int threads);

}  // namespace mb
