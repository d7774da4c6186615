#include "sweep/prepared_target.h"

#include <set>

#include "sweep/oit_target.h"
#include "sweep/scatter_target.h"
#include "techniques/registry.h"
#include "util/error.h"
#include "util/number_text.h"

namespace mb {

std::string describe_transparency(const SweepSettings& s) {
  return "target transparency: lp:<candidate> on the " + describe_oit_warp(s.oit) + " depth; LP " +
         describe_oit_lp(s.oit.technique) +
         "; error: opacity-weighted |T_ref - T|; the references' own options: " +
         technique_option_text({TechniqueFamily::Transmittance}, s.oit.technique);
}

std::string map_sizes(const std::vector<ViewData>& views) {
  std::set<int> sizes;
  for (const ViewData& v : views) sizes.insert(v.map.width);
  std::string text;
  for (int size : sizes) text += (text.empty() ? "" : ", ") + std::to_string(size);
  return text;
}

PreparedTarget prepare_target(const SweepSettings& s, const DatasetDesc& dataset, bool quiet) {
  PreparedTarget p;
  if (s.target == "transparency") {
    p.frames = render_dataset_frames(dataset, s.eval.threads);
    // The warped depth spans [0, 1]: an interval that misses part of it cannot hold the pixels'
    // own fragments (docs/transparency.md §3).
    const auto& lp = s.eval.technique.lp;
    if (lp.lo > 0 || lp.hi < 1)
      throw InputError("lp.lo, lp.hi: [" + round_trip(lp.lo) + ", " + round_trip(lp.hi) +
                       "] excludes part of the warped depth [0, 1] of target transparency "
                       "(expected lp.lo <= 0 and lp.hi >= 1)");
    p.target = make_oit_target(p.frames, s.oit, s.eval.threads);
  } else if (s.target == "scattering") {
    p.scatter_scenes = scatter_scenes(dataset);
    p.scatter_frames = prepare_scatter_frames(p.scatter_scenes, s.scatter, s.eval.threads);
    p.target = make_scatter_target(p.scatter_frames, s.scatter, s.eval.threads);
  } else {
    // A dataset's light_angles, or a scene's view naming its own light angle, make area lights as
    // light.angle does (sweep_settings_from refuses those); refused before rendering.
    const std::vector<Scene> scenes = build_dataset_scenes(dataset);
    for (const auto& scene : scenes)
      for (const auto& view : rendered_views(scene, dataset, s.resolution, s.eval))
        if (view.light_angle_deg > 0)
          throw InputError(dataset.file + ": view " + scene.name + "/" + view.name +
                           " is lit by an area light of " + round_trip(view.light_angle_deg) +
                           " degrees (the dataset's light_angles or the scene's view); a shadow "
                           "sweep ranks bases by Problem 1's bound on the hard shadow, expected a "
                           "dataset without light angles (eval takes them)");
    p.views = prepare_views(scenes, dataset, s.resolution, s.eval, quiet);
    check_lp_interval(p.views, s.eval.technique.lp.lo, s.eval.technique.lp.hi);
    p.target = make_shadow_target(p.views, s.eval);
  }
  for (const auto& name : s.references) p.target->check_reference(name);
  return p;
}

}  // namespace mb
