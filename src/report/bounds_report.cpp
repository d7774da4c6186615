#include "report/bounds_report.h"

#include <cmath>
#include <cstdio>
#include <sstream>

#include "util/name_list.h"
#include "util/number_text.h"

namespace mb {

BoundsReport render_bounds_report(const BoundCurveRequest& request, const BoundCurves& curves,
                                  const std::string& source, const BoundsRun& run) {
  std::ostringstream csv, dist, md;
  csv << "zf,cdf";
  for (const auto& s : curves.series) csv << ",\"" << s.basis << " m=" << s.m << "\"";
  csv << "\n";
  for (size_t i = 0; i < curves.zf.size(); ++i) {
    csv << round_trip(curves.zf[i]) << "," << round_trip(curves.cdf[i]);
    for (const auto& s : curves.series)
      csv << "," << (std::isnan(s.lower[i]) ? std::string() : round_trip(s.lower[i]));
    csv << "\n";
  }
  dist << "depth,weight\n";
  for (size_t t = 0; t < request.depths.size(); ++t)
    if (request.weights[t] > 0)
      dist << round_trip(request.depths[t]) << "," << round_trip(request.weights[t]) << "\n";

  md << "# Sharp lower bounds of Problem 1 for one kernel (seed 000, Figure 3)\n\n"
     << "Made by momentbench " << run.version << " (git " << run.git_sha << "), " << request.threads
     << " threads, " << run.started << ".\n\n"
     << "- Distribution: " << source << "\n"
     << "- LP: I = " << request.lp.grid << "-point grid on [" << format_number(request.lp.lo, "%g")
     << ", " << format_number(request.lp.hi, "%g")
     << "] ∪ the distribution's depths ∪ {z_f} (docs/reference.md §2), backend " << request.backend
     << "; " << request.samples << " values of z_f on [" << format_number(request.zf_lo, "%g")
     << ", " << format_number(request.zf_hi, "%g") << "]\n"
     << "- Gap = F_Z(z_f) − G(b, z_f) ≥ 0; its mean over z_f is the area between the CDF and the "
        "bound.\n\n"
     << "| basis | m | functions | mean gap | max gap | LPs not optimal "
        "|\n|---|---|---|---|---|---|\n";
  for (const auto& s : curves.series) {
    md << "| " << s.basis << " | " << s.m << " | " << joined(s.functions, ", ") << " | "
       << format_number(s.mean_gap, "%.5f") << " | " << format_number(s.max_gap, "%.5f") << " | "
       << s.failures << " |\n";
  }
  return {csv.str(), dist.str(), md.str()};
}

}  // namespace mb
