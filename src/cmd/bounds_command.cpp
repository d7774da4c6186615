// `momentbench bounds` (the seed paper's Figure 3): for one kernel, from a dataset texel or given
// depths and weights, the true CDF and the sharp lower bounds of Problem 1 for m = 2, 3, 4 (the
// first m functions of each basis) as functions of z_f; CSV, Markdown and a plot.
#include <cstdio>
#include <sstream>

#include "cmd/command_common.h"
#include "cmd/commands.h"
#include "eval/eval_config.h"
#include "report/bounds_report.h"
#include "scene/dataset.h"
#include "techniques/lp_options.h"
#include "util/error.h"
#include "util/number_text.h"
#include "util/option_record.h"
#include "util/output_dir.h"
#include "util/run_metadata.h"
#include "verify/bound_curves.h"

namespace mb {

namespace {

// bounds' own options; the kernel's, the LP's and the dataset's come from their own tables.
struct BoundsSettings {
  std::vector<double> depths, weights, zf_range;
  std::string view;
  std::vector<int64_t> texel, sizes;
  std::vector<std::string> bases;
  int samples = 0;  // its record holds the default
};

const std::vector<OptionRecord<BoundsSettings>>& bounds_options() {
  static const std::vector<OptionRecord<BoundsSettings>> records{
      {{"bounds.depths", OptionType::NumberList, "[0.2, 0.35, 0.5, 0.8]",
        "The kernel's depths (used when bounds.view is empty)."},
       &BoundsSettings::depths},
      {{"bounds.weights", OptionType::NumberList, "[0.3, 0.2, 0.35, 0.15]",
        "Their weights (normalised; one per depth)."},
       &BoundsSettings::weights},
      {{"bounds.view", OptionType::String, "''",
        "Take the kernel from this view of the dataset instead ('scene/view' or 'view')."},
       &BoundsSettings::view},
      {{"bounds.texel", OptionType::IntegerList, "[0, 0]", "With bounds.view: the texel x, y.", 0,
        16384},
       &BoundsSettings::texel},
      {{"bounds.bases", OptionType::StringList, "[power4, trig4]",
        "Bases, each a named set or 'f1; f2; f3; f4'; the first m functions give the m-series."},
       &BoundsSettings::bases},
      {{"bounds.sizes", OptionType::IntegerList, "[2, 3, 4]", "m values (numbers of functions).", 1,
        7},
       &BoundsSettings::sizes},
      {{"bounds.samples", OptionType::Integer, "401", "z_f values, uniform on bounds.zf_range.", 2,
        1e6},
       &BoundsSettings::samples},
      {{"bounds.zf_range", OptionType::NumberList, "[0, 1]", "z_f from, to."},
       &BoundsSettings::zf_range},
  };
  return records;
}

}  // namespace

std::vector<OptionSpec> bounds_specs() {
  auto specs = dataset_option_specs();
  for (auto& s : shadow_option_specs())
    if (s.name.rfind("kernel.", 0) == 0 || s.name.rfind("lp.", 0) == 0) specs.push_back(s);
  for (auto& s : specs)
    if (s.name == "lp.grid") s.default_value = "1024";  // one kernel: a fine grid costs nothing
  for (auto& s : option_specs(bounds_options())) specs.push_back(s);
  return specs;
}

namespace {

int run_bounds(const CommonOptions& options) {
  auto cmd = CommandRun::begin(bounds_specs(), options);
  if (!cmd) return 0;
  const Config& config = cmd->config();
  const DatasetOptions data = dataset_options_from(config);
  BoundsSettings b;
  read_options(config, bounds_options(), b);
  BoundCurveRequest request;
  request.threads = cmd->threads();
  request.lp = lp_discretization_from(config);
  request.backend = lp_backend_from(config);
  request.bases = b.bases;
  request.sizes.assign(b.sizes.begin(), b.sizes.end());
  request.samples = b.samples;
  if (b.zf_range.size() != 2) throw InputError("bounds.zf_range: expected [from, to]");
  request.zf_lo = b.zf_range[0];
  request.zf_hi = b.zf_range[1];
  const GaussianKernel kernel = kernel_from(config);
  std::string source = "given depths and weights";
  if (!b.view.empty()) {
    source = take_texel_distribution(load_dataset(data.dataset), data.resolution, b.view, b.texel,
                                     kernel, options.quiet, request);
  } else {
    request.depths = b.depths;
    request.weights = b.weights;
  }
  StagedOutputDir& out = cmd->out();
  const BoundCurves curves = compute_bound_curves(request);

  const RunMetadata& meta = cmd->metadata();
  const BoundsReport report =
      render_bounds_report(request, curves, source, {meta.version, meta.git_sha, meta.started_utc});
  write_file_atomically(out / "bounds.csv", report.bounds_csv);
  write_file_atomically(out / "distribution.csv", report.distribution_csv);
  const std::string plot =
      run_plot_script("plot_bounds.py",
                      {"--bounds", (out / "bounds.csv").string(), "--distribution",
                       (out / "distribution.csv").string()},
                      (out / "bounds").string(), "CDF and sharp lower bounds", options.quiet);
  const std::string text = report.markdown + "\n" + plot;
  write_file_atomically(out / "bounds.md", text);
  cmd->finish();
  std::fputs(text.substr(0, text.rfind("\n\n![")).c_str(), stdout);
  std::fputs("\n", stdout);
  return 0;
}

}  // namespace

void register_bounds_command(CLI::App& app, std::function<int()>& action) {
  auto options = std::make_shared<CommonOptions>();
  CLI::App* command = app.add_subcommand(
      "bounds", "CDF and sharp lower bounds for m = 2, 3, 4 of one kernel (Figure 3)");
  add_common_options(*command, *options);
  command->callback([options, &action] { action = [options] { return run_bounds(*options); }; });
}

}  // namespace mb
