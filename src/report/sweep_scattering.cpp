#include "report/sweep_scattering.h"

#include <algorithm>
#include <set>

#include "eval/error_stats.h"
#include "lp/solution.h"
#include "util/number_text.h"

namespace mb {

namespace {

std::string pct(double fraction) {
  return percent_text(fraction) + " %";
}

// z, z^2, ..., z^m: the power moments of m functions, spelt as the catalog spells them.
std::set<std::string> power_functions(int m) {
  std::set<std::string> out;
  for (int k = 1; k <= m; ++k) out.insert(k == 1 ? "z" : "z^" + std::to_string(k));
  return out;
}

// Seed 004 §2.5 prefilters power moments; how far the best basis of the same size lies from them.
void finding_power_moments(std::ostringstream& md, const std::vector<SweepSeries>& series) {
  md << "### Power moments among the candidates\n\n"
        "Each candidate is pss_lp:<candidate> at beta 0, the sharp lower bound its moments allow "
        "on every ray's shadowed fraction; power moments z, ..., z^m are what seed 004 "
        "prefilters (pss_msm4, pss_msm6 are their closed forms).\n\n";
  for (const auto& s : series) {
    md << "- " << s.label << ", power moments: ";
    const ResultRow* r = s.size <= 6 ? find_candidate(s, power_functions(s.size)) : nullptr;
    if (!r) {
      md << "not among the evaluated candidates\n";
      continue;
    }
    md << (r->estimated ? "≈ " : "") << pct(r->mean) << ", " << rank_text(s, r->mean)
       << "; the best: " << pct(s.best()) << " (" << s.ranked.front().name << ")";
    if (r->mean > 0) md << ", " << round_trip(s.best() / r->mean) << " of power moments' error";
    md << "\n";
  }
  md << "\n";
}

void finding_references(std::ostringstream& md, const SweepSeries& main) {
  md << "### The prefiltered techniques among the candidates\n\n";
  if (main.references.empty()) md << "- no reference technique (option `scatter_references`)\n";
  for (const auto& r : main.references)
    md << "- " << r.name << ": " << pct(r.mean) << ", " << rank_text(main, r.mean) << "\n";
  md << "\nThe references run at scatter.beta (seed 004 §2.4: 0.5) and the candidates at 0, so a "
        "reference may sit below every candidate's sharp lower bound: its error mixes darker "
        "and brighter rays.\n\n";
}

void finding_too_dark(std::ostringstream& md, const std::vector<SweepSeries>& series) {
  double worst = 0;
  std::string name;
  for (const auto& s : series)
    for (const auto& r : s.ranked)
      if (!r.estimated && r.max_dark > worst) worst = r.max_dark, name = r.name;
  md << "### Too dark\n\n"
        "At beta 0 a candidate's shadowed fraction is the LP's sharp lower bound for the ray's "
        "own distribution of depths, which pss_exact's is one of: never too dark beyond the "
        "LP's certified error ("
     << round_trip(lp::kCertifiedError)
     << "). Largest too-dark error of one ray over the exact candidates, as a fraction of its "
        "S_max: "
     << round_trip(worst) << (name.empty() ? "" : " (" + name + ")")
     << (worst > lp::kCertifiedError ? " — **above the certified error**" : "") << ".\n\n";
}

}  // namespace

std::string scattering_protocol_text() {
  return "Target scattering (docs/scattering.md §7). Errors are `scatter`'s mean_error: "
         "Σ|I - I_ref| / Σ S_max over every pixel of every light view and camera, in percent, "
         "I_ref the in-scattering of pss_exact (the rectified row's own visibility, so that an "
         "error is the moments' loss alone), I a candidate's pss_lp:<candidate> at beta 0 (Problem "
         "1's sharp lower bound on the ray's shadowed fraction from its row's prefix-summed "
         "moments), S_max what the ray could scatter unshadowed. 'too bright' is the part where "
         "I > I_ref (all of a lower bound's error), 'too dark' the rest. Failures: rays whose LP "
         "had no certified answer (answered lit).";
}

void scattering_findings(std::ostringstream& md, const std::vector<SweepSeries>& series) {
  md << "## Findings\n\n";
  finding_power_moments(md, series);
  finding_references(md, main_series(series));
  finding_too_dark(md, series);
}

}  // namespace mb
