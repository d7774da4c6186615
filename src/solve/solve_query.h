#pragma once
// Problem 1 queries (docs/reference.md §1-2): one instance, or a JSON Lines batch of them, answered
// as JSON by an LP backend on a grid or the continuous interval, or by a closed form. `solve`
// parses its flags into SolveSettings and calls these; tests call them directly.
#include <istream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "util/config.h"

namespace mb {

// solve's settings; a default-made one holds its option records' defaults (written there only).
struct SolveSettings {
  SolveSettings();
  std::vector<std::string> basis;
  std::vector<double> interval;
  int grid;
  std::vector<double> moments, points;
  // A distribution instead of moments (docs/reference.md §2): its moments are computed from it,
  // for a power basis in its own local coordinates (continuous/local_power.h).
  std::vector<double> depths, weights;
  double zf;
  std::string backend;
  std::string technique;  // a closed form instead of the LP
  double alpha;           // its moment bias (< 0: the technique's default)
  std::string input, output;
  bool check, quantize;
  std::string discretization;
  double moment_tolerance;  // ulps of each moment (docs/reference.md §2)
};

// solve's option table, and the settings it declares read from a resolved config (an instance
// beside `input` is an InputError).
std::vector<OptionSpec> solve_option_specs();
SolveSettings solve_settings_from(const Config& config);

// The instance of `settings` (its basis, moments and z_f, or its technique): the answer object with
// `status`, `G`, `support`, and for the continuous method `lower`, `bracket`, `proven`.
nlohmann::json solve_instance(const SolveSettings& settings);

struct SolveBatch {
  std::string lines;  // one JSON answer per non-blank input line, in input order
  int failures = 0;   // answers that are not optimal, and malformed lines
};
// Every line of `in` as a query object (keys id, basis, interval, grid, discretization, moments or
// depths and weights, points, zf, technique, alpha, moment_tolerance; the rest from `settings`). A
// malformed line is answered {"status": "error", "message": "<source>:<line>: ..."} (and printed to
// stderr when `report_errors`) without stopping the others.
SolveBatch solve_batch(const SolveSettings& settings, std::istream& in, const std::string& source,
                       bool report_errors = true);

}  // namespace mb
