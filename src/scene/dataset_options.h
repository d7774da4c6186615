#pragma once
// The options of every command that reads a dataset: which dataset, at which shadow-map
// resolution, on how many threads. Declared once as records (util/option_record.h).
#include <string>
#include <vector>

#include "util/option_record.h"

namespace mb {

struct DatasetOptions {
  std::string dataset;
  int resolution = 0;  // 0 keeps each view's own
  int threads = 0;     // 0 uses every core
};

const std::vector<OptionRecord<DatasetOptions>>& dataset_option_records();

// The records' values in `config`.
DatasetOptions dataset_options_from(const Config& config);

}  // namespace mb
