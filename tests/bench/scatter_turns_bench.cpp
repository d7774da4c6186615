// How the prefiltered rows' answers move as the camera turns (docs/scattering.md §3.3; seed 004
// §2.3 and Figure 6: point-sampled rectification leaves stripes that move with the camera). Not a
// timing benchmark: a measurement that `scatter`'s per-camera errors cannot make. A turning camera
// keeps its position, so the exact in-scattering along a fixed world direction stays the same;
// only its rectified map moves (its bounds of phi and theta follow the view). So each camera of
// the scattering dataset's house keeps its own pixels' rays while the rectified map is built for
// the camera turned about the vertical axis by 0, 0.1, ..., 0.7 degrees, and the flicker of a
// row is the spread of its answer per pixel over the 8 maps:
//   flicker = Σ_p std_k(L_k(p)) / Σ_p L_max(p),
// L the transmittance-weighted lit length, L_max its value all lit (seed 000 §3.2's L1 measure, as
// mean_error, but without the phase function's weights, so its mean error differs a little from
// `scatter`'s). Pixels within 8 columns of the image's sides, which a turned map may not cover,
// are left out. Deterministic: each ray is answered on its own and the sums run in pixel order.
//   scatter_turns_bench [LIGHT_RESOLUTION [GUARD_BAND]]   (defaults 1024 and 64)
#include <omp.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <string>
#include <vector>

#include "raster/render_camera.h"
#include "raster/render_view.h"
#include "scatter/scatter_run.h"

namespace mb {
namespace {

constexpr int kTurns = 8, kMargin = 8;
constexpr double kStepDegrees = 0.1;

CameraDesc turned(const CameraDesc& camera, double degrees) {
  const double a = degrees * std::numbers::pi / 180;
  const Eigen::Vector3d d = camera.target - camera.position;
  CameraDesc out = camera;
  out.target = camera.position + Eigen::Vector3d(d.x() * std::cos(a) + d.z() * std::sin(a), d.y(),
                                                 -d.x() * std::sin(a) + d.z() * std::cos(a));
  return out;
}

std::vector<double> lit_lengths(const ScatterTechnique& t, const std::vector<ScatterRay>& rays) {
  std::vector<double> out(rays.size());
#pragma omp parallel for schedule(dynamic, 256)
  for (long p = 0; p < long(rays.size()); ++p) out[size_t(p)] = t.lit_length(rays[size_t(p)]);
  return out;
}

int run(int light_resolution, double guard_band) {
  Config config(scatter_run_option_specs());
  ScatterRunOptions options = scatter_run_options_from(config);
  options.light_resolution = light_resolution, options.guard_band = guard_band;
  const std::vector<ScatterScene> scenes = scatter_scenes(load_dataset("scattering"));
  const ScatterScene* house = nullptr;
  for (const auto& s : scenes)
    if (s.scene.name == "house") house = &s;
  if (!house) return std::fprintf(stderr, "no scene house in dataset scattering\n"), 1;
  const int threads = omp_get_max_threads();

  LightViewDesc view = house->scene.views.at(0), low = view;
  view.resolution = options.reference_resolution, low.resolution = light_resolution;
  const LayerStack stack = render_view(house->scene, view, threads);
  const LightFrame frame(view, house->scene.mesh.vertices);
  const LightDepthMap light(frame, stack);
  const LayerStack low_stack = render_view(house->scene, low, threads);
  const LightFrame low_frame(low, house->scene.mesh.vertices);
  const LightDepthMap rectify(low_frame, low_stack);

  std::printf("rectified maps %d², guard band %g, reference maps %d², %d turns of %g degree\n\n",
              light_resolution, guard_band, options.reference_resolution, kTurns, kStepDegrees);
  std::printf("| camera | technique | resample | mean error over the turns | flicker |\n");
  std::printf("|---|---|---|---|---|\n");
  for (const CameraDesc& camera : house->scene.cameras) {
    const CameraImage image = render_camera(house->scene, camera, threads);
    const CameraFrame view_frame(camera);
    std::vector<ScatterRay> rays;
    for (int y = 0; y < image.height; ++y)
      for (int x = kMargin; x < image.width - kMargin; ++x) {
        const size_t p = size_t(y) * image.width + x;
        ScatterRay ray;
        ray.direction = view_frame.ray(x, y), ray.pixel = p, ray.length = options.max_distance;
        if (image.offsets[p] != image.offsets[p + 1])
          ray.length = (image.point[image.offsets[p]] - camera.position).norm();
        rays.push_back(ray);
      }
    const double sigma = house->medium.extinction;
    double all_lit = 0;
    for (const auto& ray : rays) all_lit += transmittance_integral(0, ray.length, sigma);
    std::vector<CameraDesc> turns;
    for (int k = 0; k < kTurns; ++k) turns.push_back(turned(camera, k * kStepDegrees));
    const auto reference = make_scatter_technique("exact", scatter_params(options));
    reference->prepare({&light, &house->scene, &view, &camera, camera.position, sigma, &rectify});
    const std::vector<double> exact = lit_lengths(*reference, rays);
    for (const std::string technique : {"pss_exact", "pss_msm4", "pss_msm6"})
      for (const std::string resample : {"point", "filtered"}) {
        options.resample = resample;
        const auto t = make_scatter_technique(technique, scatter_params(options));
        std::vector<double> sum(rays.size()), square(rays.size());
        double error = 0;
        for (const CameraDesc& turn : turns) {
          t->prepare({&light, &house->scene, &view, &turn, camera.position, sigma, &rectify});
          const std::vector<double> l = lit_lengths(*t, rays);
          for (size_t p = 0; p < rays.size(); ++p) {
            sum[p] += l[p], square[p] += l[p] * l[p];
            error += std::abs(l[p] - exact[p]);
          }
        }
        double spread = 0;
        for (size_t p = 0; p < rays.size(); ++p) {
          const double mean = sum[p] / kTurns;
          spread += std::sqrt(std::max(square[p] / kTurns - mean * mean, 0.0));
        }
        std::printf("| %s | %s | %s | %.5f | %.3e |\n", camera.name.c_str(), technique.c_str(),
                    resample.c_str(), error / kTurns / all_lit, spread / all_lit);
      }
  }
  return 0;
}

}  // namespace
}  // namespace mb

int main(int argc, char** argv) {
  const int resolution = argc > 1 ? std::atoi(argv[1]) : 1024;
  const double guard = argc > 2 ? std::atof(argv[2]) : 64;
  if (resolution < 1 || !(guard >= 0) || 2 * guard >= resolution) {
    std::fprintf(stderr, "usage: scatter_turns_bench [LIGHT_RESOLUTION [GUARD_BAND]]\n");
    return 2;
  }
  return mb::run(resolution, guard);
}
