#include "scene/mesh.h"

#include "util/eigen.h"

namespace mb {

void TriangleMesh::append(const TriangleMesh& other) {
  uint32_t base = uint32_t(vertices.size());
  vertices.insert(vertices.end(), other.vertices.begin(), other.vertices.end());
  for (const auto& t : other.triangles)
    triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
}

void TriangleMesh::add_quad(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                            const Eigen::Vector3d& c, const Eigen::Vector3d& d) {
  uint32_t base = uint32_t(vertices.size());
  vertices.insert(vertices.end(), {a, b, c, d});
  triangles.push_back({base, base + 1, base + 2});
  triangles.push_back({base, base + 2, base + 3});
}

Eigen::AlignedBox3d TriangleMesh::bounds() const {
  Eigen::AlignedBox3d box;
  for (const auto& v : vertices) box.extend(v);
  return box;
}

void apply_transform(TriangleMesh& mesh, const Eigen::Matrix3d& linear,
                     const Eigen::Vector3d& offset) {
  for (auto& v : mesh.vertices) v = linear * v + offset;
  if (linear.determinant() < 0)
    for (auto& t : mesh.triangles) std::swap(t[1], t[2]);
}

}  // namespace mb
