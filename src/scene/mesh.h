#pragma once
// An indexed triangle mesh in world units. Winding is counter-clockwise seen from outside, so the
// geometric normal (b-a)x(c-a) points out of closed solids; facing the light is read from it.
#include <array>
#include <cstdint>
#include <vector>

#include "util/eigen.h"

namespace mb {

struct TriangleMesh {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<std::array<uint32_t, 3>> triangles;
  // A two-sided surface (a leaf, a sheet) receives light on whichever side faces it.
  bool two_sided = false;

  void append(const TriangleMesh& other);
  // Adds a quad a,b,c,d (counter-clockwise seen from the side its normal points to).
  void add_quad(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                const Eigen::Vector3d& d);
  Eigen::AlignedBox3d bounds() const;
};

// An affine transform applied to a mesh's vertices; a mirroring transform (det < 0) also flips
// the winding so that outward normals stay outward.
void apply_transform(TriangleMesh& mesh, const Eigen::Matrix3d& linear,
                     const Eigen::Vector3d& offset);

}  // namespace mb
