#include "report/sweep_transparency.h"

#include <algorithm>
#include <set>

#include "eval/error_stats.h"
#include "techniques/registry.h"
#include "util/number_text.h"

namespace mb {

namespace {

// MBOIT's bases that the catalog holds: the transmittance rows' catalog_basis
// (docs/transparency.md §7).
struct MboitBasis {
  std::set<std::string> functions;
  std::string label;
};

const std::vector<MboitBasis>& mboit_bases() {
  static const std::vector<MboitBasis> bases = [] {
    std::vector<MboitBasis> out;
    for (const TechniqueRow* row : family_rows(TechniqueFamily::Transmittance))
      if (!row->catalog_basis.empty())
        out.push_back(
            {{row->catalog_basis.begin(), row->catalog_basis.end()}, row->catalog_basis_label});
    return out;
  }();
  return bases;
}

// "MBOIT power4's basis: 4; ...": each basis with its number of functions.
std::string basis_sizes() {
  std::string text;
  for (const auto& b : mboit_bases())
    text += (text.empty() ? "" : "; ") + b.label + ": " + std::to_string(b.functions.size());
  return text;
}

std::string pct(double fraction) {
  return percent_text(fraction) + " %";
}

void finding_mboit_bases(std::ostringstream& md, const std::vector<SweepSeries>& series) {
  md << "### MBOIT's bases among the candidates\n\n"
        "Each candidate is judged by the sharp bound of its moments (lp.beta, default 0): MBOIT's "
        "bases below are its closed forms' information, without their overestimation beta and "
        "normalisation.\n\n";
  bool any = false;
  for (const auto& s : series)
    for (const auto& b : mboit_bases()) {
      if (int(b.functions.size()) != s.size) continue;
      any = true;
      const ResultRow* r = find_candidate(s, b.functions);
      md << "- " << s.label << ", " << b.label << ": ";
      if (!r) {
        md << "not among the evaluated candidates\n";
        continue;
      }
      md << r->name << ", " << (r->estimated ? "≈ " : "") << pct(r->mean) << ", "
         << rank_text(s, r->mean) << "; the best: " << pct(s.best()) << " ("
         << s.ranked.front().name << ")\n";
    }
  if (!any)
    md << "- no MBOIT basis has " << main_series(series).size << " functions (" << basis_sizes()
       << ")\n";
  md << "\nMBOIT trig2 and trig3 with the authors' wrapping zone use frequencies 1.9 pi k, outside "
        "the catalog; give `candidates` or `oit_references` their functions to place them.\n\n";
}

void finding_closed_forms(std::ostringstream& md, const SweepSeries& main) {
  md << "### The closed forms and references among the candidates\n\n";
  bool any = false;
  for (const auto& r : main.references) {
    if (technique_role(r.name, {TechniqueFamily::Transmittance}) == RowRole::Reference) continue;
    any = true;
    md << "- " << r.name << ": " << pct(r.mean) << ", " << rank_text(main, r.mean) << "\n";
  }
  if (!any) md << "- no reference technique (option `oit_references`)\n";
  md << "\nMBOIT's rows are its reconstruction (beta and the normalisation Gamma); a candidate's "
        "row is the sharp bound of its moments, which only ever overestimates transmittance.\n\n";
}

void finding_deficit(std::ostringstream& md, const std::vector<SweepSeries>& series) {
  double worst = 0, mean = 0;
  std::string name;
  for (const auto& s : series)
    for (const auto& r : s.ranked) {
      if (r.estimated) continue;
      if (r.max_dark > worst) worst = r.max_dark, name = r.name;
      mean = std::max(mean, r.dark);
    }
  md << "### Transmittance below the exact\n\n"
        "The exact distribution of a pixel's absorbance is feasible for every candidate's LP, so "
        "the exact LP never puts T below T_ref. The LP is solved for the moments rounded to "
        "double, and where two fragments of a pixel lie close in warped depth that rounding moves "
        "the bound (docs/transparency.md §7). Largest T_ref - T at one fragment over the exact "
        "candidates: "
     << round_trip(worst) << (name.empty() ? "" : " (" + name + ")")
     << "; largest mean: " << pct(mean) << ".\n\n";
}

}  // namespace

std::string transparency_protocol_text() {
  return "Target transparency (docs/transparency.md §7). Errors are the opacity-weighted mean "
         "|T_ref - T| over every transparent fragment of every camera, in percent: T_ref the exact "
         "transmittance in front of the fragment (sorted compositing), T a candidate's e^{-b_0 "
         "G}, G Problem 1's bound of the absorbance in front of the fragment from the pixel's "
         "normalised absorbance moments on the warped depth, b_0 the total absorbance. 'T too "
         "high' is the part where the candidate lets too much through (all of a sharp bound's "
         "error), 'T too low' the rest. Reference rows are measured as `oit` measures them (the "
         "transmittance the composite weighs each fragment with). Failures: fragments an LP could "
         "not answer (T = 1).";
}

std::string mboit_basis_mark(const std::string& candidate) {
  const std::set<std::string> functions = candidate_functions(candidate);
  for (const auto& b : mboit_bases())
    if (b.functions == functions) return " (" + b.label + ")";
  return "";
}

void transparency_findings(std::ostringstream& md, const std::vector<SweepSeries>& series) {
  md << "## Findings\n\n";
  finding_mboit_bases(md, series);
  finding_closed_forms(md, main_series(series));
  finding_deficit(md, series);
}

}  // namespace mb
