// `momentbench storage`: a basis's quantization transform (docs/reference.md §8; seed 000 §4.3)
// with its entropy gain over the canonical storage, the hull volumes and the certified upper
// bounds of the gain, as JSON.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <nlohmann/json.hpp>
#include <optional>

#include "cmd/command_common.h"
#include "cmd/commands.h"
#include "moments/quantization_transform.h"
#include "util/error.h"
#include "util/option_record.h"

namespace mb {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr int kMaxStorageFunctions = 8;

struct StorageSettings {
  std::vector<std::string> basis;
  std::string transform;
  int samples = 0;  // its record holds the default
};

const std::vector<OptionRecord<StorageSettings>>& storage_options() {
  static const std::vector<OptionRecord<StorageSettings>> records{
      {{"storage.basis", OptionType::StringList, "[z, z^2, z^3]",
        "The basis on [0, 1]: catalog functions, named sets (power4, ...) or a sweep's candidate "
        "(\"z; z^2; cos(pi z); exp(-z^2)\"); expressions have no certified range and are refused."},
       &StorageSettings::basis},
      {{"storage.transform",
        OptionType::String,
        "optimized",
        "canonical (each function scaled to its range), seed (seed 000's theta_2 / theta_4) or "
        "optimized (the search).",
        -kInf,
        kInf,
        {"canonical", "seed", "optimized"}},
       &StorageSettings::transform},
      {{"storage.curve_samples", OptionType::Integer, "0",
        "Also print the curve b(z) and A b(z) + c at this many depths (0: none; for plots).", 0,
        100000},
       &StorageSettings::samples},
  };
  return records;
}

nlohmann::ordered_json matrix_json(const Eigen::MatrixXd& M) {
  nlohmann::ordered_json rows = nlohmann::ordered_json::array();
  for (Eigen::Index i = 0; i < M.rows(); ++i) {
    nlohmann::ordered_json row = nlohmann::ordered_json::array();
    for (Eigen::Index j = 0; j < M.cols(); ++j) row.push_back(M(i, j));
    rows.push_back(row);
  }
  return rows;
}

int run_storage(const CLI::App& command, const CommonOptions& common,
                const StorageSettings& flags) {
  auto cmd = CommandRun::begin(
      storage_specs(), common, command,
      {{"--basis", "storage.basis", [&] { return YAML::Node(flags.basis); }},
       {"--transform", "storage.transform", [&] { return YAML::Node(flags.transform); }},
       {"--curve-samples", "storage.curve_samples", [&] { return YAML::Node(flags.samples); }}});
  if (!cmd) return 0;
  StorageSettings o;
  read_options(cmd->config(), storage_options(), o);
  const Basis basis = Basis::parse(o.basis);
  // The search's starts and the hulls' sample counts grow with m (docs/reference.md §8); eight
  // moments are the most any technique here stores (MBOIT's power8 and trig4).
  if (basis.size() > size_t(kMaxStorageFunctions))
    throw InputError("storage.basis: " + std::to_string(basis.size()) +
                     " functions; expected at most " + std::to_string(kMaxStorageFunctions) +
                     " (the most moments a technique stores, docs/reference.md §8)");
  check_quantizable(basis);
  const auto start = std::chrono::steady_clock::now();
  nlohmann::ordered_json search;
  QuantizationTransform t;
  if (o.transform == "optimized") {
    const OptimizedTransform found = optimize_transform(basis);
    t = found.transform;
    search = {{"starts", found.starts}, {"exhaustive", found.exhaustive}};
  } else {
    t = quantization_transform(basis, o.transform);
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  // The bounds are a certificate beside the transform: where Qhull cannot take a hull the
  // transform and its gain are still printed, with the reason in place of the bounds.
  std::optional<GainBounds> bounds;
  std::string bounds_error;
  try {
    bounds = gain_bounds(basis);
  } catch (const InputError& e) {
    bounds_error = e.what();
  }
  const QuantizationTransform canonical = quantization_transform(basis, "canonical");
  const double det = std::abs(t.A.determinant()),
               canonical_det = std::abs(canonical.A.determinant());
  nlohmann::ordered_json out = {
      {"basis", basis.names()},
      {"kind", o.transform},
      {"transform", {{"A", matrix_json(t.A)}, {"c", std::vector<double>(t.c.begin(), t.c.end())}}},
      {"entropy_gain_bits", entropy_gain_bits(basis, t)},
      {"log2_det_A", std::log2(det)},
      {"admissibility_violation", admissibility_violation(basis, t)},
      {"hull_volume", nullptr},
      {"canonical_hull_volume", nullptr},
      {"transformed_hull_volume", nullptr},
      {"volume_ratio", det / canonical_det},
      {"bounds", {{"error", bounds_error}}},
      {"seconds", seconds}};
  if (bounds) {
    out["hull_volume"] = bounds->hull_volume;
    out["canonical_hull_volume"] = canonical_det * bounds->hull_volume;
    out["transformed_hull_volume"] = det * bounds->hull_volume;
    out["bounds"] = {{"hull_bits", bounds->hull_bound_bits},
                     {"difference_body_bits", bounds->difference_bound_bits},
                     {"best_bits", bounds->best_bits()},
                     {"difference_body_volume", bounds->difference_volume},
                     {"note",
                      "certified upper bounds of entropy_gain_bits: the volumes are those of "
                      "hulls of sampled points (Qhull), lower bounds of the true volumes"}};
    // Two functions: both row angles searched exhaustively, the optimum certified within the
    // grid's slack (moments/angle_grid_bound.cpp).
    if (basis.size() == 2) {
      out["bounds"]["angle_grid_bits"] = bounds->angle_grid_bits;
      out["bounds"]["angle_grid_note"] =
          "every pair of row angles: a grid of " + std::to_string(kAngleGridAngles) +
          " on [0, pi) for each row, each cell's widths bounded from below by its centre's "
          "attained extrema";
    }
  }
  if (!search.is_null()) out["search"] = search;
  if (o.samples > 0) {
    nlohmann::ordered_json z = nlohmann::ordered_json::array(), b = nlohmann::ordered_json::array(),
                           q = nlohmann::ordered_json::array();
    Eigen::VectorXd v(basis.size());
    for (int k = 0; k < o.samples; ++k) {
      const double x = o.samples == 1 ? 0.0 : double(k) / (o.samples - 1);
      for (size_t j = 0; j < basis.size(); ++j) v(Eigen::Index(j)) = basis[j](x);
      const Eigen::VectorXd s = t.A * v + t.c;
      z.push_back(x);
      b.push_back(std::vector<double>(v.begin(), v.end()));
      q.push_back(std::vector<double>(s.begin(), s.end()));
    }
    out["curve"] = {{"z", z}, {"b", b}, {"stored", q}};
  }
  std::printf("%s\n", out.dump(2).c_str());
  return 0;
}

}  // namespace

std::vector<OptionSpec> storage_specs() {
  return option_specs(storage_options());
}

void register_storage_command(CLI::App& app, std::function<int()>& action) {
  auto flags = std::make_shared<StorageSettings>();
  auto common = std::make_shared<CommonOptions>();
  CLI::App* c = app.add_subcommand(
      "storage", "A basis's quantization transform, its entropy gain and certified bounds (JSON)");
  add_common_options(*c, *common, /*has_output=*/false);
  c->add_option("--basis", flags->basis, "= --set storage.basis=[...]")->delimiter(',');
  c->add_option("--transform", flags->transform, "= --set storage.transform=KIND");
  c->add_option("--curve-samples", flags->samples, "= --set storage.curve_samples=N");
  c->callback([flags, common, c, &action] {
    action = [flags, common, c] { return run_storage(*c, *common, *flags); };
  });
}

}  // namespace mb
