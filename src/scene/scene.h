#pragma once
// A scene: parts (mesh files or procedural generators, each with a transform) and the light views
// that look at it. Parsed from YAML into description structs first, then built into triangles.
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "scene/camera.h"
#include "scene/light_view.h"
#include "scene/medium.h"
#include "scene/mesh.h"
#include "scene/opacity.h"

namespace mb {

struct TransformDesc {
  Eigen::Vector3d translate = Eigen::Vector3d::Zero();
  Eigen::Vector3d rotate_deg = Eigen::Vector3d::Zero();  // about x, then y, then z
  Eigen::Vector3d scale = Eigen::Vector3d::Ones();
};

struct PartDesc {
  std::string kind;                                   // "mesh" or a generator name
  std::string mesh_file;                              // for kind == "mesh", resolved path
  std::map<std::string, std::vector<double>> params;  // generator parameters, validated
  double fit = 0;  // mesh only: scale so the largest extent is `fit`, centred, resting on y = 0
  bool two_sided = false;
  OpacityDesc opacity;  // opaque unless the part says otherwise
  // Diffuse reflectance in linear RGB, each in [0, 1]: what a camera frame of `oit` shades
  // (docs/transparency.md); light views ignore it.
  Eigen::Vector3d color = Eigen::Vector3d::Constant(0.8);
  TransformDesc transform;
  std::string where;  // "file:line" for errors found while building
};

struct SceneDesc {
  std::string name;
  std::string file;
  std::vector<PartDesc> parts;
  std::vector<LightViewDesc> views;
  std::vector<CameraDesc> cameras;   // optional: camera images of the techniques' shadows
  std::optional<MediumDesc> medium;  // optional: what `scatter` lights (docs/scattering.md §1)
};

struct Scene {
  std::string name;
  TriangleMesh mesh;                   // all parts, world coordinates
  std::vector<uint8_t> two_sided;      // per triangle
  std::vector<uint32_t> part;          // per triangle: its part, an index into `opacity`
  std::vector<OpacityDesc> opacity;    // per part
  std::vector<Eigen::Vector3d> color;  // per part: PartDesc::color
  bool translucent() const;            // some part is not opaque
  std::vector<LightViewDesc> views;
  std::vector<CameraDesc> cameras;
  std::optional<MediumDesc> medium;
};

SceneDesc parse_scene(const std::string& file);
// Builds triangles; fails on an empty scene or non-finite coordinates after transforms.
Scene build_scene(const SceneDesc& desc);

}  // namespace mb
