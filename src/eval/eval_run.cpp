#include "eval/eval_run.h"

#include <algorithm>
#include <chrono>
#include <limits>
#include <stdexcept>

#include "techniques/registry.h"
#include "techniques/soft/soft_technique.h"

namespace mb {

// `techniques` chooses the rows, not their numbers; the images and their colour scales change no
// measured number (OptionEffect, docs/sweeps.md "Identity").
const std::vector<OptionRecord<EvalRunOptions>>& eval_run_options() {
  static const std::vector<OptionRecord<EvalRunOptions>> records{
      {selects_runs(
           {"techniques", OptionType::StringList, default_techniques(TechniqueFamily::HardShadow),
            "Techniques to evaluate: the hard-shadow rows of `momentbench options techniques` "
            "(closed "
            "forms, pcf, or lp:<basis>, e.g. lp:power4, lp:trig4); under an area light also its "
            "soft-shadow rows (docs/soft-shadows.md)."}),
       &EvalRunOptions::techniques},
      {measures_nothing({"images", OptionType::Boolean, "true",
                         "Write shadow and error images per view and technique."}),
       &EvalRunOptions::images},
      {measures_nothing(
           {"camera_images", OptionType::Boolean, "false",
            "For every camera a scene names and each of its light views: the camera's image with "
            "each "
            "technique's shadow, its difference from PCF, and one contact sheet (cameras/)."}),
       &EvalRunOptions::camera_images},
      {measures_nothing({"error_scale", OptionType::Number, "0.5",
                         "|PCF - G| at the top of the error colour bar.", 1e-6, 1}),
       &EvalRunOptions::error_scale},
  };
  return records;
}

namespace {

size_t receiver_count(const std::vector<ViewData>& views) {
  size_t receivers = 0;
  for (const auto& v : views) receivers += v.fragments.size();
  return receivers;
}

// The row's error split by where the receivers lie (ShadowRegion), in fragment order.
void add_regions(const Fragments& f, const std::vector<double>& shadow, EvalRow& row) {
  for (size_t k = 0; k < f.size(); ++k) {
    const ShadowRegion region = shadow_region(f, k);
    if (region == ShadowRegion::Interior) row.interior.add(f.pcf[k], shadow[k]);
    if (region == ShadowRegion::Silhouette) row.silhouette.add(f.pcf[k], shadow[k]);
  }
}

// The soft-shadow row that is every soft row's second reference (RowRole::ExactReference).
const TechniqueRow& exact_soft_row() {
  for (const TechniqueRow* row : family_rows(TechniqueFamily::SoftShadow))
    if (row->role == RowRole::ExactReference) return *row;
  throw std::logic_error("no soft-shadow row is the exact reference");
}

// The exact soft row on every view under an area light (empty on the others), with the time it
// took: the second reference of soft techniques (EvalRow::against_pcss), and that row's own when
// asked for.
struct ExactPcss {
  TechniqueResult result;
  double seconds = 0;
};

std::vector<ExactPcss> exact_pcss(const std::vector<ViewData>& views,
                                  const EvalSettings& settings) {
  using Clock = std::chrono::steady_clock;
  std::vector<ExactPcss> out(views.size());
  for (size_t v = 0; v < views.size(); ++v) {
    const ViewData& view = views[v];
    if (!(view.soft.angle_deg > 0)) continue;
    const auto start = Clock::now();
    SoftResult soft =
        soft_shadow(exact_soft_row().name, view.map, view.fragments, view.soft, settings.kernel,
                    settings.bias, settings.soft, settings.threads, settings.technique);
    out[v].result.shadow = std::move(soft.shadow);
    out[v].result.failures = soft.failures;
    out[v].seconds = std::chrono::duration<double>(Clock::now() - start).count();
  }
  return out;
}

}  // namespace

void merge_row(EvalRow& total, const EvalRow& row) {
  total.stats.merge(row.stats);
  total.interior.merge(row.interior);
  total.silhouette.merge(row.silhouette);
  total.against_pcss.merge(row.against_pcss);
  total.fallbacks += row.fallbacks;
  total.seconds += row.seconds;
}

EvalRows evaluate_techniques(const std::vector<ViewData>& views,
                             const std::vector<std::string>& techniques,
                             const EvalSettings& settings, bool quiet,
                             const ViewShadowSink& on_view) {
  using Clock = std::chrono::steady_clock;
  const size_t receivers = receiver_count(views);
  const std::vector<ExactPcss> pcss = exact_pcss(views, settings);
  EvalRows rows;
  for (const auto& name : techniques) {
    ProgressBar bar(name, receivers, quiet);
    EvalRow total;
    total.technique = name;
    total.scene = "all";
    total.darkening_bound = technique_darkening_bound(name, settings);
    for (const auto& view : views) {
      const auto start = Clock::now();
      const ExactPcss& exact = pcss[size_t(&view - views.data())];
      const bool known = name == exact_soft_row().name && !exact.result.shadow.empty();
      if (known) bar.advance(view.fragments.size());
      TechniqueResult result =
          known ? exact.result : evaluate_technique(view, name, settings, &bar);
      EvalRow row = total;
      row.scene = view.scene;
      row.view = view.view;
      row.light_angle = view.soft.angle_deg;
      total.light_angle = std::max(total.light_angle, row.light_angle);
      row.stats = ErrorStats();
      row.interior = row.silhouette = row.against_pcss = ErrorStats();
      row.stats.add_all(view.fragments.pcf, result.shadow);
      if (!exact.result.shadow.empty())
        row.against_pcss.add_all(exact.result.shadow, result.shadow);
      add_regions(view.fragments, result.shadow, row);
      row.stats.failures = result.failures;
      // A technique's proven bound is on G - F_Z (docs/reference.md §3); an area light's shadow is
      // no F_Z, and every technique may darken past it (docs/soft-shadows.md §1).
      if (view.soft.angle_deg > 0) row.darkening_bound = std::numeric_limits<double>::infinity();
      total.darkening_bound = std::max(total.darkening_bound, row.darkening_bound);
      row.fallbacks = result.fallbacks;
      row.seconds = std::chrono::duration<double>(Clock::now() - start).count() +
                    (known ? exact.seconds : 0.0);
      merge_row(total, row);
      if (on_view) on_view(name, view, result.shadow);
      rows.per_view.push_back(std::move(row));
    }
    bar.finish();
    rows.overall.push_back(std::move(total));
  }
  return rows;
}

}  // namespace mb
