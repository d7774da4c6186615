#pragma once
// Technique x view -> one shadow intensity per receiver fragment (docs/design.md §Data flow).
#include <map>
#include <string>
#include <vector>

#include "scene/dataset.h"
#include "scene/scene.h"
#include "shadow/area_light.h"
#include "shadow/fragments.h"
#include "shadow/gaussian_kernel.h"
#include "techniques/registry.h"
#include "techniques/soft/soft_technique.h"
#include "techniques/technique.h"
#include "util/progress.h"

namespace mb {

// One light view, ready to evaluate: its shadow map and receivers with their bias and reference.
struct ViewData {
  std::string scene, view;
  ShadowMap map;
  Fragments fragments;
  // Lit by an area light (soft.angle_deg > 0, docs/soft-shadows.md): fragments.pcf is then its
  // shadow, and `soft` keeps the hard reference and what soft techniques read.
  SoftReceivers soft;
};

struct EvalSettings {
  // The option records' defaults (eval/eval_config.h; written there only), as a library caller or
  // a test gets them.
  EvalSettings();
  struct Unset {};
  explicit EvalSettings(Unset) {}  // what shadow_settings_from fills
  GaussianKernel kernel;
  BiasParams
      bias;  // delta_f and the reference: techniques see z_f - delta_f (docs/reference.md §3)
  TechniqueParams technique;
  // How translucent moment maps blend (translucent.blend; the reference is always exact).
  BlendOrder blend{};
  // The light of every view that names none, unless the dataset lists light_angles (light.angle,
  // light.directions; docs/soft-shadows.md §1).
  AreaLight light;
  SoftParams soft;  // the soft techniques' constants (soft.*)
  int threads = 1;
};

// Renders one view of a scene and collects its receivers with their bias and reference: the hard
// shadow, or the area light's where view.light_angle_deg > 0.
ViewData prepare_view(const Scene& scene, const LightViewDesc& view, const EvalSettings& settings);
// The views of `scene` as prepare_views renders them (as_rendered), each at its light angle: its
// own, else settings.light's when above 0, else one view per angle the dataset lists (named
// view_<angle>deg), else 0.
std::vector<LightViewDesc> rendered_views(const Scene& scene, const DatasetDesc& dataset,
                                          int resolution, const EvalSettings& settings);
// A scene's light view as prepare_views renders it: `resolution` > 0 overrides the dataset's,
// which (when > 0) overrides the scene's.
LightViewDesc as_rendered(LightViewDesc view, const DatasetDesc& dataset, int resolution);
// Renders every view of the dataset (resolution > 0 overrides the dataset's, which overrides the
// scene's) and collects its receivers.
std::vector<ViewData> prepare_views(const DatasetDesc& dataset, int resolution,
                                    const EvalSettings& settings, bool quiet);
// The dataset's scenes, built (InputError for two scenes of one name: outputs are named
// scene_view), and their views rendered from them, for callers that need the scenes too.
std::vector<Scene> build_dataset_scenes(const DatasetDesc& dataset);
std::vector<ViewData> prepare_views(const std::vector<Scene>& scenes, const DatasetDesc& dataset,
                                    int resolution, const EvalSettings& settings, bool quiet);

// For reports: "; views lit by an area light: their reference is that light's shadow ..." naming
// the views' light angles and N, or
// "" when every view is lit by a hard light.
std::string describe_area_lights(const std::vector<ViewData>& views, const AreaLight& light);

// The LP's interval [lo, hi] must hold every depth a kernel can see (docs/reference.md §2: the
// kernel's own distribution is then feasible, and the bound is the one asked for): InputError
// naming lp.lo / lp.hi, the first view that has a depth outside and its range, otherwise.
void check_lp_interval(const std::vector<ViewData>& views, double lo, double hi);

struct TechniqueResult {
  std::vector<double> shadow;  // G per fragment, in fragment order
  size_t failures = 0;
  size_t fallbacks = 0;  // Technique::fallbacks
};

// The row of a shadow technique (hard or soft) `name`; InputError (as make_technique's) otherwise.
const TechniqueRow& shadow_row(const std::string& name);
// What images name the shadow of an area light itself: a view's reference under it.
inline constexpr const char* kAreaLightShadow = "area_light";
// Whether `technique`'s shadow is the reference of a view lit at `light_angle_deg`, which has no
// error image: the Reference row's under a hard light; under an area light the reference is the
// light's own shadow (kAreaLightShadow), and that row's is the hard shadow, which has an error.
bool is_view_reference(const std::string& technique, double light_angle_deg);
// The technique's proven darkening bound and the reason it has none (Technique::darkening_bound):
// a soft technique claims none (its row's reason).
double technique_darkening_bound(const std::string& name, const EvalSettings& settings);
std::string technique_darkening_reason(const std::string& name, const EvalSettings& settings);
// Each technique's reason for the report's darkening notes: its own, or where the views are lit by
// an area light (describe_area_lights) the reference's, the area light's shadow, which no
// technique bounds (docs/soft-shadows.md §1).
std::map<std::string, std::string> darkening_reasons(const std::vector<std::string>& techniques,
                                                     const EvalSettings& settings,
                                                     const std::vector<ViewData>& views);

// Runs `technique_name` on every receiver of `view` with one technique instance per thread.
TechniqueResult evaluate_technique(const ViewData& view, const std::string& technique_name,
                                   const EvalSettings& settings, ProgressBar* progress);

}  // namespace mb
