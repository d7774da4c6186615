#pragma once
// The sweep report of target transparency (docs/transparency.md §7): what its errors mean, MBOIT's
// bases among the candidates, the closed forms against the sharp bounds of the same basis, and
// the measured transmittance deficit of the candidates (the LP's bound on rounded moments).
#include <sstream>
#include <string>
#include <vector>

#include "report/sweep_report.h"

namespace mb {

std::string transparency_protocol_text();
// " (MBOIT power4's basis)" for a candidate whose functions are one of MBOIT's bases in the
// catalog, else "".
std::string mboit_basis_mark(const std::string& candidate);
void transparency_findings(std::ostringstream& md, const std::vector<SweepSeries>& series);

}  // namespace mb
