#pragma once
// Camera views of the techniques' shadows (issue 34; the seed paper's Figures 1 and 6): what a
// camera sees of a scene, lit by one light view, with each technique's shadow. Every visible point
// that faces the light becomes a receiver of that light view: projected into its shadow map
// (nearest texel), with its own depth z_f and bias delta_f from its triangle's plane
// (docs/reference.md §3) and the evaluation's reference (shadow/fragments.h, receiver_test), or
// under an area light that light's shadow at the same point (shadow/area_light.h). The techniques
// then run through evaluate_technique unchanged; report/camera_images.h shades the images.
#include <functional>
#include <string>
#include <vector>

#include "eval/evaluation.h"
#include "raster/render_camera.h"
#include "scene/scene.h"

namespace mb {

struct CameraView {
  std::string camera;
  int width = 0, height = 0;
  // The light view's shadow map with the camera's receivers as its fragments (in texel order).
  ViewData receivers;
  std::vector<uint32_t> pixel;  // per receiver: its pixel
  // Per pixel: max(0, n . l) of the nearest surface seen (0 facing away from the light), -1
  // background.
  std::vector<float> diffuse;
  // Every surface a pixel shows (CameraImage's), nearest first: its diffuse term, its share of the
  // pixel (its alpha times the transmittance of those in front: front-to-back compositing, 1 for
  // an opaque scene's one surface) and its receiver (-1: it faces away from the light). The sky
  // takes what the shares leave.
  std::vector<uint64_t> surface_offsets;
  std::vector<float> surface_diffuse, surface_share;
  std::vector<int64_t> surface_receiver;
};

// `light`: the view as rendered for `light_view` (its resolution). The camera sees `scene`.
CameraView camera_view(const Scene& scene, const LightViewDesc& light, const ViewData& light_view,
                       const CameraDesc& camera, const EvalSettings& settings);

// InputError unless some scene of `dataset` names a camera (checked before any work).
void check_dataset_cameras(const std::vector<Scene>& scenes, const DatasetDesc& dataset);
// One camera seeing a scene lit by one of its light views, with each technique's shadow per
// receiver: under an area light its own shadow first, named kAreaLightShadow (the reference),
// then the techniques in the order asked for; `reference` marks the view's reference
// (is_view_reference), which has no difference image.
struct CameraShadows {
  std::string scene, light;
  CameraView view;
  std::vector<std::string> names;
  std::vector<std::vector<double>> shadows;
  std::vector<bool> reference;
};

// Every camera of every scene (`scenes`, built from `dataset`), lit by each of the scene's light
// views (`views` as prepare_views rendered them at `resolution`), for `techniques`: `each` is
// called per camera and light view as soon as it is computed, so one is held at a time.
void evaluate_camera_views(const std::vector<Scene>& scenes, const DatasetDesc& dataset,
                           const std::vector<ViewData>& views,
                           const std::vector<std::string>& techniques, int resolution,
                           const EvalSettings& settings, bool quiet,
                           const std::function<void(const CameraShadows&)>& each);

}  // namespace mb
