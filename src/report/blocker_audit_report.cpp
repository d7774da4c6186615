#include "report/blocker_audit_report.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

#include "eval/error_stats.h"
#include "techniques/registry.h"
#include "util/number_text.h"

namespace mb {

std::string blocker_audit_csv(const std::vector<ViewBlockerAudit>& audits) {
  std::ostringstream csv;
  csv << "scene,view,light_angle,receiver,zs,blocker_exact,blocker_seed,blocker_lo,blocker_hi,"
         "penumbra_exact,penumbra_seed,penumbra_lo,penumbra_hi,outside\n";
  for (const auto& audit : audits)
    for (const auto& r : audit.rows)
      csv << audit.scene << "," << audit.view << "," << round_trip(audit.angle_deg) << ","
          << r.receiver << "," << round_trip(r.zs) << "," << round_trip(r.exact) << ","
          << round_trip(r.seed) << "," << round_trip(r.lo) << "," << round_trip(r.hi) << ","
          << round_trip(r.penumbra_exact) << "," << round_trip(r.penumbra_seed) << ","
          << round_trip(r.penumbra_lo) << "," << round_trip(r.penumbra_hi) << ","
          << (r.outside() ? 1 : 0) << "\n";
  return csv.str();
}

namespace {

struct AngleSummary {
  size_t rows = 0, outside = 0, undetermined = 0;
  double seed_error = 0, width = 0;  // sums, in penumbra texels
};

}  // namespace

std::string blocker_audit_section(const std::vector<ViewBlockerAudit>& audits) {
  std::map<double, AngleSummary> by_angle;
  for (const auto& audit : audits)
    for (const auto& r : audit.rows) {
      AngleSummary& s = by_angle[audit.angle_deg];
      const double width = std::abs(r.penumbra_hi - r.penumbra_lo);
      ++s.rows;
      s.outside += r.outside();
      s.undetermined += width > 1;
      s.seed_error += std::abs(r.penumbra_seed - r.penumbra_exact);
      s.width += width;
    }
  if (by_angle.empty()) return "";
  std::ostringstream md;
  std::string audited;  // the soft rows whose blocker search eval audits
  for (const TechniqueRow* row : family_rows(TechniqueFamily::SoftShadow))
    if (row->audits_blocker) audited += (audited.empty() ? "" : ", ") + row->name;
  md << "## " << audited << "'s blocker search against its sharp bounds\n\n"
     << "On evenly spaced receivers whose search region holds a blocker (soft.audit per view; "
        "blocker_audit.csv), the mean blocker depth that any distribution with the region's four "
        "moments allows lies in [lo, hi] (docs/soft-shadows.md §3). Seed 004's estimate outside "
        "that interval is an error of its heuristic, not of the moments; the interval's width in "
        "penumbra texels is what four moments cannot decide.\n\n"
     << "| light angle | receivers | estimate outside % | mean distance of the estimate from the "
        "own mean (texels) | "
        "mean width (texels) | width > 1 texel % |\n|---|---|---|---|---|---|\n";
  for (const auto& [angle, s] : by_angle) {
    const double n = double(s.rows);
    md << "| " << round_trip(angle) << "° | " << s.rows << " | "
       << percent_text(double(s.outside) / n) << " | " << format_number(s.seed_error / n, "%.3g")
       << " | " << format_number(s.width / n, "%.3g") << " | "
       << percent_text(double(s.undetermined) / n) << " |\n";
  }
  return md.str() + "\n";
}

}  // namespace mb
