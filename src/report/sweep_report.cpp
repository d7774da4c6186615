#include "report/sweep_report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>
#include <sstream>

#include "basis/basis.h"
#include "eval/error_stats.h"
#include "report/darkening.h"
#include "report/series_identity.h"
#include "report/sweep_scattering.h"
#include "report/sweep_transparency.h"
#include "shadow/fragments.h"
#include "sweep/candidates.h"
#include "sweep/run_identity.h"
#include "techniques/lp_technique.h"
#include "techniques/registry.h"
#include "util/error.h"
#include "util/name_list.h"
#include "util/number_text.h"

namespace mb {

namespace {

// Margins of the "ties at the top" count: absolute differences of mean error, as fractions
// (0.01 % = 1e-4), as Peters' dissertation counts candidates that realize the top performance.
constexpr double kTieMargins[] = {1e-4, 5e-4, 1e-3};

// The hard-shadow reference row (pcf's role): it has no rank among the candidates.
bool is_hard_reference(const std::string& name) {
  const TechniqueRow* row = find_technique(name, TechniqueFamily::HardShadow);
  return row && row->role == RowRole::Reference;
}

const ResultRow* find_row(const std::vector<ResultRow>& rows, const std::string& name) {
  auto it = std::find_if(rows.begin(), rows.end(), [&](const auto& r) { return r.name == name; });
  return it == rows.end() ? nullptr : &*it;
}

std::string pct(double fraction) {
  return percent_text(fraction) + " %";
}

uint64_t planned_total(const SweepSeries& s) {
  const auto it = s.meta.find("catalog_size");
  return it == s.meta.end() ? 0 : binomial(std::stoi(it->second), s.size);
}

std::string row_line(size_t rank, const ResultRow& r, bool transparency) {
  std::ostringstream s;
  const std::string name = r.name + (transparency ? mboit_basis_mark(r.name) : "");
  if (r.estimated) {  // an estimate: its standard error, and nothing the sample cannot tell
    s << "| " << rank << " | " << r.id << " | " << name << " | ≈ " << percent_text(r.mean) << " ± "
      << percent_text(r.se) << " (estimate) | - | - | " << r.solved << " of a sample | "
      << r.unstable << " |";
    return s.str();
  }
  s << "| " << rank << " | " << r.id << " | " << name << " | " << percent_text(r.mean) << " | "
    << percent_text(r.leak) << " | " << darkening_text(r.dark, r.max_dark, r.darkening_bound)
    << " | " << r.solved << " | " << (r.infeasible + r.unstable) << " |";
  return s.str();
}

// Functions per candidate (the seed paper's Figure 3).
void finding_sizes(std::ostringstream& md, const std::vector<SweepSeries>& series) {
  const SweepSeries& main = main_series(series);
  std::set<int> sizes;
  for (const auto& s : series) sizes.insert(s.size);
  md << "### Four functions against two or three\n\n";
  if (sizes.size() < 2) {
    md << "Only candidates of " << main.size
       << " functions are in this report; give `report` sweeps of several "
       << "`combination_size` values to compare (the paper: four clearly beat two or three, its "
          "Figure 3).\n\n";
  } else {
    md << "| series | candidates | best % | median % | worst % | best candidate "
          "|\n|---|---|---|---|---|---|\n";
    for (const auto& s : series)
      md << "| " << s.label << " | " << s.ranked.size() << " | " << percent_text(s.best()) << " | "
         << percent_text(s.median()) << " | " << percent_text(s.ranked.back().mean) << " | "
         << s.ranked.front().name << " |\n";
    std::vector<const SweepSeries*> by_size;
    for (const auto& s : series) by_size.push_back(&s);
    std::stable_sort(by_size.begin(), by_size.end(),
                     [](auto* a, auto* b) { return a->size < b->size; });
    bool best_falls = true, median_falls = true;
    for (size_t i = 1; i < by_size.size(); ++i) {
      if (by_size[i]->size == by_size[i - 1]->size) continue;
      best_falls = best_falls && by_size[i]->best() < by_size[i - 1]->best();
      median_falls = median_falls && by_size[i]->median() < by_size[i - 1]->median();
    }
    md << "\nThe paper: four channels clearly outperform two or three (its Figure 3). Here: "
       << (best_falls ? "the best error falls" : "the best error does **not** fall") << " and "
       << (median_falls ? "the median error falls" : "the median error does **not** fall")
       << " with every added function" << (best_falls && median_falls ? " — agrees" : " — differs")
       << ".\n\n";
  }
}

// The references whose basis the seed paper ranked (seed 000 §3.2), in row order.
std::vector<SweepReference> ranked_bases() {
  std::vector<SweepReference> bases;
  for (const SweepReference& r : sweep_references(TechniqueFamily::HardShadow))
    if (!r.moments.empty()) bases.push_back(r);
  return bases;
}

// A candidate's name as the sweep writes it ("f1; f2; ..."), for an lp: reference.
std::string candidate_name(const SweepReference& reference) {
  std::string name;
  for (const std::string& item : lp_technique_basis(reference.name)) {
    std::vector<std::string> set = named_basis_set(item);
    if (set.empty()) set = {item};
    for (const auto& f : set) name += (name.empty() ? "" : "; ") + f;
  }
  return name;
}

// The bases the seed paper ranked, against the candidates and the paper's numbers.
void finding_bases(std::ostringstream& md, const std::vector<SweepSeries>& series) {
  const SweepSeries& main = main_series(series);
  md << "### Power and trigonometric moments (" << main.label << ")\n\n";
  const std::vector<SweepReference> bases = ranked_bases();
  for (const SweepReference& basis : bases) {
    const std::string label = basis.moments + " moments";
    const ResultRow* candidate = find_row(main.ranked, candidate_name(basis));
    const ResultRow* reference = find_row(main.references, basis.name);
    const ResultRow* row = candidate ? candidate : reference;
    if (!row) {
      md << "- " << label << ": neither among the candidates nor a reference (add `" << basis.name
         << "` to `references`)\n";
      continue;
    }
    md << "- " << label << " (" << candidate_name(basis) << "): " << pct(row->mean) << ", "
       << rank_text(main, row->mean) << (candidate ? "" : ", from the reference row")
       << "; the paper: " << pct(basis.seed_error) << "\n";
  }
  // The paper's best basis against its runner-up, where both were measured.
  std::vector<std::pair<const SweepReference*, const ResultRow*>> measured;
  for (const SweepReference& basis : bases)
    if (const ResultRow* row = find_row(main.references, basis.name))
      measured.emplace_back(&basis, row);
  std::stable_sort(measured.begin(), measured.end(), [](const auto& a, const auto& b) {
    return a.first->seed_error < b.first->seed_error;
  });
  if (measured.size() == 2 && measured.size() == bases.size()) {
    const auto& [best, best_row] = measured[0];
    const auto& [next, next_row] = measured[1];
    md << "\nThe paper found " << best->moments << " moments best and " << next->moments
       << " moments close behind. Here "
       << (best_row->mean < next_row->mean
               ? best->moments + " moments are the better of the two"
               : next->moments + " moments are the better of the two (the paper: " + best->moments +
                     ")")
       << ", by " << percent_text(std::abs(best_row->mean - next_row->mean))
       << " percentage points; the best candidate is " << pct(main.best()) << ".\n";
  }
  md << "\n";
}

// The LP grid's bias, where a closed form of the continuous problem measures it.
void finding_lp_grid_bias(std::ostringstream& md, const std::vector<SweepSeries>& series) {
  const SweepSeries& main = main_series(series);
  // The LP grid's bias (docs/reference.md §2): a grid admits fewer distributions than the interval,
  // so every candidate's LP error is optimistic. Rows that solve the continuous Problem 1 on
  // [0, 1] in closed form (techniques/lp_technique.h, continuous_lp_of) measure the bias there.
  const std::optional<LpGridIdentity> lp_grid = lp_grid_of(main.meta);
  md << "### The LP grid's bias (" << main.label << ")\n\n";
  if (!lp_grid) {
    md << "- the database does not record its LP discretisation\n\n";
    return;
  }
  const double lo = lp_grid->lo, hi = lp_grid->hi;
  md << "Each candidate is judged by an LP on " << lp_grid->grid << " grid points of ["
     << round_trip(lo) << ", " << round_trip(hi)
     << "] plus the kernel's depths. A grid admits fewer distributions than the interval, so "
        "every LP error is optimistic (docs/reference.md §2), by an amount that varies by "
        "candidate. Measured in this run where the continuous problem has a closed form:\n\n";
  bool measured = false;
  std::string needs;
  for (const TechniqueRow* closed : family_rows(TechniqueFamily::HardShadow)) {
    const std::string lp_name = continuous_lp_of(*closed);
    if (lp_name.empty()) continue;
    needs += (needs.empty() ? "" : " or ") + lp_name + " and " + closed->name;
    std::string basis = lp_name;
    for (const SweepReference& r : ranked_bases())
      if (r.name == lp_name) basis = r.moments + " moments";
    const ResultRow* lp_row = find_row(main.references, lp_name);
    const ResultRow* exact = find_row(main.references, closed->name);
    if (!lp_row || !exact || lo != 0 || hi != 1) continue;
    measured = true;
    md << "- " << basis << ": " << lp_name << " " << pct(lp_row->mean) << " on the grid, "
       << closed->name << " " << pct(exact->mean)
       << " on [0, 1]: the grid understates the error by "
       << percent_text(exact->mean - lp_row->mean) << " percentage points\n";
  }
  if (!measured)
    md << "- not measured: it needs the references " << needs << ", and the LP on [0, 1]\n";
  md << "\nDifferences between candidates smaller than this bias are not resolved by the LP "
        "(compare the tie margins below); a finer `lp.grid` shrinks it.\n\n";
}

// The classic techniques against the candidates, with what the seeds found of each.
void finding_classics(std::ostringstream& md, const std::vector<SweepSeries>& series) {
  const SweepSeries& main = main_series(series);
  md << "### Classic techniques (" << main.label << ")\n\n";
  std::vector<SweepReference> classics;
  for (const SweepReference& r : sweep_references(TechniqueFamily::HardShadow))
    if (!r.expectation.empty()) classics.push_back(r);
  std::stable_sort(classics.begin(), classics.end(),
                   [](const auto& a, const auto& b) { return a.place < b.place; });
  bool any = false;
  for (const SweepReference& c : classics) {
    const ResultRow* r = find_row(main.references, c.name);
    if (!r) continue;
    any = true;
    md << "- " << c.name << ": " << pct(r->mean) << ", " << rank_text(main, r->mean)
       << "; expected: " << c.expectation << "\n";
  }
  if (!any) md << "- no classic technique among the references (option `references`)\n";
  md << "\n";
}

// Ties at the top (Peters' dissertation: ~15 000 of 66 045 once the LP was exact).
void finding_ties(std::ostringstream& md, const std::vector<SweepSeries>& series) {
  md << "### Candidates tied at the top\n\nCandidates whose mean error lies within an absolute "
        "margin of the best. "
        "Peters' dissertation (docs/reference.md §3) found about 15 000 of the 66 045 realizing "
        "the top "
        "performance once "
        "the LP's tolerances were small. For a sample, the share projects to all combinations.\n\n"
     << "| series | evaluated | best % |";
  for (double m : kTieMargins) md << " within " << round_trip(100 * m) << " % |";
  md << "\n|---|---|---|---|---|---|\n";
  for (const auto& s : series) {
    md << "| " << s.label << " | " << s.ranked.size() << " of " << planned_total(s) << " | "
       << percent_text(s.best()) << " |";
    for (double m : kTieMargins) {
      const size_t n = s.within(m);
      md << " " << n;
      if (s.ranked.size() < planned_total(s))
        md << " (~"
           << uint64_t(std::llround(double(n) / double(s.ranked.size()) * double(planned_total(s))))
           << " of all)";
      md << " |";
    }
    md << "\n";
  }
}

// Over-darkening: the LP is exact, so no candidate may exceed its bound, where the settings give
// it one (each row's own: none under an area light, report/series_identity.h).
void finding_over_darkening(std::ostringstream& md, const std::vector<SweepSeries>& series) {
  double worst = 0;
  std::string worst_name, unbounded;
  bool violated = false;
  for (const auto& s : series)
    for (const auto& r : s.ranked) {
      if (r.max_dark > worst) worst = r.max_dark, worst_name = r.name;
      violated |= darkening_violates(r.max_dark, r.darkening_bound);
      if (can_over_darken(r.darkening_bound) && unbounded.empty())
        unbounded = r.darkening_reason.empty() ? "no proven bound" : r.darkening_reason;
    }
  md << "\n### Over-darkening\n\n"
     << (unbounded.empty()
             ? "Every candidate is the exact LP of Problem 1 with the kernel's own distribution "
               "feasible, so G <= F_Z(z_f - delta_f) <= PCF at every fragment (docs/reference.md "
               "§3). "
             : "No bound applies (" + unbounded + "). ")
     << "Largest G - PCF at one fragment over all candidates: " << round_trip(worst)
     << (worst_name.empty() ? "" : " (" + worst_name + ")")
     << (violated            ? " — **above the certified bound: a bug**"
         : unbounded.empty() ? " — as expected"
                             : "")
     << ".\n\n";
}

void findings(std::ostringstream& md, const std::vector<SweepSeries>& series) {
  md << "## Findings of the seed paper, checked on this data\n\n"
     << "Each claim of seed 000 §3.2 (docs/reference.md §3) next to what this report's databases "
        "show. "
        "The paper's own "
        "scenes are not available, so absolute errors differ; orderings and shapes are what can "
        "agree.\n\n";

  finding_sizes(md, series);
  finding_bases(md, series);
  finding_lp_grid_bias(md, series);
  finding_classics(md, series);
  finding_ties(md, series);
  finding_over_darkening(md, series);
}

}  // namespace

namespace {

// Whether every series was measured with the same values of the keys allowed to differ (report
// --allow-different): then their references are one measurement, the main series'; otherwise
// each series' references are its own, and every table of them names its series.
bool measured_alike(const std::vector<SweepSeries>& series) {
  return std::all_of(series.begin(), series.end(), [&](const SweepSeries& s) {
    return s.own_values == series.front().own_values;
  });
}

// The series whose references a report shows: the main one, or each when they were measured
// differently.
std::vector<const SweepSeries*> reference_series(const std::vector<SweepSeries>& series) {
  if (measured_alike(series)) return {&main_series(series)};
  std::vector<const SweepSeries*> out;
  for (const auto& s : series) out.push_back(&s);
  return out;
}

}  // namespace

SweepReportTables sweep_report_tables(const std::vector<SweepSeries>& series, int bins) {
  SweepReportTables t;
  std::ostringstream candidates, histogram, summary, references;
  candidates << "series,rank,id,functions,mean_error,leak,over_darkening,max_over_darkening,max_"
                "error,share_over_0.1,"
                "fragments,solved,skipped,infeasible,unstable,view_errors,exact,standard_"
                "error\n";
  double lo = series.front().best(), hi = lo;
  for (const auto& s : series) {
    lo = std::min(lo, s.best());
    hi = std::max(hi, s.ranked.back().mean);
    for (size_t i = 0; i < s.ranked.size(); ++i) {
      const ResultRow& r = s.ranked[i];
      std::string views = r.view_errors;
      std::replace(views.begin(), views.end(), '"', '\'');
      candidates << '"' << s.label << "\"," << i + 1 << "," << r.id << ",\"" << r.name << "\","
                 << round_trip(r.mean) << "," << round_trip(r.leak) << "," << round_trip(r.dark)
                 << "," << round_trip(r.max_dark) << "," << round_trip(r.max) << ","
                 << round_trip(r.share_over_tenth) << "," << r.fragments << "," << r.solved << ","
                 << r.skipped << "," << r.infeasible << "," << r.unstable << ",\"" << views << "\","
                 << (r.estimated ? 0 : 1) << "," << round_trip(r.se) << "\n";
    }
  }
  hi = std::max(hi, lo + 1e-12);
  // `exact`: how many of a bin's candidates are exact means, not screened estimates (the plot
  // draws them apart).
  histogram << "series,error_lo,error_hi,candidates,exact\n";
  summary << "series,size,database,evaluated,combinations,best,median,worst,best_candidate";
  for (double m : kTieMargins) summary << ",within_" << round_trip(100 * m) << "pct";
  summary << "\n";
  for (const auto& s : series) {
    std::vector<uint64_t> counts(bins, 0), exact(bins, 0);
    for (const auto& r : s.ranked) {
      const int b = std::min(bins - 1, int((r.mean - lo) / (hi - lo) * bins));
      counts[b]++;
      exact[b] += r.estimated ? 0 : 1;
    }
    for (int b = 0; b < bins; ++b)
      histogram << '"' << s.label << "\"," << round_trip(lo + (hi - lo) * b / bins) << ","
                << round_trip(lo + (hi - lo) * (b + 1) / bins) << "," << counts[b] << ","
                << exact[b] << "\n";
    summary << '"' << s.label << "\"," << s.size << ",\"" << s.database << "\"," << s.ranked.size()
            << "," << planned_total(s) << "," << round_trip(s.best()) << ","
            << round_trip(s.median()) << "," << round_trip(s.ranked.back().mean) << ",\""
            << s.ranked.front().name << "\"";
    for (double m : kTieMargins) summary << "," << s.within(m);
    summary << "\n";
  }
  // One measurement: its references as they are; several (--allow-different): each series' own,
  // named by a first column.
  const bool alike = measured_alike(series);
  references << (alike ? "" : "series,")
             << "technique,mean_error,leak,over_darkening,max_over_darkening\n";
  for (const SweepSeries* s : reference_series(series))
    for (const auto& r : s->references)
      references << (alike ? "" : "\"" + s->label + "\",") << '"' << r.name << "\","
                 << round_trip(r.mean) << "," << round_trip(r.leak) << "," << round_trip(r.dark)
                 << "," << round_trip(r.max_dark) << "\n";
  t.candidates_csv = candidates.str();
  t.histogram_csv = histogram.str();
  t.series_csv = summary.str();
  t.references_csv = references.str();
  return t;
}

namespace {

// Three lines before the tables: what ran, each series' best candidate, what needs attention
// (failed LPs, a missing shard, a candidate or reference above its proven bound).
std::string summary_lines(const std::vector<SweepSeries>& series) {
  std::ostringstream s, attention;
  size_t candidates = 0;
  uint64_t failed = 0, above = 0;
  for (const auto& x : series) {
    candidates += x.ranked.size();
    for (const auto& r : x.ranked) {
      failed += r.infeasible + r.unstable;
      above += !r.estimated && darkening_violates(r.max_dark, r.darkening_bound);
    }
    if (x.meta.count("missing_shards"))
      attention << (attention.tellp() > 0 ? "; " : "") << x.label << " lacks shards "
                << x.meta.at("missing_shards");
  }
  s << "**Summary.** " << candidates << " candidates in " << series.size() << " series on dataset "
    << main_series(series).meta.at("dataset") << ".  \nBest: ";
  for (size_t i = 0; i < series.size(); ++i)
    s << (i ? "; " : "") << series[i].label << " " << percent_text(series[i].best()) << " % ("
      << series[i].ranked.front().name << ")";
  for (const SweepSeries* x : reference_series(series))
    for (const auto& r : x->references)
      if (darkening_violates(r.max_dark, r.darkening_bound))
        attention << (attention.tellp() > 0 ? "; " : "") << "**" << r.name
                  << (series.size() > 1 && !measured_alike(series) ? " (" + x->label + ")" : "")
                  << " over-darkens above its proven bound**";
  if (failed) attention << (attention.tellp() > 0 ? "; " : "") << failed << " LPs failed";
  if (above)
    attention << (attention.tellp() > 0 ? "; " : "") << "**" << above
              << " candidates over-darken above the certified bound**";
  s << ".  \nNeeds attention: "
    << (attention.tellp() > 0 ? attention.str() : std::string("nothing")) << ".\n\n";
  return s.str();
}

}  // namespace

SweepErrorAxis sweep_error_axis(const SweepSeries& series) {
  const std::string target = series.target();
  if (target == "transparency")
    return {"mean |T_ref - T|", "transparent fragments, opacity-weighted"};
  if (target == "scattering") return {"Σ|I - I_ref| / Σ S_max", "view rays"};
  return {"mean |PCF - G|", "receiver fragments"};
}

std::string sweep_report_markdown(const std::vector<SweepSeries>& series,
                                  const std::string& histogram_note) {
  const SweepSeries& main = main_series(series);
  const bool transparency = main.transparency();
  const bool scattering = main.target() == "scattering";
  std::ostringstream md;
  md << "# Sweep report\n\n" << summary_lines(series);
  for (const auto& s : series) {
    auto meta = s.meta;
    md << "- " << s.label << ": `" << s.database << "`, " << s.ranked.size() << " of "
       << meta["planned"] << " planned candidates evaluated (combinations of " << s.size << " from "
       << meta["catalog_size"] << " functions: " << planned_total(s) << "), config hash "
       << meta["config_hash"] << ", shard " << meta["shard"]
       << (meta.count("git_sha") ? ", momentbench git " + meta["git_sha"] : "")
       << (meta.count("missing_shards")
               ? "; **merged without shards " + meta["missing_shards"] + "**"
               : "");
    for (const auto& value : s.own_values) md << "; " << value;
    md << "; "
       << (s.off_default.empty()
               ? std::string(s.own_values.empty() ? "every measurement option at its default"
                                                  : "every other measurement option at its default")
               : (s.own_values.empty() ? "measurement options off their defaults: "
                                       : "other measurement options off their defaults: ") +
                     joined(s.off_default, ", "))
       << "\n";
  }
  auto meta = main.meta;
  // Series whose measurement options differ (report --allow-different) were measured under
  // different settings: each states its own then, none is shown as the others'.
  const auto setting_of = [](const SweepSeries& s) {
    auto m = s.meta;
    return "dataset " + m["dataset"] + "; " + m["settings"];
  };
  const bool shared = std::all_of(series.begin(), series.end(), [&](const SweepSeries& s) {
    return setting_of(s) == setting_of(main);
  });
  if (shared)
    md << "- " << setting_of(main) << "\n";
  else
    for (const auto& s : series) md << "- " << s.label << ": " << setting_of(s) << "\n";
  uint64_t failures = 0, lps = 0;
  for (const auto& s : series)
    for (const auto& r : s.ranked)
      failures += r.infeasible + r.unstable, lps += r.solved + r.infeasible + r.unstable;
  md << "- LPs: " << lps << ", of which infeasible or unstable: " << failures << " ("
     << percent_text(lps ? double(failures) / double(lps) : 0)
     << " %; these fragments count as lit)\n\n"
     << (transparency ? transparency_protocol_text()
         : scattering
             ? scattering_protocol_text()
             : protocol_text(meta["reference"] == "receiver_plane" ? Reference::ReceiverPlane
                                                                   : Reference::Biased))
     << "\n\n";
  const auto oracle_of = [](const ResultRow& r) {
    const TechniqueRow* row = find_technique(r.name, TechniqueFamily::HardShadow);
    return row && row->role == RowRole::BiasFloor;
  };
  const auto oracle_it = std::find_if(main.references.begin(), main.references.end(), oracle_of);
  if (const ResultRow* oracle = oracle_it == main.references.end() ? nullptr : &*oracle_it;
      oracle && meta["reference"] == "receiver_plane")
    md << "**Oracle floor: " << pct(oracle->mean)
       << ".** The error of F_Z(z_f - delta_f) itself against the "
       << "receiver-plane reference: the part of every candidate's error that is the bias's, not "
          "the moments'.\n\n";

  md << "## Histogram\n\n";
  for (const auto& s : series)
    if (s.estimated)
      md << "Series \"" << s.label << "\" was screened (`sweep --screen`): its histogram shows "
         << s.estimated << " screened estimates and " << s.exact
         << " exact means (the candidates whose interval reached the best ones, and the pilot). "
            "Estimates are marked ≈ with their standard error in the tables.\n\n";
  md << histogram_note;
  if (transparency)
    transparency_findings(md, series);
  else if (scattering)
    scattering_findings(md, series);
  else
    findings(md, series);

  const std::string columns = transparency ? "T too high % | T too low %"
                              : scattering ? "too bright % | too dark %"
                                           : "leak % | over-darkening %";
  const std::vector<const SweepSeries*> shown = reference_series(series);
  for (const SweepSeries* s : shown) {
    md << "## Reference techniques on the same dataset"
       << (shown.size() > 1 ? " as " + s->label + " measured them" : "") << "\n\n"
       << "| technique | mean error % | " << columns << " | rank among " << s->label
       << " |\n|---|---|---|---|---|\n";
    std::vector<DarkeningRow> darkening;
    for (const auto& r : s->references) {
      md << "| " << r.name << " | " << percent_text(r.mean) << " | " << percent_text(r.leak)
         << " | " << darkening_text(r.dark, r.max_dark, r.darkening_bound) << " | "
         << (is_hard_reference(r.name) ? std::string("-")
                                       : std::to_string(better_than(*s, r.mean) + 1))
         << " |\n";
      darkening.push_back({r.name, r.dark, r.max_dark, r.darkening_bound, r.darkening_reason});
    }
    md << "\n" << darkening_notes(darkening);
  }

  const std::string header = "| rank | id | functions | mean error % | " + columns +
                             " | LPs solved | failed |\n|---|---|---|---|---|---|---|---|\n";
  for (const auto& s : series) {
    const auto& ranked = s.ranked;
    // Each candidate once: the worst 10 start after the best 50 when there are fewer than 60.
    const size_t best = std::min<size_t>(50, ranked.size());
    const size_t worst_from = std::max(best, ranked.size() > 10 ? ranked.size() - 10 : 0);
    md << "## " << (best == ranked.size() ? "All " : "Best ") << best << " candidates: " << s.label
       << "\n\n"
       << header;
    for (size_t i = 0; i < best; ++i) md << row_line(i + 1, ranked[i], transparency) << "\n";
    if (worst_from < ranked.size()) {
      md << "\n## Worst " << ranked.size() - worst_from << " candidates: " << s.label << "\n\n"
         << header;
      for (size_t i = worst_from; i < ranked.size(); ++i)
        md << row_line(i + 1, ranked[i], transparency) << "\n";
    }
    md << "\n";
  }
  return md.str();
}

}  // namespace mb
