// `momentbench solve`: Problem 1 instances (REFERENCE.md §1-2) with a chosen LP backend, one from
// flags or a JSON Lines batch; `--check` runs the independent KKT checker on every answer.
#include <cstdio>
#include <fstream>
#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>

#include "cmd/command_common.h"
#include "cmd/commands.h"
#include "eval/technique.h"
#include "lp/kkt_checker.h"
#include "lp/problem.h"
#include "lp/solution.h"
#include "util/error.h"
#include "util/output_dir.h"

namespace mb {

namespace {

struct SolveOptions {
  std::vector<std::string> basis{"power4"};
  std::vector<double> interval{0, 1};
  int grid = 1024;
  std::vector<double> moments, points;
  double zf = 0.5;
  std::string backend = "fast";
  std::string technique;  // a closed form instead of the LP
  double alpha = -1;      // its moment bias (< 0: the technique's default)
  std::string input, output;
  bool check = false, quantize = false;
};

using nlohmann::json;

// The problem factory of the last LP line's basis and discretisation: a batch's lines mostly share
// them, and building one (the basis checked, the grid orthonormalised in long double: ~0.15 ms at
// 256 points, ~1.7 ms at 1024 with eight functions) costs more than solving the LP.
class FactoryCache {
 public:
  const lp::ProblemFactory& get(const std::vector<std::string>& basis_names, const lp::Discretization& disc) {
    if (!factory_ || basis_names != names_ || disc != disc_) {
      factory_.reset();  // a line that fails here must not leave the previous one's factory behind
      Basis basis = Basis::parse(basis_names);
      basis.check_independent(disc.lo, disc.hi);
      factory_ = std::make_unique<lp::ProblemFactory>(basis, disc);
      names_ = basis_names;
      disc_ = disc;
    }
    return *factory_;
  }

