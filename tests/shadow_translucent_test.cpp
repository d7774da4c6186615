// Translucent occluders (docs/reference.md §7): the reference is the filtered transmittance's
// complement, the moment map holds E_Z[b] of each texel's translucent distribution, and opacity 1
// is the opaque pipeline exactly.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "eval/evaluation.h"
#include "raster/deep_exr.h"
#include "raster/render_view.h"
#include "scene/scene.h"
#include "shadow/moment_map.h"
#include "test_support.h"

namespace mb {
namespace {

using testing_support::write_temp_file;

// Layer stacks hold alpha as float (the deep EXR's A channel): 0.3 is 0.3f.
const double kUpper = double(0.3f);

// A ground plane under single-surface squares at heights 1.5 and 2.5 (the second only with two
// opacities; a box would be two surfaces, each taking its alpha), lit from straight above: every
// receiver of the ground under both squares' interiors sees the same stack in every tap.
std::string slabs(const std::string& first, const std::string& second = "") {
  std::string yaml =
      "name: slabs\nparts:\n  - ground_plane: {size: 8}\n"
      "  - ground_plane: {size: 4}\n    transform: {translate: [0, 1.5, 0]}\n" +
      first;
  if (!second.empty())
    yaml += "  - ground_plane: {size: 4}\n    transform: {translate: [0, 2.5, 0]}\n" + second;
  return yaml + "views:\n  - {name: top, azimuth: 0, elevation: 90, resolution: 64}\n";
}

ViewData view_of(const std::string& yaml, BlendOrder blend = BlendOrder::Sorted) {
  const Scene scene = build_scene(parse_scene(write_temp_file("scene.yaml", yaml)));
  EvalSettings settings;
  settings.threads = 2;
  settings.blend = blend;
  return prepare_view(scene, scene.views[0], settings);
}

// The ground's receivers whose whole kernel lies under the slabs (texels 24..39 of 64 at the
// centre: the slabs span 4 of the plane's ~8.2 units).
std::vector<size_t> ground_interior(const ViewData& v) {
  std::vector<size_t> out;
  for (size_t k = 0; k < v.fragments.size(); ++k) {
    const int x = int(v.fragments.texel[k] % v.fragments.width),
              y = int(v.fragments.texel[k] / v.fragments.width);
    if (x >= 26 && x < 38 && y >= 26 && y < 38 && v.fragments.zf[k] > 0.9) out.push_back(k);
  }
  return out;
}

TEST(Translucent, OneSlabOfHalfOpacityLetsHalfThrough) {
  const ViewData v = view_of(slabs("    opacity: 0.5\n"));
  ASSERT_TRUE(v.map.translucent());
  const auto ground = ground_interior(v);
  ASSERT_GT(ground.size(), 50u);
  for (size_t k : ground) EXPECT_NEAR(v.fragments.pcf[k], 0.5, 1e-15) << k;
}

TEST(Translucent, TwoSlabsComposeTheirTransmittances) {
  const ViewData v = view_of(slabs("    opacity: 0.5\n", "    opacity: 0.3\n"));
  const auto ground = ground_interior(v);
  ASSERT_GT(ground.size(), 50u);
  for (size_t k : ground) EXPECT_NEAR(v.fragments.pcf[k], 1 - 0.5 * (1 - kUpper), 1e-15) << k;
  // The lower slab's receivers are shadowed by the upper one alone.
  size_t lower = 0;
  for (size_t k = 0; k < v.fragments.size(); ++k) {
    const int x = int(v.fragments.texel[k] % 64), y = int(v.fragments.texel[k] / 64);
    if (x < 26 || x >= 38 || y < 26 || y >= 38 || v.fragments.zf[k] > 0.9) continue;
    if (v.fragments.zf[k] < 0.2) continue;  // the upper slab's own top
    EXPECT_NEAR(v.fragments.pcf[k], kUpper, 1e-15) << k;
    ++lower;
  }
  EXPECT_GT(lower, 50u);
}

// E_Z[b] in closed form: under both squares Z = a delta_{z1} + (1 - a) 0.5 (delta_{z2} + delta_g).
TEST(Translucent, MomentMapHoldsTheTranslucentDistributionsMoments) {
  const ViewData v = view_of(slabs("    opacity: 0.5\n", "    opacity: 0.3\n"));
  const Basis basis = Basis::parse({"z", "z^2", "z^3", "z^4"});
  const MomentMap moments =
      compute_moment_map(v.map, basis, make_gaussian_kernel(9, 2.4), double_storage(), 2);
  const size_t t = 32 * 64 + 32;
  const uint64_t a = v.map.atom_offsets[t];
  ASSERT_EQ(v.map.atom_offsets[t + 1] - a, 3u);
  const double z1 = v.map.atom_depth[a], z2 = v.map.atom_depth[a + 1], zg = v.map.atom_depth[a + 2];
  for (int j = 0; j < 4; ++j) {
    const double rest = (1 - kUpper) * 0.5;
    const double expected =
        kUpper * std::pow(z1, j + 1) + rest * std::pow(z2, j + 1) + rest * std::pow(zg, j + 1);
    EXPECT_NEAR(moments.at(t)[j], expected, 1e-14) << "b_" << j + 1;
  }
}

// An unsorted blend (translucent.blend = submission) over the ground, under both slabs: drawn back
// to front (the lower slab's part first) it is the exact blend; drawn front to back the far slab
// takes alpha of the blend after the near one, and the near one keeps its share times 1 - alpha.
// The reference stays the exact one either way.
TEST(Translucent, SubmissionOrderBlendsInTriangleOrder) {
  const std::string lower =
      "  - ground_plane: {size: 4}\n    transform: {translate: [0, 1.5, 0]}\n"
      "    opacity: 0.5\n";
  const std::string upper =
      "  - ground_plane: {size: 4}\n    transform: {translate: [0, 2.5, 0]}\n"
      "    opacity: 0.3\n";
  const std::string head = "name: slabs\nparts:\n  - ground_plane: {size: 8}\n";
  const std::string views = "views:\n  - {name: top, azimuth: 0, elevation: 90, resolution: 64}\n";
  const size_t t = 32 * 64 + 32;
  const ViewData sorted = view_of(head + lower + upper + views, BlendOrder::Sorted);
  const ViewData back_to_front = view_of(head + lower + upper + views, BlendOrder::Submission);
  const ViewData front_to_back = view_of(head + upper + lower + views, BlendOrder::Submission);
  const uint64_t a = sorted.map.atom_offsets[t];
  ASSERT_EQ(sorted.map.atom_offsets[t + 1] - a, 3u);
  for (int i = 0; i < 3; ++i)
    EXPECT_NEAR(back_to_front.map.blended_mass()[a + i], sorted.map.atom_mass[a + i], 1e-15) << i;
  const double expected[3] = {kUpper * 0.5, 0.5, (1 - kUpper) * 0.5};  // z1, z2, the ground
  for (int i = 0; i < 3; ++i)
    EXPECT_NEAR(front_to_back.map.blended_mass()[a + i], expected[i], 1e-15) << i;
  EXPECT_EQ(front_to_back.map.atom_mass, sorted.map.atom_mass);
  EXPECT_EQ(front_to_back.fragments.pcf, sorted.fragments.pcf);
  const MomentMap moments = compute_moment_map(front_to_back.map, Basis::parse({"z"}),
                                               make_gaussian_kernel(1, 1), double_storage(), 2);
  const double z1 = sorted.map.atom_depth[a], z2 = sorted.map.atom_depth[a + 1],
               zg = sorted.map.atom_depth[a + 2];
  EXPECT_NEAR(moments.at(t)[0], expected[0] * z1 + expected[1] * z2 + expected[2] * zg, 1e-15);
}

// An unsorted blend moves mass backwards, never forwards: the mass a blend leaves on the atoms
// nearer than any depth is at most 1 - prod (1 - alpha) of them, which the sorted blend gives
// (docs/reference.md §7). So every exact technique stays a lower bound of the exact reference.
TEST(Translucent, UnsortedBlendIsNeverDarkerThanTheSortedOne) {
  const std::string head = "name: slabs\nparts:\n  - ground_plane: {size: 8}\n";
  const std::string near =
      "  - ground_plane: {size: 4}\n    transform: {translate: [0, 2.5, 0]}\n"
      "    opacity: 0.9\n    opacity_pattern: {noise: {scale: 0.3, seed: 7, min: 0.1}}\n";
  const std::string far =
      "  - ground_plane: {size: 4}\n    transform: {translate: [0.7, 1.5, 0]}\n"
      "    opacity: 0.6\n";
  const std::string views = "views:\n  - {name: top, azimuth: 0, elevation: 90, resolution: 64}\n";
  const ViewData v = view_of(head + near + far + views, BlendOrder::Submission);
  size_t lighter = 0;
  for (size_t t = 0; t + 1 < v.map.atom_offsets.size(); ++t) {
    double sorted = 0, unsorted = 0;
    for (uint64_t a = v.map.atom_offsets[t]; a < v.map.atom_offsets[t + 1]; ++a) {
      sorted += v.map.atom_mass[a];
      unsorted += v.map.blended_mass()[a];
      ASSERT_LE(unsorted, sorted + 1e-15) << "texel " << t << " atom " << a;
      if (unsorted < sorted - 1e-3) ++lighter;
    }
  }
  EXPECT_GT(lighter, 100u);  // drawn front to back, the near surface loses mass where both lie
}

// Stored formats round every blend step, as a GPU writing float or 16-bit targets does (seed 004
// §4: theta_4's values blended into two RG16 targets). Under both slabs, with a one-tap kernel,
// the texel is the ground's stored value, blended over by the far slab, then the near one.
TEST(Translucent, StoredFormatsRoundEveryBlendStep) {
  const ViewData v = view_of(slabs("    opacity: 0.5\n", "    opacity: 0.3\n"));
  const Basis basis = Basis::parse({"z", "z^2", "z^3", "z^4"});
  const size_t t = 32 * 64 + 32;
  const uint64_t a = v.map.atom_offsets[t];
  ASSERT_EQ(v.map.atom_offsets[t + 1] - a, 3u);
  const double z[3] = {v.map.atom_depth[a], v.map.atom_depth[a + 1], v.map.atom_depth[a + 2]};
  const double alpha[2] = {kUpper, 0.5};
  for (const MomentStorage& storage : {unorm16_power4_storage(), float32_storage()}) {
    const auto stored_b = [&](double depth) {
      const std::vector<double> b = {depth, depth * depth, std::pow(depth, 3), std::pow(depth, 4)};
      return stored_values(storage, b);
    };
    const auto round = [&](double q) {
      if (storage.kind == StorageKind::Float32) return double(float(q));
      return std::round(q * 65535.0) / 65535.0;
    };
    std::vector<double> q = stored_b(z[2]);
    for (double& v : q) v = round(v);
    for (int s : {1, 0}) {
      const std::vector<double> src = stored_b(z[s]);
      for (int j = 0; j < 4; ++j) q[j] = round(alpha[s] * src[j] + (1 - alpha[s]) * q[j]);
    }
    load_moments(storage, q);
    const MomentMap map = compute_moment_map(v.map, basis, make_gaussian_kernel(1, 1), storage, 2);
    for (int j = 0; j < 4; ++j) EXPECT_NEAR(map.at(t)[j], q[j], 1e-13) << storage.name() << j;
    // Not what rounding the exact blend once gives: three roundings, not one.
    const MomentMap exact =
        compute_moment_map(v.map, basis, make_gaussian_kernel(1, 1), double_storage(), 2);
    std::vector<double> once(exact.at(t).begin(), exact.at(t).end());
    store_moments(storage, once);
    load_moments(storage, once);
    double apart = 0;
    for (int j = 0; j < 4; ++j) apart = std::max(apart, std::abs(once[j] - q[j]));
    EXPECT_GT(apart, 0) << storage.name();
  }
}

// Fourier opacity mapping: one slab of alpha 0.5 at depth 0.3 in every tap; behind it the series'
// absorbance approaches -ln 0.5 as terms are added (the truncated step converges away from its
// jump), and an absorbance map adds up in any order, so an unsorted blend leaves it unchanged.
TEST(Translucent, FourierOpacityMappingConvergesAndIgnoresTheOrder) {
  const std::vector<double> depths = {0.3, 1.0}, weights = {0.5, 0.5}, alphas = {0.5, 0.0};
  FragmentInput in;
  in.kernel_depths = depths;
  in.kernel_weights = weights;
  in.kernel_alpha = alphas;
  const std::vector<uint32_t> offsets = {0, 2};
  in.tap_offsets = offsets;
  in.zf = 0.7;
  double previous = 1;
  for (int terms : {1, 4, 16, 64}) {
    TechniqueParams params;
    params.set("fom.terms", terms);
    const double error = std::abs(make_technique("fom", params)->shadow(in) - 0.5);
    EXPECT_LT(error, previous + 1e-12) << terms;
    previous = error;
  }
  EXPECT_LT(previous, 2e-3);
  const std::string yaml =
      "name: slabs\nparts:\n  - ground_plane: {size: 8}\n"
      "  - ground_plane: {size: 4}\n    transform: {translate: [0, 2.5, 0]}\n    opacity: 0.3\n"
      "  - ground_plane: {size: 4}\n    transform: {translate: [0, 1.5, 0]}\n    opacity: 0.5\n"
      "views:\n  - {name: top, azimuth: 0, elevation: 90, resolution: 64}\n";
  EvalSettings settings;
  settings.threads = 2;
  const TechniqueResult sorted =
      evaluate_technique(view_of(yaml, BlendOrder::Sorted), "fom", settings, nullptr);
  const TechniqueResult unsorted =
      evaluate_technique(view_of(yaml, BlendOrder::Submission), "fom", settings, nullptr);
  // Equal but for the rounding of each tap's weight, summed from its (differently blended) masses.
  ASSERT_EQ(sorted.shadow.size(), unsorted.shadow.size());
  for (size_t k = 0; k < sorted.shadow.size(); ++k)
    EXPECT_NEAR(sorted.shadow[k], unsorted.shadow[k], 1e-14) << k;
  const TechniqueResult moments =
      evaluate_technique(view_of(yaml, BlendOrder::Submission), "hamburger4", settings, nullptr);
  const TechniqueResult exact =
      evaluate_technique(view_of(yaml, BlendOrder::Sorted), "hamburger4", settings, nullptr);
  EXPECT_NE(moments.shadow, exact.shadow);  // moments, unlike absorbance, depend on the order
}

// opacity: 1 is the key's absence: the same stack, map and receivers, bit for bit.
TEST(Translucent, OpacityOneIsTheOpaquePipeline) {
  const ViewData plain = view_of(slabs(""));
  const ViewData keyed = view_of(slabs("    opacity: 1\n"));
  EXPECT_FALSE(keyed.map.translucent());
  EXPECT_EQ(plain.map.depth, keyed.map.depth);
  EXPECT_EQ(plain.fragments.pcf, keyed.fragments.pcf);
  EXPECT_EQ(plain.fragments.ztest, keyed.fragments.ztest);
}

// Exact techniques bound the filtered transmittance's complement from below, fragment by fragment,
// on a noise-patterned slab over a ground, whose alpha varies inside every kernel.
TEST(Translucent, ExactTechniquesNeverExceedTheReference) {
  const ViewData v = view_of(
      slabs("    opacity: 0.9\n    opacity_pattern: {noise: {scale: 0.3, seed: 7, min: 0.1}}\n",
            "    opacity: 0.6\n"));
  EvalSettings settings;
  settings.threads = 2;
  for (const char* name : {"hamburger4", "hausdorff4", "vsm", "tmsm", "lp:power4", "lp:trig4"}) {
    const TechniqueResult r = evaluate_technique(v, name, settings, nullptr);
    double leak = 0;
    for (size_t k = 0; k < r.shadow.size(); ++k) {
      ASSERT_LE(r.shadow[k], v.fragments.pcf[k] + 1e-9) << name << " fragment " << k;
      leak += v.fragments.pcf[k] - r.shadow[k];
    }
    EXPECT_GT(leak, 0) << name;  // three-atom kernels: four moments cannot pin them down
  }
}

TEST(Translucent, DeepExrCarriesAlpha) {
  const Scene scene = build_scene(parse_scene(write_temp_file(
      "scene.yaml",
      slabs("    opacity: 0.8\n    opacity_pattern: {noise: {scale: 0.5, seed: 3}}\n"))));
  const LayerStack stack = render_view(scene, scene.views[0], 2);
  ASSERT_TRUE(stack.translucent());
  const auto file = std::filesystem::temp_directory_path() /
                    ("mb_translucent_" + std::to_string(getpid()) + ".exr");
  write_deep_exr(stack, file.string());
  const LayerStack back = read_deep_exr(file.string());
  std::filesystem::remove(file);
  EXPECT_TRUE(stack.same_fragments(back));
  EXPECT_EQ(stack.alpha, back.alpha);
}

std::string error_of(const std::string& part_keys) {
  return testing_support::input_error_of(
      [&] { build_scene(parse_scene(write_temp_file("scene.yaml", slabs(part_keys)))); });
}

TEST(Translucent, BadOpacityNamesFileLineAndKey) {
  std::string m = error_of("    opacity: 1.5\n");
  EXPECT_NE(m.find(":5:"), std::string::npos) << m;
  EXPECT_NE(m.find("opacity"), std::string::npos) << m;
  m = error_of("    opacity: thick\n");
  EXPECT_NE(m.find("opacity"), std::string::npos) << m;
  m = error_of("    opacity_pattern: {noize: {seed: 1}}\n");
  EXPECT_NE(m.find("noize"), std::string::npos) << m;
  m = error_of("    opacity_pattern: {noise: {scale: 0.5}}\n");
  EXPECT_NE(m.find("seed"), std::string::npos) << m;
}

}  // namespace
}  // namespace mb
