// Scene descriptions: what parses, and the messages for what does not.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "scene/dataset.h"
#include "scene/mesh_loader.h"
#include "scene/procedural.h"
#include "scene/scene.h"
#include "test_support.h"
#include "util/error.h"

namespace mb {
namespace {

std::string parse_error(const std::string& yaml) {
  std::string file = testing_support::write_temp_file("mb_scene.yaml", yaml);
  try {
    build_scene(parse_scene(file));
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(SceneParse, BuiltInDatasetsParse) {
  for (const char* name : {"tiny", "default", "paper", "translucent", "transparency"}) {
    DatasetDesc dataset = load_dataset(name);
    EXPECT_FALSE(dataset.scene_files.empty());
    for (const auto& file : dataset.scene_files) EXPECT_NO_THROW(parse_scene(file)) << file;
  }
  EXPECT_EQ(load_dataset("default").scene_files.size(), 3u);
}

// A face listed twice, in either winding, is one surface (mesh_loader.cpp): a translucent surface
// counted twice would absorb twice.
TEST(SceneParse, RepeatedFacesAreLoadedOnce) {
  const std::string file = testing_support::write_temp_file("twice.obj", R"(v 0 0 0
v 1 0 0
v 0 1 0
v 1 1 0
f 1 2 3
f 2 4 3
f 3 2 1
f 1 2 3
)");
  const TriangleMesh mesh = load_mesh(file);
  EXPECT_EQ(mesh.triangles.size(), 2u);
}

// A card cloud: `count` two-sided squares of the given size inside the extent.
TEST(SceneParse, CardCloudHasItsCardsInsideItsExtent) {
  const TriangleMesh cloud = make_card_cloud(50, 0.4, {2, 1, 3}, 9);
  EXPECT_EQ(cloud.triangles.size(), 100u);
  EXPECT_TRUE(cloud.two_sided);
  const Eigen::AlignedBox3d box = cloud.bounds();
  EXPECT_GE(box.min().x(), -1 - 0.29);
  EXPECT_LE(box.max().y(), 1 + 0.29);  // half a diagonal beyond the centres' box at most
  EXPECT_LE(box.max().z(), 1.5 + 0.29);
  for (size_t t = 0; t < cloud.triangles.size(); t += 2) {
    const auto& a = cloud.vertices[cloud.triangles[t][0]];
    const auto& b = cloud.vertices[cloud.triangles[t][1]];
    EXPECT_NEAR((b - a).norm(), 0.4, 1e-12);
  }
}

TEST(SceneParse, MisspelledKeysAreReportedWithLineAndSuggestion) {
  std::string m =
      parse_error("parts:\n  - box: {size: [1, 1, 1]}\nviews:\n  - {azimuth: 10, elevaton: 30}\n");
  EXPECT_NE(m.find(":4:"), std::string::npos) << m;
  EXPECT_NE(m.find("did you mean 'elevation'"), std::string::npos) << m;
  m = parse_error("parts:\n  - spher: {radius: 1}\nviews:\n  - {azimuth: 10}\n");
  EXPECT_NE(m.find("did you mean 'sphere'"), std::string::npos) << m;
  m = parse_error("parts:\n  - sphere: {radius: 1, ring: 3}\nviews:\n  - {azimuth: 10}\n");
  EXPECT_NE(m.find("did you mean 'rings'"), std::string::npos) << m;
}

TEST(SceneParse, BadValuesAreErrors) {
  EXPECT_NE(parse_error("parts: []\nviews:\n  - {azimuth: 10}\n").find("at least one part"),
            std::string::npos);
  EXPECT_NE(parse_error("parts:\n  - box: {}\nviews: []\n").find("at least one light view"),
            std::string::npos);
  EXPECT_NE(parse_error("parts:\n  - box: {}\nviews:\n  - {resolution: 0}\n").find("[1, 16384]"),
            std::string::npos);
  EXPECT_NE(parse_error("parts:\n  - box: {size: [1, 0, 1]}\nviews:\n  - {}\n").find("size"),
            std::string::npos);
  EXPECT_NE(
      parse_error("parts:\n  - box: {}\n    transform: {scale: 0}\nviews:\n  - {}\n").find("scale"),
      std::string::npos);
  EXPECT_NE(parse_error("parts:\n  - mesh: nowhere.obj\nviews:\n  - {}\n").find("not found"),
            std::string::npos);
}

TEST(SceneParse, ProceduralSolidsAreClosedAndOutwardOriented) {
  // Closed and outward: the signed volume (divergence theorem) equals the solid's volume.
  auto volume = [](const TriangleMesh& m) {
    double v = 0;
    for (const auto& t : m.triangles)
      v += m.vertices[t[0]].dot(m.vertices[t[1]].cross(m.vertices[t[2]])) / 6;
    return v;
  };
  EXPECT_NEAR(volume(make_box({1, 2, 3}, {5, 1, -2})), 6.0, 1e-12);
  EXPECT_NEAR(volume(make_staircase(4, 2.0, 0.5, 0.25)), 2.0 * 0.5 * 0.25 * (1 + 2 + 3 + 4), 1e-12);
  double sphere = volume(make_sphere(1, {0.3, 0, 0}, 64, 128));
  EXPECT_NEAR(sphere, 4.0 / 3.0 * M_PI, 6e-3);  // inscribed polyhedron: ~0.1 % less
  EXPECT_LT(sphere, 4.0 / 3.0 * M_PI);
  TreeMeshes tree = make_tree(2, 2, 3, 0.2, 9);
  EXPECT_GT(volume(tree.wood), 0);
  EXPECT_TRUE(tree.leaves.two_sided);
  EXPECT_EQ(tree.leaves.triangles.size(), 9u * 6 * 2);  // 3^2 tips, 6 quads each
}

}  // namespace
}  // namespace mb
