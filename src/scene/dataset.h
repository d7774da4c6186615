#pragma once
// A dataset: the scenes (and so the light views) an evaluation runs on (docs/reference.md §3: the
// paper used four views of three scenes).
#include <optional>
#include <string>
#include <vector>

#include "scene/medium.h"

namespace mb {

struct DatasetDesc {
  std::string name;
  std::string file;
  std::vector<std::string> scene_files;  // resolved paths
  int resolution = 0;                    // > 0 overrides every view's resolution
  // Soft shadows (docs/soft-shadows.md §1): each view that names no light angle of its own is
  // evaluated once per angle listed here, in degrees; empty: the option light.angle.
  std::vector<double> light_angles;
  // The medium of every scene that declares none of its own (docs/scattering.md §1).
  std::optional<MediumDesc> medium;
};

// `name_or_path` is a YAML file, or a name looked up in the source tree's configs/datasets/.
DatasetDesc load_dataset(const std::string& name_or_path);
// The file a dataset name resolves to (or the path itself).
std::string resolve_dataset_path(const std::string& name_or_path);

}  // namespace mb
