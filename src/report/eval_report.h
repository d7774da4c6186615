#pragma once
// The report of `momentbench eval`: report.md (the error table of every technique against PCF,
// overall and per view, with the protocol and over-darkening notes), errors.csv (full precision)
// and each technique's error histogram CSV.
#include <map>
#include <string>
#include <vector>

#include "eval/error_stats.h"
#include "eval/eval_run.h"
#include "shadow/fragments.h"

namespace mb {

// What the report's header states about the run.
struct EvalReportContext {
  std::string dataset, version, git_sha, compiler, started, settings_text;
  int threads = 0;
  Reference reference = Reference::Biased;
  bool area_light = false;  // some view is lit by an area light: its reference is that light's
  size_t views = 0, receivers = 0;
  std::vector<std::string> non_default;  // "key: value" of the options that differ
  bool images = false;
  double error_scale = 0;
  std::string sections;  // markdown appended after the per-view table (e.g. the blocker audit)
};

struct EvalReport {
  std::string table;  // the overall table (stdout)
  std::string markdown, errors_csv;
  std::string regions_csv;  // each row's error split by ShadowRegion (regions.csv)
  // Under area lights, each row's shadow against pcss_exact's (pcss_errors.csv); else empty.
  std::string pcss_csv;
};

EvalReport render_eval_report(const EvalReportContext& ctx, const std::vector<EvalRow>& overall,
                              const std::vector<EvalRow>& per_view,
                              const std::map<std::string, std::string>& darkening_reason);

// A technique's error histogram (ErrorStats::kHistogramBins bins on [0, 1]) as CSV.
std::string histogram_csv(const ErrorStats& stats);

// A technique name as a file name: [A-Za-z0-9._-] kept, everything else '_' (lp:z;z^2 -> lp_z_z_2).
std::string file_stem(const std::string& name);

}  // namespace mb
