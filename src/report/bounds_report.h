#pragma once
// The report of `momentbench bounds` (seed 000, Figure 3): bounds.csv (the CDF and every series'
// sharp lower bound against z_f), distribution.csv and bounds.md (mean and max gap per series).
#include <string>

#include "verify/bound_curves.h"

namespace mb {

struct BoundsRun {
  std::string version, git_sha, started;
};

struct BoundsReport {
  std::string bounds_csv, distribution_csv, markdown;  // markdown without the plot line
};

BoundsReport render_bounds_report(const BoundCurveRequest& request, const BoundCurves& curves,
                                  const std::string& source, const BoundsRun& run);

}  // namespace mb
