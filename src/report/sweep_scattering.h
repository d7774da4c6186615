#pragma once
// The sweep report of target scattering (docs/scattering.md §7): what its errors mean, where power
// moments rank among the candidates (seed 004 §2.5 uses them), the prefiltered rows against the
// sharp bounds of the candidates, and the measured darkening of the lower bound (never beyond the
// LP's certified error).
#include <sstream>
#include <string>
#include <vector>

#include "report/sweep_series.h"

namespace mb {

std::string scattering_protocol_text();
void scattering_findings(std::ostringstream& md, const std::vector<SweepSeries>& series);

}  // namespace mb