 private:
  std::vector<std::string> names_;
  lp::Discretization disc_;
  std::unique_ptr<lp::ProblemFactory> factory_;
};

json solve_one(lp::Backend& backend, FactoryCache& factories, const std::vector<std::string>& basis_names,
               const lp::Discretization& disc, const std::vector<double>& moments, double zf,
               const std::vector<double>& points, bool check) {
  lp::Problem problem = factories.get(basis_names, disc).from_moments(moments, zf, points);
  lp::Solution s = backend.solve(problem);
  json out;
  if (s.call == lp::CallStatus::Failed) {
    out["status"] = "call_failed";
    out["message"] = s.call_message;
    return out;
  }
  out["status"] = lp::to_string(s.status);
  if (s.status == lp::ProblemStatus::Optimal) {
    out["G"] = s.G;
    json support = json::array();
    for (size_t k = 0; k < s.support.size(); ++k) support.push_back({problem.point(s.support[k]), s.weights[k]});
    out["support"] = support;
  }
  out["iterations"] = s.iterations;
  out["backend"] = backend.name();
  if (check && s.status == lp::ProblemStatus::Optimal) out["kkt"] = lp::check_kkt(problem, s).describe();
  return out;
}

// A closed-form technique (REFERENCE.md §4) on the given moments, e.g. to re-run a worst case of
// `verify`; alpha >= 0 replaces every solver's default moment bias.
json solve_closed_form(const std::string& name, double alpha, const std::vector<double>& moments, double zf) {
  if (name == "pcf" || name.rfind("lp:", 0) == 0)
    throw InputError("technique: '" + name + "' is not a closed form of the moments (use basis for an LP)");
  TechniqueParams params;
  if (alpha >= 0)
    for (double* a : {&params.hamburger4_alpha, &params.hamburger4_float_alpha, &params.hamburger4_16bit_alpha,
                      &params.hausdorff4_alpha, &params.hamburger6_alpha, &params.tmsm_alpha, &params.tmsm_float_alpha})
      *a = alpha;
  auto technique = make_technique(name, params);
  if (moments.size() != technique->basis().size())
    throw InputError("moments: technique '" + name + "' reads " + std::to_string(technique->basis().size()) +
                     " moments, got " + std::to_string(moments.size()));
  FragmentInput in;
  in.moments = moments;
  in.zf = zf;
  const double g = technique->shadow(in);
  json out;
  out["status"] = technique->failures() ? "numerically_unstable" : "optimal";
  if (!technique->failures()) out["G"] = g;
  out["backend"] = "closed_form";
  out["technique"] = name;
  return out;
}

int run_solve(const SolveOptions& o) {
  auto backend = lp::make_backend(o.backend);
  if (o.interval.size() != 2) throw InputError("--interval: expected lo,hi");
  lp::Discretization disc{o.interval[0], o.interval[1], o.grid, o.quantize};
  if (o.input.empty()) {
    FactoryCache factories;
    json r = !o.technique.empty() ? solve_closed_form(o.technique, o.alpha, o.moments, o.zf)
                                  : solve_one(*backend, factories, o.basis, disc, o.moments, o.zf, o.points, o.check);
    std::printf("%s\n", r.dump(2).c_str());
    return r["status"] == "optimal" ? 0 : 3;
  }
  std::ifstream in(o.input);
  if (!in) throw InputError(o.input + ": cannot open");
  std::ostringstream results;
  std::string line;
  int number = 0, failures = 0;
  FactoryCache factories;
  while (std::getline(in, line)) {
    ++number;
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    json out;
    try {
      json q = json::parse(line);
      out["id"] = q.value("id", json(number));
      if (q.contains("technique")) {
        out.update(solve_closed_form(q.at("technique").get<std::string>(), q.value("alpha", -1.0),
                                     q.at("moments").get<std::vector<double>>(), q.at("zf").get<double>()));
      } else {
        std::vector<std::string> basis = q.at("basis").get<std::vector<std::string>>();
        std::vector<double> interval = q.value("interval", std::vector<double>{0, 1});
        if (interval.size() != 2) throw InputError("interval: expected [lo, hi]");
        lp::Discretization d{interval[0], interval[1], q.value("grid", o.grid), o.quantize};
        out.update(solve_one(*backend, factories, basis, d, q.at("moments").get<std::vector<double>>(),
                             q.at("zf").get<double>(), q.value("points", std::vector<double>{}), o.check));
      }
    } catch (const std::exception& e) {
      // A malformed line is reported with its number and does not stop the others.
      ++failures;
      out["status"] = "error";
      out["message"] = o.input + ":" + std::to_string(number) + ": " + e.what();
      std::fprintf(stderr, "momentbench: %s\n", out["message"].get<std::string>().c_str());
    }
    results << out.dump() << "\n";
  }
  if (o.output.empty()) {
    std::fputs(results.str().c_str(), stdout);
  } else {
    write_file_atomically(o.output, results.str());
  }
  return failures ? 3 : 0;
}

}  // namespace

void register_solve_command(CLI::App& app, std::function<int()>& action) {
  auto o = std::make_shared<SolveOptions>();
  CLI::App* c = app.add_subcommand("solve", "Solve Problem 1 instances as LPs (one from flags, or JSON Lines)");
  c->add_option("--basis", o->basis, "Basis functions: catalog names, expressions in z, or a set (power4, trig4)")
      ->delimiter(',');
  c->add_option("--interval", o->interval, "Admissible interval lo,hi")->delimiter(',');
  c->add_option("--grid", o->grid, "Uniform grid points on the interval")->check(CLI::Range(2, 1 << 24));
  c->add_option("--moments", o->moments, "Moment vector b_1..b_m")->delimiter(',');
  c->add_option("--points", o->points, "Extra points of I (e.g. the kernel's depths)")->delimiter(',');
  c->add_option("--zf", o->zf, "Fragment depth z_f");
  c->add_option("--backend", o->backend, "LP backend")->check(CLI::IsMember({"fast", "glpk"}));
  c->add_option("--technique", o->technique,
                 "A closed form instead of the LP (hamburger4, hausdorff4, tmsm, vsm, esm, ...); --basis is ignored");
  c->add_option("--alpha", o->alpha, "Moment bias for --technique (default: the technique's own)")
      ->check(CLI::Range(0.0, 0.999999));
  c->add_option("--input", o->input, "JSON Lines file of instances");
  c->add_option("--output", o->output, "JSON Lines results (written atomically; stdout if absent)");
  c->add_flag("--check", o->check, "Run the independent KKT checker on every optimal answer");
  c->add_flag("--quantize", o->quantize, "Round extra points to the grid (REFERENCE.md §2)");
  c->callback([o, &action] { action = [o] { return run_solve(*o); }; });
}

}  // namespace mb
