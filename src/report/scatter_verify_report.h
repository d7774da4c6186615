#pragma once
// verify's scattering rows in its report (docs/scattering.md §6): a section of verify.md and
// verify_scatter.csv.
#include <string>
#include <vector>

#include "verify/scatter_verification.h"

namespace mb {

// "" when there are no rows.
std::string scatter_verify_section(const std::vector<ScatterVerifyRow>& rows,
                                   const std::string& dataset, int resolution);
std::string scatter_verify_csv(const std::vector<ScatterVerifyRow>& rows);

}  // namespace mb
