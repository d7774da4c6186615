#include "scene/dataset_options.h"

namespace mb {

const std::vector<OptionRecord<DatasetOptions>>& dataset_option_records() {
  static const std::vector<OptionRecord<DatasetOptions>> records{
      {{"dataset", OptionType::String, "default",
        "Dataset: a YAML file, or the name of one in configs/datasets/ (tiny, default, paper)."},
       &DatasetOptions::dataset},
      {{"resolution", OptionType::Integer, "0",
        "Shadow-map resolution for every view; 0 keeps the dataset's.", 0, 16384},
       &DatasetOptions::resolution},
      {measures_nothing(
           {"threads", OptionType::Integer, "0", "OpenMP threads; 0 uses every core.", 0, 4096}),
       &DatasetOptions::threads},
  };
  return records;
}

DatasetOptions dataset_options_from(const Config& config) {
  DatasetOptions options;
  read_options(config, dataset_option_records(), options);
  return options;
}

}  // namespace mb
