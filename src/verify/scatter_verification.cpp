#include "verify/scatter_verification.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "raster/render_camera.h"
#include "raster/render_view.h"
#include "scene/procedural.h"
#include "techniques/registry.h"
#include "techniques/scatter/prefiltered_scatter.h"
#include "util/error.h"
#include "util/number_text.h"

namespace mb {

namespace {

// scatter.max_distance's default: the length of a ray that sees no surface, as `scatter` gives it.
double default_max_distance() {
  ScatterRunOptions run;
  read_options(Config(option_specs(scatter_run_options())), scatter_run_options(), run);
  return run.max_distance;
}

// The rows verify judges answer through their rectified row (PrefilteredScatter::shadowed).
const PrefilteredScatter& prefiltered(const ScatterTechnique& t) {
  const auto* p = dynamic_cast<const PrefilteredScatter*>(&t);
  if (!p) throw std::logic_error(t.name() + ": verify's scattering rows are prefiltered rows");
  return *p;
}

// A scattering row's verify recipe (PrefilteredScatter::verify_recipe), none for the others.
std::optional<ScatterVerifyRecipe> recipe_of(const std::string& name) {
  const auto technique = make_scatter_technique(name, ScatterParams{});
  const auto* p = dynamic_cast<const PrefilteredScatter*>(technique.get());
  return p ? p->verify_recipe() : std::nullopt;
}

}  // namespace

std::vector<std::string> scatter_verify_names() {
  std::vector<std::string> names;
  for (const TechniqueRow* row : family_rows(TechniqueFamily::Scattering))
    if (!row->prefix() && recipe_of(row->name)) names.push_back(row->name);
  return names;
}

void check_scatter_verify_technique(const std::string& technique) {
  const auto names = scatter_verify_names();
  if (std::find(names.begin(), names.end(), technique) != names.end()) return;
  std::string valid;
  for (const auto& n : names) valid += (valid.empty() ? "" : ", ") + n;
  throw InputError("verify.scatter_techniques: '" + technique + "': expected one of " + valid +
                   " (the prefiltered rows whose bounds pss_lp computes on the same moments)");
}

std::unique_ptr<ScatterVerifyFrames> scatter_verify_frames(const DatasetDesc& dataset,
                                                           int resolution, int rays, uint64_t seed,
                                                           int threads) {
  auto out = std::make_unique<ScatterVerifyFrames>();
  out->scenes = scatter_scenes(dataset);
  const double max_distance = default_max_distance();
  SeededRandom rng(seed);
  for (const ScatterScene& s : out->scenes) {
    std::vector<CameraImage> images;
    for (const auto& camera : s.scene.cameras)
      images.push_back(render_camera(s.scene, camera, threads));
    for (const LightViewDesc& desc : s.scene.views) {
      auto view = std::make_unique<LightViewDesc>(desc);
      view->resolution = resolution;
      check_render_memory(resolution, "verify.scatter_resolution");
      out->stacks.push_back(std::make_unique<LayerStack>(render_view(s.scene, *view, threads)));
      out->light_frames.push_back(std::make_unique<LightFrame>(*view, s.scene.mesh.vertices));
      out->lights.push_back(
          std::make_unique<LightDepthMap>(*out->light_frames.back(), *out->stacks.back()));
      for (size_t c = 0; c < s.scene.cameras.size(); ++c) {
        const CameraDesc& camera = s.scene.cameras[c];
        const CameraImage& image = images[c];
        const CameraFrame frame(camera);
        ScatterVerifyFrame f;
        f.where = s.scene.name + "/" + view->name + "/" + camera.name;
        f.scene = &s.scene, f.view = view.get(), f.camera = &camera;
        f.light = out->lights.back().get(), f.extinction = s.medium.extinction;
        for (int i = 0; i < rays; ++i) {
          const int x = std::min(image.width - 1, int(rng.uniform() * image.width));
          const int y = std::min(image.height - 1, int(rng.uniform() * image.height));
          const size_t p = size_t(y) * image.width + x;
          ScatterRay ray;
          ray.direction = frame.ray(x, y), ray.pixel = p, ray.length = max_distance;
          if (image.offsets[p] != image.offsets[p + 1])
            ray.length = (image.point[image.offsets[p]] - frame.position()).norm();
          const double fraction = rng.uniform(0.02, 1);  // drawn for every ray: a fixed sequence
          if (i % 2 == 1) ray.length *= fraction;
          f.rays.push_back(ray), f.x.push_back(x), f.y.push_back(y);
        }
        out->frames.push_back(std::move(f));
      }
      out->views.push_back(std::move(view));
    }
  }
  return out;
}

ScatterVerifyRow verify_scatter_row(const std::string& technique, const ScatterMaker& make,
                                    double beta, const std::vector<ScatterVerifyFrame>& frames,
                                    int resolution) {
  check_scatter_verify_technique(technique);
  const TechniqueRow& row_of = technique_row(technique, TechniqueFamily::Scattering);
  const ScatterVerifyRecipe recipe = *recipe_of(technique);
  ScatterVerifyRow row;
  row.technique = technique, row.lp_technique = recipe.lp_technique, row.beta = beta;
  row.lo = recipe.lo, row.hi = recipe.hi, row.tolerance = recipe.tolerance;
  ScatterParams closed;
  closed.light_resolution = resolution, closed.guard_band = resolution / 16.0, closed.beta = beta;
  // Hamburger's bounds themselves: no moment bias (as verify's hard-shadow rows, alpha = 0).
  for (const TechniqueOption* o : row_of.options)
    if (o->moment_bias) closed.technique.set(*o, 0);
  // pss_lp at the same beta, continuous on the recipe's interval (the exchange method, certified):
  // at beta 0 the sharp lower bound G, at 1 the maximum G+ by reflection (docs/reference.md §2,
  // "The maximum"), both attained by Hamburger's canonical distribution where its nodes lie in
  // the interval, so both must equal the closed form's.
  ScatterParams lp = closed;
  row.kind = "equal";
  lp.technique.lp = lp::Discretization{recipe.lo, recipe.hi, 256, false};
  lp.technique.lp.continuous = true;
  const auto mine = make(closed);
  const auto reference = make_scatter_technique(recipe.lp_technique, lp);
  const PrefilteredScatter& m = prefiltered(*mine);
  const PrefilteredScatter& r = prefiltered(*reference);
  for (const ScatterVerifyFrame& f : frames) {
    const ScatterSetup setup{f.light,      f.scene, f.view, f.camera, f.camera->position,
                             f.extinction, f.light};
    mine->prepare(setup);
    reference->prepare(setup);
    // Ray by ray, so that each row's fall-back (a singular Hankel matrix, an LP without a
    // certified answer) is told by its failure count: those rays are counted, not compared.
    const size_t n = f.rays.size();
    std::vector<double> answer(n), lp_answer(n);
    std::vector<char> fell_back(n), lp_failed(n);
    for (size_t i = 0; i < n; ++i) {
      const size_t before = mine->failures(), lp_before = reference->failures();
      answer[i] = m.shadowed(f.rays[i]);
      lp_answer[i] = r.shadowed(f.rays[i]);
      fell_back[i] = mine->failures() != before;
      lp_failed[i] = reference->failures() != lp_before;
    }
    for (size_t i = 0; i < n; ++i, ++row.rays) {
      if (fell_back[i] || lp_failed[i]) {
        row.undefined += fell_back[i];
        row.lp_failures += lp_failed[i];
        continue;
      }
      ++row.compared;
      const double d = std::abs(answer[i] - lp_answer[i]);
      row.beyond += !(d <= row.tolerance);  // NaN too
      if (d > row.largest) {
        row.largest = d;
        row.worst = f.where + " pixel (" + std::to_string(f.x[i]) + ", " + std::to_string(f.y[i]) +
                    "), length " + format_number(f.rays[i].length, "%.4g");
      }
    }
  }
  return row;
}

ScatterVerifyRow verify_scatter_row(const std::string& technique, double beta,
                                    const std::vector<ScatterVerifyFrame>& frames, int resolution) {
  check_scatter_verify_technique(technique);
  const auto make = [&](const ScatterParams& p) { return make_scatter_technique(technique, p); };
  return verify_scatter_row(technique, make, beta, frames, resolution);
}

}  // namespace mb
