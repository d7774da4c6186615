#pragma once
// Sweep results -> the report a researcher reads (docs/design.md §Data flow: report): ranked
// tables, the reference techniques, the paper's findings checked on this data (docs/reference.md
// §3), and CSVs at full precision for the plots. Several databases (e.g. sweeps of 2, 3 and 4
// functions) become series of one report (report/sweep_series.h), compared in one histogram.
#include <string>
#include <vector>

#include "report/sweep_series.h"

namespace mb {

struct SweepReportTables {
  std::string candidates_csv, histogram_csv, series_csv, references_csv;
};
// Candidates' mean errors binned on one common range for all series (the seed paper's Figure 4).
SweepReportTables sweep_report_tables(const std::vector<SweepSeries>& series, int bins);
// What the histogram's axis measures, by the series' target: the error and what it is averaged
// over.
struct SweepErrorAxis {
  std::string error, over;
};
SweepErrorAxis sweep_error_axis(const SweepSeries& series);
// The Markdown report; `histogram_note` is what the plot step produced (an image link or why not).
std::string sweep_report_markdown(const std::vector<SweepSeries>& series,
                                  const std::string& histogram_note);

}  // namespace mb
