#include "report/scatter_verify_report.h"

#include <sstream>

#include "util/number_text.h"

namespace mb {

std::string scatter_verify_section(const std::vector<ScatterVerifyRow>& rows,
                                   const std::string& dataset, int resolution) {
  if (rows.empty()) return "";
  std::ostringstream md;
  md << "\n## Scattering: the prefiltered moment rows against the LP\n\n"
        "Each row's shadowed fraction of a view ray at moment bias 0, Hamburger's bounds on R "
        "from the ray's row-prefiltered moments, against pss_lp on the same prefix sums at the "
        "same scatter.beta (docs/scattering.md §6), *equal* at both: the continuous LP "
        "(certified) on an interval wide enough for the canonical nodes, its minimum at beta 0 "
        "(the sharp lower bound G) and its maximum by reflection at beta 1 (the upper bound "
        "G + w_1). "
        "Rays: seeded random pixels of every light view and camera of the "
     << dataset << " dataset, rectified maps of " << resolution
     << " texels a row, each ray ending at its pixel's surface or at a seeded point in front of "
        "it. *undefined*: the closed form had no canonical distribution (a singular Hankel "
        "matrix: a row of one depth) and answered by its fall-back, not compared. *LP failures*: "
        "rays whose LP gave no certified answer, counted and not compared. A compared ray beyond "
        "the tolerance, or no ray compared at all, fails verify (exit 5).\n\n"
        "| technique | beta | LP | LP interval | check | rays | undefined | largest dF | "
        "tolerance | beyond | LP failures | worst | verdict |\n"
        "|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const auto& r : rows)
    md << "| " << r.technique << " | " << format_number(r.beta, "%g") << " | " << r.lp_technique
       << " | [" << format_number(r.lo, "%.6g") << ", " << format_number(r.hi, "%.6g") << "] | "
       << r.kind << " | " << r.rays << " | " << r.undefined << " | "
       << format_number(r.largest, "%.3g") << " | " << format_number(r.tolerance, "%.0e") << " | "
       << r.beyond << " | " << r.lp_failures << " | " << (r.worst.empty() ? "-" : r.worst) << " | "
       << (r.passed() ? "pass" : "**FAIL**") << " |\n";
  return md.str();
}

std::string scatter_verify_csv(const std::vector<ScatterVerifyRow>& rows) {
  std::ostringstream csv;
  csv << "technique,beta,lp_technique,check,lo,hi,rays,undefined,compared,largest_dF,tolerance,"
         "beyond,"
         "lp_failures,worst,passed\n";
  for (const auto& r : rows)
    csv << r.technique << "," << round_trip(r.beta) << ",\"" << r.lp_technique << "\"," << r.kind
        << "," << round_trip(r.lo) << "," << round_trip(r.hi) << "," << r.rays << "," << r.undefined
        << "," << r.compared << "," << round_trip(r.largest) << "," << round_trip(r.tolerance)
        << "," << r.beyond << "," << r.lp_failures << ",\"" << r.worst << "\","
        << (r.passed() ? "true" : "false") << "\n";
  return csv.str();
}

}  // namespace mb
