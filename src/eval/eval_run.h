#pragma once
// What `eval` runs: its own options (which techniques, which images) declared once as records,
// and the loop of techniques over views that turns shadows into error rows against the fragments'
// reference (docs/reference.md §3). The command adds the outputs; this is reachable from tests.
#include <functional>
#include <string>
#include <vector>

#include "eval/error_stats.h"
#include "eval/evaluation.h"
#include "util/option_record.h"

namespace mb {

// Filled from eval_run_options(), where the defaults are written.
struct EvalRunOptions {
  std::vector<std::string> techniques;
  bool images = false;
  bool camera_images = false;
  double error_scale = 0;  // |reference - G| at the top of the error colour bar
};

const std::vector<OptionRecord<EvalRunOptions>>& eval_run_options();

// One technique on one view ("all" rows sum its views).
struct EvalRow {
  std::string technique, scene, view;
  double light_angle = 0;  // degrees: the view's area light (0: hard); on "all" rows the largest
  ErrorStats stats;
  ErrorStats interior, silhouette;  // the receivers of each ShadowRegion (shadow/fragments.h)
  // Under an area light: the same shadow against pcss_exact's, PCSS with nothing sampled
  // (docs/soft-shadows.md §2), which separates the heuristic's error from the technique's own
  // sampling or moments. Empty on views with a hard light.
  ErrorStats against_pcss;
  double seconds = 0;
  double darkening_bound = 0;  // Technique::darkening_bound
  size_t fallbacks = 0;        // Technique::fallbacks
};

// Adds `row`'s receivers to `total`: its errors (overall and per region), fallbacks and time.
// The darkening bound is the caller's: it depends on what the rows stand for.
void merge_row(EvalRow& total, const EvalRow& row);

struct EvalRows {
  std::vector<EvalRow> overall;   // one per technique, in the order given
  std::vector<EvalRow> per_view;  // technique-major, views in order
};

// Called with each technique's shadow on each view, in order (where images are written).
using ViewShadowSink = std::function<void(const std::string& technique, const ViewData& view,
                                          const std::vector<double>& shadow)>;

// Every technique on every view, with a progress bar per technique unless `quiet`.
EvalRows evaluate_techniques(const std::vector<ViewData>& views,
                             const std::vector<std::string>& techniques,
                             const EvalSettings& settings, bool quiet,
                             const ViewShadowSink& on_view = {});

}  // namespace mb
