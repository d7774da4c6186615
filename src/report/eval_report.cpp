#include "report/eval_report.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <map>
#include <sstream>

#include "report/darkening.h"
#include "techniques/registry.h"
#include "util/number_text.h"

namespace mb {

namespace {

std::string number(double v) {
  return round_trip(v);
}

std::string table_row(const EvalRow& r) {
  std::ostringstream s;
  s << "| " << r.technique << " | " << r.scene << (r.view.empty() ? "" : "/" + r.view) << " | "
    << r.stats.count << " | " << percent_text(r.stats.mean()) << " | "
    << percent_text(r.stats.leak()) << " | "
    << darkening_text(r.stats.dark(), r.stats.max_dark, r.darkening_bound) << " | "
    << format_number(r.stats.max, "%.6g") << " | " << percent_text(r.stats.share_over_tenth())
    << " | " << r.stats.failures << " |";
  return s.str();
}

// docs/reference.md §3 "Where the error sits": interior against silhouette receivers.
std::string regions_section(const std::vector<EvalRow>& overall) {
  if (overall.empty()) return "";
  const EvalRow& first = overall.front();
  std::ostringstream s;
  s << "## Where the error sits\n\n"
    << "Interior receivers have a surface in front of z_f - delta_f in every tap of their kernel "
       "(an umbra, or the inside of a translucent occluder's shadow): "
    << first.interior.count << " receivers. Silhouette receivers have one in some taps (the "
    << "kernel straddles an occluder's edge): " << first.silhouette.count << ". The other "
    << first.stats.count - first.interior.count - first.silhouette.count
    << " are unshadowed (the reference is 0). Mean error per region; the last column is the "
       "share of the technique's summed error that lies at silhouettes (regions.csv has every "
       "view).\n\n"
    << "| technique | interior mean error % | interior leak % | silhouette mean error % | "
       "silhouette leak % | error at silhouettes % |\n|---|---|---|---|---|---|\n";
  for (const auto& r : overall) {
    const double total = r.stats.sum_abs;  // "-" where it is only rounding
    s << "| " << r.technique << " | " << percent_text(r.interior.mean()) << " | "
      << percent_text(r.interior.leak()) << " | " << percent_text(r.silhouette.mean()) << " | "
      << percent_text(r.silhouette.leak()) << " | "
      << (r.stats.mean() > 1e-12 ? percent_text(r.silhouette.sum_abs / total) : "-") << " |\n";
  }
  return s.str() + "\n";
}

std::string regions_csv(const std::vector<EvalRow>& overall, const std::vector<EvalRow>& per_view) {
  std::ostringstream csv;
  csv << "technique,scene,view,region,receivers,mean_error,leak,over_darkening\n";
  for (const auto* rows : {&overall, &per_view})
    for (const auto& r : *rows)
      for (const auto& [region, stats] :
           {std::pair{"interior", &r.interior}, std::pair{"silhouette", &r.silhouette}})
        csv << '"' << r.technique << "\"," << r.scene << "," << (r.view.empty() ? "all" : r.view)
            << "," << region << "," << stats->count << "," << number(stats->mean()) << ","
            << number(stats->leak()) << "," << number(stats->dark()) << "\n";
  return csv.str();
}

// docs/soft-shadows.md §2: under area lights, every technique against pcss_exact, PCSS with
// nothing sampled; what remains of a technique's error against the area light beyond this is the
// PCSS heuristic's. Rows: overall, then per angle.
std::string against_pcss_section(const std::vector<EvalRow>& overall,
                                 const std::vector<EvalRow>& per_angle) {
  std::ostringstream s;
  s << "## Against exact PCSS\n\n"
    << "Each technique's shadow against `"
    << role_name(TechniqueFamily::SoftShadow, RowRole::ExactReference)
    << "`'s on the same receivers (pcss_errors.csv has "
       "every view): the part of its error that is its own sampling, table or moments, not the "
       "PCSS heuristic's (docs/soft-shadows.md §2). Lighter: the technique shows more light.\n\n"
    << "| technique | views | receivers | mean difference % | lighter % | darker % | max |\n"
    << "|---|---|---|---|---|---|---|\n";
  for (const auto* rows : {&overall, &per_angle})
    for (const auto& r : *rows) {
      const ErrorStats& e = r.against_pcss;
      s << "| " << r.technique << " | " << r.scene << (r.view.empty() ? "" : "/" + r.view) << " | "
        << e.count << " | " << percent_text(e.mean()) << " | " << percent_text(e.leak()) << " | "
        << percent_text(e.dark()) << " | " << format_number(e.max, "%.6g") << " |\n";
    }
  return s.str() + "\n";
}

std::string against_pcss_csv(const std::vector<const std::vector<EvalRow>*>& groups) {
  std::ostringstream csv;
  csv << "technique,scene,view,receivers,mean_error,leak,over_darkening,max_error\n";
  for (const auto* rows : groups)
    for (const auto& r : *rows) {
      const ErrorStats& e = r.against_pcss;
      if (e.count == 0) continue;
      csv << '"' << r.technique << "\"," << r.scene << "," << (r.view.empty() ? "all" : r.view)
          << "," << e.count << "," << number(e.mean()) << "," << number(e.leak()) << ","
          << number(e.dark()) << "," << number(e.max) << "\n";
    }
  return csv.str();
}

// Three lines before the tables: what ran, the headline numbers, what needs attention (failed
// fragments, an exact technique above its proven bound).
// Under area lights, each technique's views merged per light angle (scene "all", view "<a>deg"):
// a penumbra's error grows with the angle, and one mean over all angles would hide how.
std::vector<EvalRow> per_angle_rows(const std::vector<EvalRow>& overall,
                                    const std::vector<EvalRow>& per_view) {
  std::vector<EvalRow> rows;
  bool soft = false;
  for (const auto& r : per_view) soft |= r.light_angle > 0;
  if (!soft) return rows;
  for (const auto& total : overall) {
    std::map<double, EvalRow> by_angle;
    for (const auto& r : per_view) {
      if (r.technique != total.technique) continue;
      auto [it, fresh] = by_angle.try_emplace(r.light_angle);
      EvalRow& row = it->second;
      if (fresh) {
        row.technique = total.technique, row.scene = "all";
        row.view = round_trip(r.light_angle) + "deg";
        row.light_angle = r.light_angle, row.darkening_bound = r.darkening_bound;
      }
      row.darkening_bound = std::max(row.darkening_bound, r.darkening_bound);
      merge_row(row, r);
    }
    for (auto& [angle, row] : by_angle) rows.push_back(std::move(row));
  }
  return rows;
}

std::string summary_lines(const EvalReportContext& ctx, const std::vector<EvalRow>& overall) {
  std::ostringstream s, headline, attention;
  s << "**Summary.** " << overall.size() << " techniques on dataset " << ctx.dataset << ": "
    << ctx.views << " views, " << ctx.receivers << " receivers, reference "
    << reference_name(ctx.reference) << ".  \n";
  const EvalRow* lowest = nullptr;
  for (const auto& r : overall) {
    headline << (headline.tellp() > 0 ? ", " : "") << r.technique << " "
             << percent_text(r.stats.mean()) << " %";
    if (technique_role(r.technique) != RowRole::Reference &&
        technique_role(r.technique) != RowRole::BiasFloor &&
        (!lowest || r.stats.mean() < lowest->stats.mean()))
      lowest = &r;
  }
  s << "Mean error: " << headline.str();
  if (lowest) s << " (lowest: " << lowest->technique << ")";
  s << ".  \nNeeds attention: ";
  for (const auto& r : overall) {
    if (r.stats.failures)
      attention << (attention.tellp() > 0 ? "; " : "") << r.technique << ": " << r.stats.failures
                << " fragments failed";
    if (darkening_violates(r.stats.max_dark, r.darkening_bound))
      attention << (attention.tellp() > 0 ? "; " : "") << "**" << r.technique
                << " over-darkens above its proven bound**";
  }
  s << (attention.tellp() > 0 ? attention.str() : std::string("nothing")) << ".\n\n";
  return s.str();
}

}  // namespace

std::string file_stem(const std::string& name) {
  std::string out;
  for (char c : name)
    out += std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '-' ? c : '_';
  return out;
}

std::string histogram_csv(const ErrorStats& stats) {
  std::ostringstream histogram;
  histogram << "error_lo,error_hi,fragments\n";
  for (int b = 0; b < ErrorStats::kHistogramBins; ++b)
    histogram << number(double(b) / ErrorStats::kHistogramBins) << ","
              << number(double(b + 1) / ErrorStats::kHistogramBins) << "," << stats.histogram[b]
              << "\n";
  return histogram.str();
}

EvalReport render_eval_report(const EvalReportContext& ctx, const std::vector<EvalRow>& overall,
                              const std::vector<EvalRow>& per_view,
                              const std::map<std::string, std::string>& darkening_reason) {
  auto reason_of = [&](const std::string& technique) {
    auto it = darkening_reason.find(technique);
    return it == darkening_reason.end() ? std::string() : it->second;
  };
  const std::string header =
      "| technique | views | receivers | mean error % | leak % | over-darkening % | max error | "
      "share > 0.1 % | "
      "failures |\n|---|---|---|---|---|---|---|---|---|\n";
  std::ostringstream table, report, csv;
  table << header;
  for (const auto& r : overall) table << table_row(r) << "\n";
  report << "# Shadow evaluation of dataset " << ctx.dataset << "\n\n"
         << "Made by momentbench " << ctx.version << " (git " << ctx.git_sha << "), "
         << ctx.compiler << ", " << ctx.threads << " threads, " << ctx.started << ".\n\n"
         << summary_lines(ctx, overall) << "- " << ctx.settings_text << "\n"
         << "- " << ctx.views << " views, " << ctx.receivers
         << " receiver fragments (every light-facing fragment of "
         << "every layer, docs/reference.md §3)\n";
  for (const auto& line : ctx.non_default) report << "- option " << line << "\n";
  report << "\n" << protocol_text(ctx.reference, ctx.area_light) << "\n\n";
  for (const auto& r : overall)
    if (technique_role(r.technique) == RowRole::BiasFloor &&
        ctx.reference == Reference::ReceiverPlane)
      report << "**Oracle floor: " << percent_text(r.stats.mean())
             << " %.** The error of F_Z(z_f - delta_f) itself against the receiver-plane "
                "reference: the part of every "
                "technique's error that is the bias's, not the moments'.\n\n";
  std::vector<DarkeningRow> darkening;
  for (const auto& r : overall)
    darkening.push_back(
        {r.technique, r.stats.dark(), r.stats.max_dark, r.darkening_bound, reason_of(r.technique)});
  report << darkening_notes(darkening) << "## All views\n\n"
         << table.str() << "\n"
         << regions_section(overall);
  const std::vector<EvalRow> per_angle = per_angle_rows(overall, per_view);
  if (!per_angle.empty()) {
    report << "## Per light angle\n\n" << header;
    for (const auto& r : per_angle) report << table_row(r) << "\n";
    report << "\n" << against_pcss_section(overall, per_angle);
  }
  report << "## Per view\n\n" << header;
  for (const auto& r : per_view) report << table_row(r) << "\n";
  report << (ctx.sections.empty() ? "" : "\n" + ctx.sections);
  for (const auto& r : overall)
    if (r.stats.failures)
      report << "\n**" << r.technique << "**: " << r.stats.failures << " fragments failed; "
             << (technique_solves_lp(r.technique)
                     ? "their LPs had no certified answer (shown lit); another lp.grid or "
                       "lp.backend may solve them.\n"
                     : "raise the technique's alpha, or the LP grid, and re-run.\n");
  for (const auto& r : overall)
    if (r.fallbacks)
      report << "\n**" << r.technique << "**: " << r.fallbacks << " of " << r.stats.count
             << " fragments (" << percent_text(double(r.fallbacks) / double(r.stats.count))
             << " %) were classified as failing and answered by the 2x2 custom PCF (seed 002 "
                "§3.3).\n";
  if (ctx.images)
    report << "\nImages (images/): `<scene>_<view>_<technique>_shadow.exr` holds G of layer-0 "
              "receivers, the PNG shows "
              "1 - G (white = lit; dark blue = no layer-0 receiver); `_error.png` shows |PCF - G| "
              "on a colour bar from "
              "0 to "
           << number(ctx.error_scale) << ".\n";
  csv << "technique,scene,view,receivers,mean_error,leak,over_darkening,max_over_darkening,max_"
         "error,share_over_0.1,"
         "failures,reference\n";
  for (const auto* rows : {&overall, &per_angle, &per_view})
    for (const auto& r : *rows)
      csv << '"' << r.technique << "\"," << r.scene << "," << (r.view.empty() ? "all" : r.view)
          << "," << r.stats.count << "," << number(r.stats.mean()) << "," << number(r.stats.leak())
          << "," << number(r.stats.dark()) << "," << number(r.stats.max_dark) << ","
          << number(r.stats.max) << "," << number(r.stats.share_over_tenth()) << ","
          << r.stats.failures << "," << reference_name(ctx.reference) << "\n";
  return {table.str(), report.str(), csv.str(), regions_csv(overall, per_view),
          per_angle.empty() ? std::string() : against_pcss_csv({&overall, &per_angle, &per_view})};
}

}  // namespace mb
