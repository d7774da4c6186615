#pragma once
// verify's own options (verify.*), declared once and bound to VerifySettings' fields.
#include <cstdint>
#include <string>
#include <vector>

#include "util/option_record.h"

namespace mb {

struct VerifySettings {
  std::vector<std::string> techniques;
  int random = 2000, fragments = 2000;
  uint64_t seed = 2015;
  std::vector<int64_t> grids;
  std::string discretization, moment_box;
  double tolerance = 1e-6, esm_c = 10, evsm_c = 5;
  int csm_terms = 3, worst = 5;
  // Transparency rows (docs/transparency.md §6): MBOIT closed forms against the LP.
  std::vector<std::string> oit_techniques;
  int oit_pixels = 20;
};

const std::vector<OptionRecord<VerifySettings>>& verify_options();

}  // namespace mb
