#pragma once
// Procedural scene parts. Each returns a mesh with outward (counter-clockwise) winding, in its own
// local frame (y up, resting on y = 0 unless said otherwise), deterministic for a given seed.
#include <cstdint>

#include "scene/mesh.h"

namespace mb {

// A square in the y = 0 plane, normal +y, centred at the origin, split into cells^2 quads.
TriangleMesh make_ground_plane(double size, int cells);
// An axis-aligned closed box centred at `center`.
TriangleMesh make_box(const Eigen::Vector3d& size, const Eigen::Vector3d& center);
// A closed UV sphere of `radius` centred at `center`; `rings` >= 2, `segments` >= 3.
TriangleMesh make_sphere(double radius, const Eigen::Vector3d& center, int rings, int segments);
// Solid steps rising along +x: step i is a box of height (i+1)*rise.
TriangleMesh make_staircase(int steps, double width, double run, double rise);
// nx x nz boxes of random height in [min_height, max_height] on a regular grid.
TriangleMesh make_building_grid(int nx, int nz, double footprint, double spacing, double min_height,
                                double max_height, uint64_t seed);
// A fence along +x: posts every `post_spacing` and `rails` horizontal rails; with `pickets` > 0,
// also vertical slats between the posts, which makes a lattice of small gaps.
TriangleMesh make_fence(double length, double height, double post_spacing, int rails, int pickets);
// A particle volume: `count` square cards of side `size`, randomly oriented, their centres uniform
// in a box of `extent` (centred in x and z, resting on y = 0). Two-sided.
TriangleMesh make_card_cloud(int count, double size, const Eigen::Vector3d& extent, uint64_t seed);
// A recursively branching tree of prism segments with two-sided quad leaves at its tips.
struct TreeMeshes {
  TriangleMesh wood;
  TriangleMesh leaves;  // two_sided = true
};
TreeMeshes make_tree(double height, int depth, int branches, double leaf_size, uint64_t seed);

// Deterministic uniform numbers in [0, 1) from a 64-bit seed (SplitMix64); unlike
// std::uniform_real_distribution its output is the same with every standard library.
class SeededRandom {
 public:
  explicit SeededRandom(uint64_t seed) : state_(seed) {}
  uint64_t next_u64();
  double uniform() { return double(next_u64() >> 11) * 0x1.0p-53; }
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }

 private:
  uint64_t state_;
};

}  // namespace mb
