// The medium of scattering scenes (docs/scattering.md §1): parsing with located errors, and the
// phase function's normalisation and direction.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "scene/dataset.h"
#include "scene/medium.h"
#include "scene/scene.h"
#include "test_support.h"

namespace mb {
namespace {

using testing_support::input_error_of;
using testing_support::write_temp_file;

std::string scene_with_medium(const std::string& medium) {
  return "parts:\n  - box: {}\nviews:\n  - {}\nmedium: " + medium + "\n";
}

TEST(SceneMedium, ParsesAndDefaults) {
  const SceneDesc desc = parse_scene(write_temp_file(
      "scene.yaml", scene_with_medium("{extinction: 0.5, albedo: 0.25, phase: henyey_greenstein, "
                                      "g: -0.4}")));
  ASSERT_TRUE(desc.medium);
  EXPECT_EQ(desc.medium->extinction, 0.5);
  EXPECT_EQ(desc.medium->albedo, 0.25);
  EXPECT_EQ(desc.medium->phase, PhaseKind::HenyeyGreenstein);
  EXPECT_EQ(desc.medium->g, -0.4);
  EXPECT_EQ(desc.medium->scattering(), 0.125);
  const SceneDesc plain =
      parse_scene(write_temp_file("plain.yaml", scene_with_medium("{extinction: 2}")));
  EXPECT_EQ(plain.medium->albedo, 1);
  EXPECT_EQ(plain.medium->phase, PhaseKind::Isotropic);
  EXPECT_FALSE(
      parse_scene(write_temp_file("none.yaml", "parts:\n  - box: {}\nviews:\n  - {}\n")).medium);
}

TEST(SceneMedium, BadValuesNameFileLineKeyAndValue) {
  const auto error = [](const std::string& medium) {
    const std::string file = write_temp_file("bad.yaml", scene_with_medium(medium));
    return input_error_of([&] { parse_scene(file); });
  };
  EXPECT_NE(error("{extinction: -1}").find(":5:"), std::string::npos);
  EXPECT_NE(error("{extinction: -1}")
                .find("key 'medium.extinction': expected the extinction "
                      "coefficient sigma_t > 0 (per scene unit), got -1"),
            std::string::npos)
      << error("{extinction: -1}");
  EXPECT_NE(error("{extinction: 0}").find("got 0"), std::string::npos);
  EXPECT_NE(error("{extinction: .inf}").find("medium.extinction"), std::string::npos);
  EXPECT_NE(error("{extinction: 1, albedo: 1.5}").find("albedo in [0, 1], got 1.5"),
            std::string::npos);
  EXPECT_NE(error("{extinction: 1, phase: rayleigh}")
                .find("isotropic or henyey_greenstein, got "
                      "'rayleigh'"),
            std::string::npos);
  EXPECT_NE(error("{extinction: 1, phase: henyey_greenstein, g: 1}").find("(-1, 1), got 1"),
            std::string::npos);
  EXPECT_NE(error("{extinction: 1, g: 0.5}").find("henyey_greenstein only"), std::string::npos);
  EXPECT_NE(error("{albedo: 0.5}").find("needs `extinction`"), std::string::npos);
  EXPECT_NE(error("{extinction: 1, exctinction: 2}").find("exctinction"), std::string::npos);
}

TEST(SceneMedium, DatasetMediumParses) {
  const DatasetDesc d = load_dataset("scattering_tiny");
  ASSERT_TRUE(d.medium);
  EXPECT_GT(d.medium->extinction, 0);
}

// ∫ f dω = 2 pi ∫_{-1}^{1} f(c) dc = 1 for every g (Simpson's rule, 2^14 intervals).
TEST(SceneMedium, PhaseFunctionIntegratesToOneOverTheSphere) {
  for (double g : {0.0, 0.3, -0.6, 0.9}) {
    MediumDesc m;
    m.phase = g == 0 ? PhaseKind::Isotropic : PhaseKind::HenyeyGreenstein;
    m.g = g;
    const int n = 1 << 14;
    double sum = 0;
    for (int i = 0; i <= n; ++i) {
      const double c = -1 + 2.0 * i / n;
      sum += (i == 0 || i == n ? 1 : i % 2 ? 4 : 2) * m.phase_value(c);
    }
    EXPECT_NEAR(2 * std::numbers::pi * sum * (2.0 / n) / 3, 1, 1e-6) << "g = " << g;
  }
  MediumDesc iso;
  EXPECT_DOUBLE_EQ(iso.phase_value(0.3), 1 / (4 * std::numbers::pi));
}

// g > 0 scatters forward, away from the light: brightest where the direction towards the camera is
// the light's propagation direction (cos = 1), i.e. where the camera looks into the light.
TEST(SceneMedium, ForwardScatteringIsBrightestLookingIntoTheLight) {
  MediumDesc m;
  m.phase = PhaseKind::HenyeyGreenstein;
  m.g = 0.6;
  EXPECT_GT(m.phase_value(1), 10 * m.phase_value(-1));
  EXPECT_NEAR(m.phase_value(1), (1 - 0.36) / (4 * std::numbers::pi * std::pow(0.4, 3)), 1e-12);
}

}  // namespace
}  // namespace mb
