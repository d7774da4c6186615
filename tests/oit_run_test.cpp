// What `oit` measures (oit/oit_run.h, oit/oit_metrics.h, oit/color_difference.h): CIELAB values
// known by hand, the exact technique's zero error, the split of the transmittance error, and
// bit-identical numbers for one and two threads on a rendered frame.
#include "oit/oit_run.h"

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <set>

#include "eval/eval_config.h"
#include "oit/color_difference.h"
#include "oit/oit_verification.h"
#include "scatter/scatter_run.h"
#include "scene/scene.h"
#include "shadow/compositing.h"
#include "techniques/lp_options.h"
#include "techniques/oit/oit_options.h"
#include "techniques/registry.h"
#include "techniques/soft/soft_technique.h"
#include "test_support.h"
#include "util/error.h"

namespace mb {
namespace {

// `oit`'s tables: each technique's cameras summed into its "all" row, and the per-camera rows
// technique-major.
TEST(OitRows, SumsEveryCameraAndListsThemTechniqueMajor) {
  OitRows rows({"exact", "wboit"});
  for (const char* camera : {"front", "side"}) {
    OitFrameResult r;
    r.scene = "garden", r.camera = camera;
    r.stats.resize(2);
    r.stats[0].fragments = 3, r.stats[1].fragments = 5;
    r.stats[1].delta_e = {1.5f};
    r.seconds = {1, 2};
    rows.add(r);
  }
  ASSERT_EQ(rows.overall().size(), 2u);
  EXPECT_EQ(rows.overall()[0].camera, "all");
  EXPECT_EQ(rows.overall()[0].stats.fragments, 6u);
  EXPECT_EQ(rows.overall()[1].stats.fragments, 10u);
  EXPECT_EQ(rows.overall()[1].stats.delta_e.size(), 2u);
  EXPECT_EQ(rows.overall()[1].seconds, 4);
  const std::vector<OitRow> cameras = rows.per_camera();
  ASSERT_EQ(cameras.size(), 4u);
  EXPECT_EQ(cameras[0].technique + " " + cameras[0].camera, "exact garden/front");
  EXPECT_EQ(cameras[1].technique + " " + cameras[1].camera, "exact garden/side");
  EXPECT_EQ(cameras[2].technique + " " + cameras[2].camera, "wboit garden/front");
  EXPECT_EQ(cameras[3].stats.fragments, 5u);
}

TEST(OitMetrics, LabOfWhiteAndOfTheRedPrimary) {
  const LabConverter lab;
  const Lab white = lab.lab({1, 1, 1});
  EXPECT_NEAR(white[0], 100, 1e-3);
  EXPECT_NEAR(white[1], 0, 1e-3);
  EXPECT_NEAR(white[2], 0, 1e-3);
  // sRGB's red primary adapted to D50 (Bradford): XYZ (0.4361, 0.2225, 0.0139), hence by hand
  // L* = 116 f(0.2225) - 16 = 54.29, a* = 80.8, b* = 69.9.
  const Lab red = lab.lab({1, 0, 0});
  EXPECT_NEAR(red[0], 54.29, 0.3);
  EXPECT_NEAR(red[1], 80.8, 0.5);
  EXPECT_NEAR(red[2], 69.9, 0.5);
  EXPECT_NEAR(delta_e_76(white, red), std::sqrt(45.71 * 45.71 + 80.8 * 80.8 + 69.9 * 69.9), 1);
  EXPECT_EQ(delta_e_2000(red, red), 0);
}

TEST(OitMetrics, TransmittanceErrorSplitsIntoOverAndUnder) {
  const std::vector<double> depth = {1, 2}, alpha = {0.5, 0.25};
  const std::vector<Rgb> color = {{1, 0, 0}, {0, 1, 0}};
  const PixelFragments px{depth, alpha, color, {0, 0, 1}};
  const std::vector<double> reference = {1, 0.5}, technique = {0.8, 0.9};
  const LabConverter lab;
  const PixelError e = pixel_error(px, reference, technique, {0.5f, 0.5f, 0.5f},
                                   lab.lab({0.5f, 0.5f, 0.5f}), {0.5f, 0.5f, 0.5f}, lab);
  EXPECT_DOUBLE_EQ(e.alpha, 0.75);
  EXPECT_DOUBLE_EQ(e.under, 0.5 * 0.2);
  EXPECT_DOUBLE_EQ(e.over, 0.25 * 0.4);
  EXPECT_EQ(e.delta_e, 0);
  OitStats stats;
  stats.add(e);
  EXPECT_NEAR(stats.transmittance_error(), 0.2 / 0.75, 1e-15);
  EXPECT_NEAR(stats.transmittance_over() + stats.transmittance_under(), stats.transmittance_error(),
              1e-15);
}

Scene glass() {
  return build_scene(parse_scene(testing_support::write_temp_file("glass.yaml", R"(name: glass
parts:
  - ground_plane: {size: 8}
    color: [0.7, 0.7, 0.7]
  - card_cloud: {count: 40, size: 1.2, extent: [2, 2, 2], seed: 3}
    opacity: 0.4
    color: [0.9, 0.3, 0.2]
views:
  - {name: sun, azimuth: 30, elevation: 60}
cameras:
  - {name: eye, position: [0, 1.5, 6], target: [0, 1, 0], fov: 40, resolution: [48, 32]}
)")));
}

TEST(OitRun, ExactHasNoErrorAndThreadsDoNotChangeTheNumbers) {
  const Scene scene = glass();
  const DeepFrame frame = render_deep_frame(scene, scene.cameras[0], 2);
  ASSERT_GT(frame.fragments(), 100u);
  const std::vector<std::string> techniques = {"exact", "wboit", "mboit_power6", "mboit_trig3",
                                               "lp:power4"};
  const LabConverter lab;
  const OitFrameResult one = evaluate_oit_frame(frame, "glass", techniques, {}, 1, lab, true);
  const OitFrameResult two = evaluate_oit_frame(frame, "glass", techniques, {}, 2, lab, true);
  EXPECT_EQ(one.stats[0].transmittance_error(), 0);
  EXPECT_EQ(one.stats[0].delta_e_quantile(1), 0);
  for (size_t k = 1; k < techniques.size(); ++k) {
    EXPECT_GT(one.stats[k].transmittance_error(), 0) << techniques[k];
    EXPECT_EQ(one.stats[k].transmittance_error(), two.stats[k].transmittance_error());
    EXPECT_EQ(one.stats[k].delta_e_sum, two.stats[k].delta_e_sum) << techniques[k];
    EXPECT_EQ(one.stats[k].delta_e, two.stats[k].delta_e) << techniques[k];
    EXPECT_EQ(0, std::memcmp(one.composites[k].data(), two.composites[k].data(),
                             one.composites[k].size() * sizeof(Rgb)));
  }
}

TEST(OitRun, CameraWithoutTransparentGeometryIsAnError) {
  const Scene scene = build_scene(parse_scene(testing_support::write_temp_file("opaque.yaml",
                                                                               R"(name: opaque
parts:
  - ground_plane: {size: 8}
views:
  - {name: sun, azimuth: 30, elevation: 60}
cameras:
  - {name: eye, position: [0, 1.5, 6], target: [0, 1, 0], fov: 40, resolution: [16, 16]}
)")));
  const DeepFrame frame = render_deep_frame(scene, scene.cameras[0], 1);
  const std::string message =
      testing_support::input_error_of([&] { check_frame_has_transparency(frame, scene.name); });
  EXPECT_NE(message.find("opaque/eye"), std::string::npos) << message;
  EXPECT_NE(message.find("no transparent geometry"), std::string::npos) << message;
}

// oit.depth_range (docs/transparency.md §2): seed 003's bounding sphere of the transparent
// geometry holds every fragment, so each warps into [0, 1] before any clamping, and here it is
// wider than the frame's own range, so the moments and MBOIT's answers move with the setting.
TEST(OitRun, BoundingSphereRangeHoldsEveryFragment) {
  const Scene scene = glass();
  const DeepFrame frame = render_deep_frame(scene, scene.cameras[0], 2);
  ASSERT_TRUE(std::isfinite(frame.sphere_near) && std::isfinite(frame.sphere_far));
  EXPECT_LE(frame.sphere_near, frame.nearest());
  EXPECT_GE(frame.sphere_far, frame.farthest());
  EXPECT_GT(frame.sphere_far - frame.sphere_near, 1.01 * (frame.farthest() - frame.nearest()));
  for (const WarpKind kind : {WarpKind::Logarithmic, WarpKind::Linear}) {
    const DepthWarp sphere = frame_warp(frame, kind, DepthRangeKind::BoundingSphere);
    const DepthWarp fragments = frame_warp(frame, kind, DepthRangeKind::Fragments);
    for (double z : frame.depth) {
      const double unclamped =
          ((kind == WarpKind::Linear ? z : std::log(z)) - sphere.near) / sphere.range;
      EXPECT_GE(unclamped, 0) << z;
      EXPECT_LE(unclamped, 1) << z;
    }
    EXPECT_EQ(fragments(frame.nearest()), 0);
    EXPECT_EQ(fragments(frame.farthest()), 1);
    EXPECT_GT(sphere(frame.nearest()), 0);
    EXPECT_LT(sphere(frame.farthest()), 1);
  }
  const std::vector<std::string> techniques = {"exact", "mboit_power4", "mboit_trig2"};
  OitParams by_sphere;
  by_sphere.depth_range = DepthRangeKind::BoundingSphere;
  const LabConverter lab;
  const OitFrameResult a = evaluate_oit_frame(frame, "glass", techniques, {}, 2, lab, true);
  const OitFrameResult b = evaluate_oit_frame(frame, "glass", techniques, by_sphere, 2, lab, true);
  EXPECT_EQ(a.stats[0].delta_e_mean(), b.stats[0].delta_e_mean());  // exact needs no warp
  for (size_t k = 1; k < techniques.size(); ++k)
    EXPECT_NE(a.stats[k].delta_e_mean(), b.stats[k].delta_e_mean()) << techniques[k];
  // A frame without its scene (read back from a file) has no sphere: a named error.
  DeepFrame without = frame;
  without.sphere_near = without.sphere_far = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(frame_warp(without, WarpKind::Logarithmic, DepthRangeKind::BoundingSphere),
               InputError);
  EXPECT_EQ(depth_range_kind("bounding_sphere"), DepthRangeKind::BoundingSphere);
  EXPECT_THROW(depth_range_kind("sphere"), InputError);
}

}  // namespace
}  // namespace mb

namespace mb {
namespace {

// verify's transparency rows (oit/oit_verification.h): each MBOIT closed form passes its check on
// seeded pixels, the row counts what it compared, and a name without a certified LP is refused.
TEST(OitVerify, MboitRowsPassAgainstTheLp) {
  for (const auto& name : oit_verify_names()) {
    const OitVerifyRow row = verify_mboit(name, 6, 2015);
    EXPECT_TRUE(row.passed()) << name << ": " << row.beyond << " beyond, largest " << row.largest;
    EXPECT_EQ(row.pixels, 6u);
    EXPECT_GT(row.fragments, 12u);
    EXPECT_LE(row.largest, row.tolerance) << name;
  }
  const std::string message =
      testing_support::input_error_of([] { verify_mboit("mboit_power8", 1, 1); });
  EXPECT_NE(message.find("expected one of mboit_power4"), std::string::npos) << message;
}

// Every key a registry row lists as its family's option (TechniqueRow::family_options, shown by
// `momentbench options techniques`) is declared by a record of the technique, soft, oit or LP
// options: a renamed or misspelled key would show an option that does not exist.
TEST(OitRun, EveryFamilyOptionOfARowIsADeclaredOption) {
  std::set<std::string> declared;
  for (const auto& s :
       technique_option_specs({TechniqueFamily::HardShadow, TechniqueFamily::SoftShadow,
                               TechniqueFamily::Transmittance, TechniqueFamily::Scattering}))
    declared.insert(s.name);
  for (const auto& r : soft_option_records()) declared.insert(r.spec.name);
  for (const auto& r : oit_run_options()) declared.insert(r.spec.name);
  for (const auto& s : oit_option_specs()) declared.insert(s.name);
  for (const auto& r : scatter_run_options()) declared.insert(r.spec.name);
  for (const auto& s : lp_option_specs()) declared.insert(s.name);
  size_t listed = 0;
  for (const TechniqueRow& row : technique_registry())
    for (const std::string& key : row.family_options) {
      EXPECT_TRUE(declared.count(key)) << row.name << " lists " << key;
      ++listed;
    }
  EXPECT_GT(listed, 20u);
}

// A technique's own options (TechniqueRow::options) are declared by the command that runs its
// family, without a line outside the technique's file: eval's for hard and soft shadows, oit's
// (and a transparency sweep's) for transmittance, scatter's for scattering. A command accepts no
// other family's own option.
TEST(OitRun, EveryRowsOwnOptionsAreDeclaredByItsFamilysCommand) {
  const auto names = [](const std::vector<OptionSpec>& specs) {
    std::set<std::string> out;
    for (const auto& s : specs) out.insert(s.name);
    return out;
  };
  const std::set<std::string> eval = names(shadow_option_specs()), oit = names(oit_option_specs()),
                              scatter = names(scatter_run_option_specs());
  size_t checked = 0;
  for (const TechniqueRow& row : technique_registry())
    for (const TechniqueOption* o : row.options) {
      const std::string& key = o->spec.name;
      const bool shadow =
          row.family == TechniqueFamily::HardShadow || row.family == TechniqueFamily::SoftShadow;
      EXPECT_EQ(eval.count(key), shadow ? 1u : 0u) << row.name << " " << key;
      EXPECT_EQ(oit.count(key), row.family == TechniqueFamily::Transmittance ? 1u : 0u)
          << row.name << " " << key;
      EXPECT_EQ(scatter.count(key), row.family == TechniqueFamily::Scattering ? 1u : 0u)
          << row.name << " " << key;
      ++checked;
    }
  EXPECT_GT(checked, 40u);
  // Read from a config into the parameters the factories get.
  std::vector<OptionSpec> specs = oit_option_specs();
  for (const auto& spec : lp_option_specs()) specs.push_back(spec);
  Config config(specs);
  config.set("oit.beta=0.5");
  EXPECT_EQ(oit_params_from(config).technique.number("oit.beta"), 0.5);
  Config scattering(scatter_run_option_specs());
  scattering.set("scatter.seed=7");
  EXPECT_EQ(scatter_run_options_from(scattering).technique.integer("scatter.seed"), 7);
}

}  // namespace
// OitParams' options come from their records: a default-made one holds the records' defaults, and
// oit_params_from reads the keys a config declares (a sweep's lacks oit.depth_range) and lp.*.
TEST(OitRun, OitParamsAreTheRecordsValues) {
  const OitParams defaults;
  const Config records(oit_option_specs());
  EXPECT_EQ(defaults.technique.number("oit.beta"),
            YAML::Load(records.value_text("oit.beta")).as<double>());
  EXPECT_EQ(defaults.warp, warp_kind(records.string("oit.warp")));
  EXPECT_EQ(defaults.depth_range, depth_range_kind(records.string("oit.depth_range")));
  EXPECT_EQ(defaults.technique.lp_backend, TechniqueParams().lp_backend);
  std::vector<OptionSpec> specs = lp_option_specs();
  for (const auto& s : oit_option_specs())
    if (s.name != "oit.depth_range") specs.push_back(s);
  Config config(specs);
  config.set("oit.beta=0.5");
  config.set("oit.warp=linear");
  config.set("lp.grid=64");
  const OitParams read = oit_params_from(config);
  EXPECT_EQ(read.technique.number("oit.beta"), 0.5);
  EXPECT_EQ(read.warp, WarpKind::Linear);
  EXPECT_EQ(read.depth_range, defaults.depth_range);
  EXPECT_EQ(read.technique.lp.grid, 64);
}

}  // namespace mb
