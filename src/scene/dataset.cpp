#include "scene/dataset.h"

#include <filesystem>

#include "util/error.h"
#include "util/install_paths.h"
#include "util/number_text.h"
#include "util/yaml_reader.h"

namespace mb {

namespace fs = std::filesystem;

std::string resolve_dataset_path(const std::string& name_or_path) {
  if (fs::exists(name_or_path)) return name_or_path;
  bool bare_name =
      name_or_path.find('/') == std::string::npos && fs::path(name_or_path).extension().empty();
  if (bare_name) {
    fs::path builtin = data_root() / "configs" / "datasets" / (name_or_path + ".yaml");
    if (fs::exists(builtin)) return builtin.string();
    std::string names;
    for (const auto& entry : fs::directory_iterator(builtin.parent_path()))
      if (entry.path().extension() == ".yaml")
        names += (names.empty() ? "" : ", ") + entry.path().stem().string();
    throw InputError("dataset '" + name_or_path + "' not found; built-in datasets: " + names);
  }
  throw InputError(name_or_path + ": dataset file not found");
}

DatasetDesc load_dataset(const std::string& name_or_path) {
  DatasetDesc desc;
  desc.file = resolve_dataset_path(name_or_path);
  YamlMap root = YamlMap::load_file(desc.file, "dataset file");
  desc.name = root.string("name").value_or(fs::path(desc.file).stem().string());
  desc.resolution = int(root.integer("resolution", 0, 0, 16384));
  if (auto angles = root.numbers("light_angles", 0)) {
    for (double a : *angles)
      if (!(a >= 0 && a < 90))
        root.fail("light_angles",
                  "expected angular diameters in degrees, in [0, 90), got " + round_trip(a));
    desc.light_angles = *angles;
  }
  fs::path base = fs::path(desc.file).parent_path();
  for (const auto& scene : root.strings("scenes")) {
    fs::path path = fs::path(scene).is_absolute() ? fs::path(scene) : base / scene;
    desc.scene_files.push_back(path.lexically_normal().string());
  }
  if (desc.scene_files.empty()) root.fail("scenes", "a dataset needs at least one scene");
  desc.medium = parse_medium(root);
  root.finish();
  return desc;
}

}  // namespace mb
