#include "scene/scene.h"

#include <cmath>
#include <filesystem>
#include <limits>
#include <numbers>

#include "scene/mesh_loader.h"
#include "scene/procedural.h"
#include "util/eigen.h"
#include "util/error.h"
#include "util/name_list.h"
#include "util/number_text.h"
#include "util/yaml_reader.h"

namespace mb {

namespace {

struct ParamSpec {
  std::string name;
  size_t count;  // 1 for a number, 3 for a vector
  std::vector<double> fallback;
  double min, max;
};

constexpr double kHuge = 1e6;

// One table declares every generator and its parameters; parsing and errors follow from it.
const std::map<std::string, std::vector<ParamSpec>>& generators() {
  static const std::map<std::string, std::vector<ParamSpec>> table = {
      {"ground_plane", {{"size", 1, {20}, 1e-6, kHuge}, {"cells", 1, {1}, 1, 2000}}},
      {"box", {{"size", 3, {1, 1, 1}, 1e-9, kHuge}}},
      {"sphere",
       {{"radius", 1, {1}, 1e-9, kHuge},
        {"rings", 1, {24}, 2, 2000},
        {"segments", 1, {48}, 3, 4000}}},
      {"staircase",
       {{"steps", 1, {8}, 1, 1000},
        {"width", 1, {2}, 1e-9, kHuge},
        {"run", 1, {0.4}, 1e-9, kHuge},
        {"rise", 1, {0.25}, 1e-9, kHuge}}},
      {"building_grid",
       {{"nx", 1, {4}, 1, 1000},
        {"nz", 1, {4}, 1, 1000},
        {"footprint", 1, {1}, 1e-9, kHuge},
        {"spacing", 1, {1.6}, 1e-9, kHuge},
        {"min_height", 1, {0.5}, 1e-9, kHuge},
        {"max_height", 1, {3}, 1e-9, kHuge},
        {"seed", 1, {1}, 0, 1e15}}},
      {"fence",
       {{"length", 1, {6}, 1e-9, kHuge},
        {"height", 1, {1}, 1e-9, kHuge},
        {"post_spacing", 1, {1.5}, 1e-9, kHuge},
        {"rails", 1, {2}, 0, 100},
        {"pickets", 1, {4}, 0, 1000}}},
      {"card_cloud",
       {{"count", 1, {64}, 1, 100000},
        {"size", 1, {0.5}, 1e-9, kHuge},
        {"extent", 3, {2, 1.5, 2}, 1e-9, kHuge},
        {"seed", 1, {1}, 0, 1e15}}},
      {"tree",
       {{"height", 1, {3}, 1e-9, kHuge},
        {"depth", 1, {4}, 0, 10},
        {"branches", 1, {3}, 1, 8},
        {"leaf_size", 1, {0.25}, 1e-9, kHuge},
        {"seed", 1, {1}, 0, 1e15}}},
  };
  return table;
}

bool is_integer_param(const std::string& name) {
  for (const char* n : {"cells", "rings", "segments", "steps", "nx", "nz", "seed", "rails",
                        "pickets", "depth", "branches", "count"})
    if (name == n) return true;
  return false;
}

TransformDesc parse_transform(YamlMap map) {
  TransformDesc t;
  if (auto v = map.numbers("translate", 3))
    t.translate = Eigen::Vector3d((*v)[0], (*v)[1], (*v)[2]);
  if (auto v = map.numbers("rotate", 3)) t.rotate_deg = Eigen::Vector3d((*v)[0], (*v)[1], (*v)[2]);
  if (map.is_sequence("scale")) {
    auto v = *map.numbers("scale", 3);
    t.scale = Eigen::Vector3d(v[0], v[1], v[2]);
  } else if (auto s = map.number("scale", -kHuge, kHuge)) {
    t.scale = Eigen::Vector3d::Constant(*s);
  }
  if (t.scale.prod() == 0) map.fail("scale", "a zero scale flattens the part");
  map.finish();
  return t;
}

std::string where_of(const YamlMap& map) {
  return map.file() + " (" + map.path() + ")";
}

PartDesc parse_part(YamlMap map, const std::filesystem::path& base_dir) {
  PartDesc part;
  part.where = where_of(map);
  std::vector<std::string> kinds = {"mesh"};
  for (const auto& [name, _] : generators()) kinds.push_back(name);
  for (const auto& kind : kinds) {
    if (!map.has(kind)) continue;
    if (!part.kind.empty())
      map.fail(kind, "a part has one of mesh or a generator, but also has '" + part.kind + "'");
    part.kind = kind;
  }
  if (part.kind.empty()) {
    map.also_suggest(kinds);
    map.also_suggest({"transform", "two_sided", "fit", "opacity", "opacity_pattern", "color"});
    map.finish();  // reports a misspelled generator name first
    map.fail("", "a part needs one of: " + joined(kinds, ", "));
  }
  if (part.kind == "mesh") {
    std::filesystem::path file = *map.string("mesh");
    part.mesh_file = (file.is_absolute() ? file : base_dir / file).lexically_normal().string();
    part.fit = map.number("fit", 0, 0, kHuge);
  } else {
    YamlMap params = map.map(part.kind);
    for (const auto& spec : generators().at(part.kind)) {
      std::vector<double> value = spec.fallback;
      if (spec.count == 1) {
        if (auto v = params.number(spec.name, spec.min, spec.max)) value = {*v};
      } else if (auto v = params.numbers(spec.name, spec.count)) {
        for (double x : *v)
          if (x < spec.min || x > spec.max)
            params.fail(spec.name, "every element must be positive");
        value = *v;
      }
      if (is_integer_param(spec.name) && value[0] != std::floor(value[0]))
        params.fail(spec.name, "expected an integer");
      part.params[spec.name] = value;
    }
    params.finish();
  }
  part.two_sided = map.boolean("two_sided", false);
  part.opacity = parse_opacity(map);
  if (auto c = map.numbers("color", 3)) {
    for (double v : *c)
      if (!(v >= 0 && v <= 1))
        map.fail("color",
                 "expected three numbers in [0, 1] (linear RGB reflectance), got " + round_trip(v));
    part.color = Eigen::Vector3d((*c)[0], (*c)[1], (*c)[2]);
  }
  part.transform = parse_transform(map.map("transform"));
  map.finish();
  return part;
}

Eigen::Matrix3d linear_part(const TransformDesc& t) {
  auto radians = [](double d) { return d * std::numbers::pi / 180; };
  Eigen::Matrix3d rotation =
      (Eigen::AngleAxisd(radians(t.rotate_deg.z()), Eigen::Vector3d::UnitZ()) *
       Eigen::AngleAxisd(radians(t.rotate_deg.y()), Eigen::Vector3d::UnitY()) *
       Eigen::AngleAxisd(radians(t.rotate_deg.x()), Eigen::Vector3d::UnitX()))
          .toRotationMatrix();
  return rotation * t.scale.asDiagonal();
}

// A part may build several pieces that differ in sidedness (a tree's wood and its leaves).
std::vector<TriangleMesh> build_part(const PartDesc& part) {
  auto p = [&](const std::string& name) { return part.params.at(name)[0]; };
  auto n = [&](const std::string& name) { return int(part.params.at(name)[0]); };
  std::vector<TriangleMesh> pieces(1);
  pieces.reserve(2);  // `mesh` must stay valid when the leaves are added
  TriangleMesh& mesh = pieces[0];
  if (part.kind == "mesh") {
    try {
      mesh = load_mesh(part.mesh_file);
    } catch (const InputError& e) {
      throw InputError(part.where + ": " + e.what());  // which scene's part asked for it
    }
  } else if (part.kind == "ground_plane") {
    mesh = make_ground_plane(p("size"), n("cells"));
  } else if (part.kind == "box") {
    const auto& s = part.params.at("size");
    mesh = make_box({s[0], s[1], s[2]}, {0, s[1] / 2, 0});
  } else if (part.kind == "sphere") {
    mesh = make_sphere(p("radius"), {0, p("radius"), 0}, n("rings"), n("segments"));
  } else if (part.kind == "staircase") {
    mesh = make_staircase(n("steps"), p("width"), p("run"), p("rise"));
  } else if (part.kind == "building_grid") {
    mesh = make_building_grid(n("nx"), n("nz"), p("footprint"), p("spacing"), p("min_height"),
                              p("max_height"), uint64_t(p("seed")));
  } else if (part.kind == "fence") {
    mesh = make_fence(p("length"), p("height"), p("post_spacing"), n("rails"), n("pickets"));
  } else if (part.kind == "card_cloud") {
    const auto& e = part.params.at("extent");
    mesh = make_card_cloud(n("count"), p("size"), {e[0], e[1], e[2]}, uint64_t(p("seed")));
  } else if (part.kind == "tree") {
    TreeMeshes tree =
        make_tree(p("height"), n("depth"), n("branches"), p("leaf_size"), uint64_t(p("seed")));
    mesh = std::move(tree.wood);
    pieces.push_back(std::move(tree.leaves));  // two-sided whatever the part says
  }
  mesh.two_sided = part.two_sided || part.kind == "card_cloud";  // cards have no inside
  if (part.fit > 0) {
    // Rotate and scale, then normalise: largest extent `fit`, centred in x and z, resting on
    // y = 0; then translate. Meshes from files come in arbitrary units and origins.
    apply_transform(mesh, linear_part(part.transform), Eigen::Vector3d::Zero());
    Eigen::AlignedBox3d box = mesh.bounds();
    double scale = part.fit / box.sizes().maxCoeff();
    Eigen::Vector3d offset(-box.center().x(), -box.min().y(), -box.center().z());
    apply_transform(mesh, Eigen::Matrix3d::Identity() * scale,
                    offset * scale + part.transform.translate);
    return pieces;
  }
  for (auto& piece : pieces)
    apply_transform(piece, linear_part(part.transform), part.transform.translate);
  return pieces;
}

}  // namespace

SceneDesc parse_scene(const std::string& file) {
  YamlMap root = YamlMap::load_file(file, "scene file");
  SceneDesc desc;
  desc.file = file;
  desc.name = root.string("name").value_or(std::filesystem::path(file).stem().string());
  std::filesystem::path base_dir = std::filesystem::path(file).parent_path();
  for (auto& part : root.maps("parts")) desc.parts.push_back(parse_part(part, base_dir));
  if (desc.parts.empty()) root.fail("parts", "a scene needs at least one part");
  for (auto& view : root.maps("views")) {
    LightViewDesc v;
    v.name = view.string("name").value_or("view" + std::to_string(desc.views.size()));
    v.azimuth_deg = view.number("azimuth", 0, -360, 360);
    v.elevation_deg = view.number("elevation", 45, 1, 90);
    v.resolution = int(view.integer("resolution", 512, 1, 16384));
    v.margin = view.number("margin", 0.02, 0, 1);
    v.light_angle_deg = view.number("light_angle", -1, -1e300, 1e300);
    if (v.light_angle_deg >= 90 || (v.light_angle_deg < 0 && v.light_angle_deg != -1))
      view.fail("light_angle",
                "expected the light's angular diameter in degrees, in [0, 90), got " +
                    round_trip(v.light_angle_deg));
    // Outputs are named scene_view: two views of one name would overwrite each other's files.
    for (const auto& other : desc.views)
      if (other.name == v.name)
        view.fail("name", "view name '" + v.name + "' is used twice in this scene");
    view.finish();
    desc.views.push_back(v);
  }
  if (desc.views.empty()) root.fail("views", "a scene needs at least one light view");
  for (auto& camera : root.maps("cameras")) {
    CameraDesc c;
    c.name = camera.string("name").value_or("camera" + std::to_string(desc.cameras.size()));
    if (auto v = camera.numbers("position", 3)) c.position = {(*v)[0], (*v)[1], (*v)[2]};
    if (auto v = camera.numbers("target", 3)) c.target = {(*v)[0], (*v)[1], (*v)[2]};
    c.fov_deg = camera.number("fov", 45, 1, 170);
    if (auto v = camera.numbers("resolution", 2)) {
      for (double d : *v)
        if (!(d >= 1 && d <= 8192 && d == std::floor(d)))
          camera.fail("resolution", "expected [width, height], integers in [1, 8192]");
      c.width = int((*v)[0]), c.height = int((*v)[1]);
    }
    if ((c.target - c.position).norm() <= 0)
      camera.fail("target", "the target must differ from the camera's position");
    for (const auto& other : desc.cameras)
      if (other.name == c.name)
        camera.fail("name", "camera name '" + c.name + "' is used twice in this scene");
    camera.finish();
    desc.cameras.push_back(c);
  }
  desc.medium = parse_medium(root);
  root.finish();
  return desc;
}

bool Scene::translucent() const {
  for (const auto& o : opacity)
    if (!o.opaque()) return true;
  return false;
}

Scene build_scene(const SceneDesc& desc) {
  Scene scene;
  scene.name = desc.name;
  scene.views = desc.views;
  scene.cameras = desc.cameras;
  scene.medium = desc.medium;
  for (const auto& part : desc.parts) {
    scene.opacity.push_back(part.opacity);
    scene.color.push_back(part.color);
    for (const auto& piece : build_part(part)) {
      for (const auto& v : piece.vertices)
        if (!v.allFinite())
          throw InputError(part.where + ": transform produced a non-finite vertex");
      scene.mesh.append(piece);
      scene.two_sided.resize(scene.mesh.triangles.size(), piece.two_sided ? 1 : 0);
      scene.part.resize(scene.mesh.triangles.size(), uint32_t(scene.opacity.size() - 1));
    }
  }
  if (scene.mesh.triangles.empty())
    throw InputError(desc.file + ": the scene is empty (no triangles)");
  return scene;
}

}  // namespace mb
