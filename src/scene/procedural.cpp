#include "scene/procedural.h"

#include <cmath>
#include <numbers>

#include "util/eigen.h"

namespace mb {

using Eigen::Vector3d;

uint64_t SeededRandom::next_u64() {
  uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

namespace {
// Flips triangles whose normal points towards `inside`: valid for convex pieces only.
void orient_outward(TriangleMesh& mesh, const Vector3d& inside) {
  for (auto& t : mesh.triangles) {
    const Vector3d &a = mesh.vertices[t[0]], &b = mesh.vertices[t[1]], &c = mesh.vertices[t[2]];
    if ((b - a).cross(c - a).dot((a + b + c) / 3.0 - inside) < 0) std::swap(t[1], t[2]);
  }
}

// A closed prism of `sides` faces around the segment p0 -> p1 (a branch).
TriangleMesh make_prism(const Vector3d& p0, const Vector3d& p1, double r0, double r1, int sides) {
  TriangleMesh mesh;
  Vector3d axis = (p1 - p0).normalized();
  Vector3d helper = std::abs(axis.y()) < 0.9 ? Vector3d::UnitY() : Vector3d::UnitX();
  Vector3d e1 = axis.cross(helper).normalized(), e2 = axis.cross(e1);
  for (int ring = 0; ring < 2; ++ring) {
    for (int s = 0; s < sides; ++s) {
      double angle = 2 * std::numbers::pi * s / sides;
      double r = ring ? r1 : r0;
      mesh.vertices.push_back((ring ? p1 : p0) + r * (std::cos(angle) * e1 + std::sin(angle) * e2));
    }
  }
  uint32_t n = uint32_t(sides);
  for (uint32_t s = 0; s < n; ++s) {
    uint32_t t = (s + 1) % n;
    mesh.triangles.push_back({s, t, n + t});
    mesh.triangles.push_back({s, n + t, n + s});
  }
  for (uint32_t s = 1; s + 1 < n; ++s) {
    mesh.triangles.push_back({0, s, s + 1});
    mesh.triangles.push_back({n, n + s, n + s + 1});
  }
  orient_outward(mesh, (p0 + p1) / 2);
  return mesh;
}
}  // namespace

TriangleMesh make_ground_plane(double size, int cells) {
  TriangleMesh mesh;
  // Shared vertices computed by one formula, so that neighbouring cells meet exactly.
  auto coordinate = [&](int i) { return -size / 2 + size * i / cells; };
  for (int i = 0; i <= cells; ++i)
    for (int k = 0; k <= cells; ++k) mesh.vertices.emplace_back(coordinate(i), 0.0, coordinate(k));
  auto index = [&](int i, int k) { return uint32_t(i * (cells + 1) + k); };
  for (int i = 0; i < cells; ++i) {
    for (int k = 0; k < cells; ++k) {
      // (z, x) order makes the normal +y.
      mesh.triangles.push_back({index(i, k), index(i, k + 1), index(i + 1, k + 1)});
      mesh.triangles.push_back({index(i, k), index(i + 1, k + 1), index(i + 1, k)});
    }
  }
  return mesh;
}

TriangleMesh make_box(const Vector3d& size, const Vector3d& center) {
  TriangleMesh mesh;
  Vector3d lo = center - size / 2, d = size;
  Vector3d hi = lo + d;
  Vector3d ex(d.x(), 0, 0), ey(0, d.y(), 0), ez(0, 0, d.z());
  // Each face: origin o and edges e1, e2 with e1 x e2 pointing outward.
  auto face = [&](const Vector3d& o, const Vector3d& e1, const Vector3d& e2) {
    mesh.add_quad(o, o + e1, o + e1 + e2, o + e2);
  };
  face(lo, ez, ey);                                // -x
  face(Vector3d(hi.x(), lo.y(), lo.z()), ey, ez);  // +x
  face(lo, ex, ez);                                // -y
  face(Vector3d(lo.x(), hi.y(), lo.z()), ez, ex);  // +y
  face(lo, ey, ex);                                // -z
  face(Vector3d(lo.x(), lo.y(), hi.z()), ex, ey);  // +z
  return mesh;
}

TriangleMesh make_sphere(double radius, const Vector3d& center, int rings, int segments) {
  TriangleMesh mesh;
  mesh.vertices.push_back(center + Vector3d(0, radius, 0));
  for (int r = 1; r < rings; ++r) {
    double theta = std::numbers::pi * r / rings;
    for (int s = 0; s < segments; ++s) {
      double phi = 2 * std::numbers::pi * s / segments;
      mesh.vertices.push_back(center + radius * Vector3d(std::sin(theta) * std::cos(phi),
                                                         std::cos(theta),
                                                         std::sin(theta) * std::sin(phi)));
    }
  }
  mesh.vertices.push_back(center - Vector3d(0, radius, 0));
  uint32_t bottom = uint32_t(mesh.vertices.size() - 1);
  auto ring_vertex = [&](int r, int s) {
    return uint32_t(1 + (r - 1) * segments + (s % segments));
  };
  for (int s = 0; s < segments; ++s) {
    mesh.triangles.push_back({0, ring_vertex(1, s), ring_vertex(1, s + 1)});
    mesh.triangles.push_back({bottom, ring_vertex(rings - 1, s), ring_vertex(rings - 1, s + 1)});
    for (int r = 1; r + 1 < rings; ++r) {
      mesh.triangles.push_back(
          {ring_vertex(r, s), ring_vertex(r + 1, s), ring_vertex(r + 1, s + 1)});
      mesh.triangles.push_back(
          {ring_vertex(r, s), ring_vertex(r + 1, s + 1), ring_vertex(r, s + 1)});
    }
  }
  orient_outward(mesh, center);
  return mesh;
}

TriangleMesh make_staircase(int steps, double width, double run, double rise) {
  // One closed solid: the stair profile in the xy plane (counter-clockwise seen from +z),
  // extruded along z. Walls follow the profile; each cap is one rectangle per step column.
  std::vector<Eigen::Vector2d> profile = {{0, 0}, {steps * run, 0}};
  for (int i = steps; i >= 1; --i) {
    profile.emplace_back(i * run, i * rise);
    profile.emplace_back((i - 1) * run, i * rise);
  }
  TriangleMesh mesh;
  double z0 = -width / 2, z1 = width / 2;
  for (size_t k = 0; k < profile.size(); ++k) {
    const auto& p = profile[k];
    const auto& q = profile[(k + 1) % profile.size()];
    if ((q - p).norm() == 0) continue;
    // Edges (q - p) and +z: their cross product is the outward normal of a CCW profile.
    mesh.add_quad({p.x(), p.y(), z0}, {q.x(), q.y(), z0}, {q.x(), q.y(), z1}, {p.x(), p.y(), z1});
  }
  for (int i = 0; i < steps; ++i) {
    double x0 = i * run, x1 = (i + 1) * run, h = (i + 1) * rise;
    mesh.add_quad({x0, 0, z1}, {x1, 0, z1}, {x1, h, z1}, {x0, h, z1});  // +z cap
    mesh.add_quad({x0, 0, z0}, {x0, h, z0}, {x1, h, z0}, {x1, 0, z0});  // -z cap
  }
  return mesh;
}

TriangleMesh make_building_grid(int nx, int nz, double footprint, double spacing, double min_height,
                                double max_height, uint64_t seed) {
  TriangleMesh mesh;
  SeededRandom random(seed);
  for (int i = 0; i < nx; ++i) {
    for (int k = 0; k < nz; ++k) {
      double h = random.uniform(min_height, max_height);
      double x = (i - (nx - 1) / 2.0) * spacing, z = (k - (nz - 1) / 2.0) * spacing;
      mesh.append(make_box({footprint, h, footprint}, {x, h / 2, z}));
    }
  }
  return mesh;
}

TriangleMesh make_fence(double length, double height, double post_spacing, int rails, int pickets) {
  TriangleMesh mesh;
  double post = 0.06 * height, depth = 0.05 * height;
  int posts = std::max(2, int(std::round(length / post_spacing)) + 1);
  double step = length / (posts - 1);
  for (int p = 0; p < posts; ++p)
    mesh.append(make_box({post, height, post}, {p * step, height / 2, 0}));
  for (int r = 0; r < rails; ++r) {
    double y = height * (r + 1) / (rails + 1);
    mesh.append(make_box({length, post * 0.6, depth * 0.6}, {length / 2, y, post * 0.5}));
  }
  for (int p = 0; p + 1 < posts; ++p) {
    for (int k = 1; k <= pickets; ++k) {
      double x = p * step + step * k / (pickets + 1);
      mesh.append(
          make_box({post * 0.5, height * 0.9, depth * 0.4}, {x, height * 0.45, -post * 0.5}));
    }
  }
  return mesh;
}

TriangleMesh make_card_cloud(int count, double size, const Vector3d& extent, uint64_t seed) {
  TriangleMesh mesh;
  SeededRandom random(seed);
  for (int c = 0; c < count; ++c) {
    const Vector3d center(random.uniform(-0.5, 0.5) * extent.x(), random.uniform(0, 1) * extent.y(),
                          random.uniform(-0.5, 0.5) * extent.z());
    // Two random directions made orthonormal: a uniformly tilted card.
    Vector3d u(random.uniform(-1, 1), random.uniform(-1, 1), random.uniform(-1, 1));
    Vector3d w(random.uniform(-1, 1), random.uniform(-1, 1), random.uniform(-1, 1));
    if (u.norm() < 1e-3) u = Vector3d::UnitX();
    u.normalize();
    w -= w.dot(u) * u;
    if (w.norm() < 1e-3) w = u.unitOrthogonal();
    w.normalize();
    u *= size / 2, w *= size / 2;
    mesh.add_quad(center - u - w, center + u - w, center + u + w, center - u + w);
  }
  mesh.two_sided = true;
  return mesh;
}

namespace {

void grow_branch(TreeMeshes& tree, SeededRandom& random, const Vector3d& base,
                 const Vector3d& direction, double length, double radius, int depth, int branches,
                 double leaf_size) {
  Vector3d tip = base + direction * length;
  tree.wood.append(make_prism(base, tip, radius, radius * 0.7, 6));
  if (depth == 0) {
    // A cluster of leaves: randomly tilted two-sided quads around the tip.
    for (int l = 0; l < 6; ++l) {
      Vector3d center = tip + leaf_size * Vector3d(random.uniform(-1, 1), random.uniform(-0.5, 1),
                                                   random.uniform(-1, 1));
      Vector3d u = Vector3d(random.uniform(-1, 1), random.uniform(-0.3, 0.3), random.uniform(-1, 1))
                       .normalized();
      Vector3d v =
          u.cross(Vector3d(random.uniform(-0.3, 0.3), 1, random.uniform(-0.3, 0.3))).normalized();
      double s = leaf_size / 2;
      tree.leaves.add_quad(center - s * u - s * v, center + s * u - s * v, center + s * u + s * v,
                           center - s * u + s * v);
    }
    return;
  }
  for (int b = 0; b < branches; ++b) {
    double azimuth = 2 * std::numbers::pi * (b + random.uniform(0, 0.5)) / branches;
    double tilt = random.uniform(0.45, 0.9);
    Vector3d side(std::cos(azimuth), 0, std::sin(azimuth));
    Vector3d child = (direction * std::cos(tilt) + side * std::sin(tilt)).normalized();
    grow_branch(tree, random, tip, child, length * random.uniform(0.6, 0.8), radius * 0.65,
                depth - 1, branches, leaf_size);
  }
}
}  // namespace

TreeMeshes make_tree(double height, int depth, int branches, double leaf_size, uint64_t seed) {
  TreeMeshes tree;
  tree.leaves.two_sided = true;
  SeededRandom random(seed);
  grow_branch(tree, random, Vector3d::Zero(), Vector3d::UnitY(), height * 0.4, height * 0.04, depth,
              branches, leaf_size);
  return tree;
}

}  // namespace mb
