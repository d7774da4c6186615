#pragma once
// verify's own options (verify.*), declared once and bound to VerifySettings' fields.
#include <cstdint>
#include <string>
#include <vector>

#include "util/option_record.h"

namespace mb {

// verify's settings; a default-made one holds its option records' defaults (written there only).
struct VerifySettings {
  VerifySettings();
  std::vector<std::string> techniques;
  int random, fragments;
  uint64_t seed;
  std::vector<int64_t> grids;
  std::string discretization, moment_box;
  double tolerance, esm_c, evsm_c;
  int csm_terms, worst;
  // Transparency rows (docs/transparency.md §6): MBOIT closed forms against the LP.
  std::vector<std::string> oit_techniques;
  int oit_pixels;
  // Scattering rows (docs/scattering.md §6): pss_msm4, pss_msm6 against pss_lp.
  std::vector<std::string> scatter_techniques;
  std::string scatter_dataset;
  int scatter_rays, scatter_resolution;
};

const std::vector<OptionRecord<VerifySettings>>& verify_options();

}  // namespace mb
