// `momentbench solve`: Problem 1 instances (docs/reference.md §1-2) with a chosen LP backend, one
// from flags or a JSON Lines batch; `--check` runs the independent KKT checker on every answer.
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "cmd/command_common.h"
#include "cmd/commands.h"
#include "lp/solution.h"
#include "solve/solve_query.h"
#include "util/error.h"
#include "util/output_dir.h"

namespace mb {

std::vector<OptionSpec> solve_specs() {
  return solve_option_specs();
}

namespace {

template <class T>
YAML::Node yaml_of(const T& value) {
  return YAML::Node(value);
}

int run_solve_command(const CLI::App& command, const CommonOptions& common, SolveSettings flags) {
  auto cmd = CommandRun::begin(
      solve_specs(), common, command,
      {{"--basis", "basis", [&] { return yaml_of(flags.basis); }},
       {"--interval", "interval", [&] { return yaml_of(flags.interval); }},
       {"--grid", "grid", [&] { return yaml_of(flags.grid); }},
       {"--moments", "moments", [&] { return yaml_of(flags.moments); }},
       {"--depths", "depths", [&] { return yaml_of(flags.depths); }},
       {"--weights", "weights", [&] { return yaml_of(flags.weights); }},
       {"--points", "points", [&] { return yaml_of(flags.points); }},
       {"--zf", "zf", [&] { return yaml_of(flags.zf); }},
       {"--backend", "backend", [&] { return yaml_of(flags.backend); }},
       {"--technique", "technique", [&] { return yaml_of(flags.technique); }},
       {"--alpha", "alpha", [&] { return yaml_of(flags.alpha); }},
       {"--input", "input", [&] { return yaml_of(flags.input); }},
       {"--output", "output", [&] { return yaml_of(flags.output); }},
       {"--check", "check", [&] { return yaml_of(flags.check); }},
       {"--quantize", "quantize", [&] { return yaml_of(flags.quantize); }},
       {"--discretization", "discretization", [&] { return yaml_of(flags.discretization); }},
       {"--moment-tolerance", "moment_tolerance",
        [&] { return yaml_of(flags.moment_tolerance); }}});
  if (!cmd) return 0;
  const SolveSettings o = solve_settings_from(cmd->config());
  if (o.input.empty()) {
    const nlohmann::json answer = solve_instance(o);
    std::printf("%s\n", answer.dump(2).c_str());
    return answer["status"] == "optimal" ? 0 : 3;
  }
  if (std::filesystem::is_directory(o.input))
    throw InputError(o.input + ": is a directory; --input needs a JSON Lines file");
  std::ifstream in(o.input);
  if (!in) throw InputError(o.input + ": cannot open");
  const SolveBatch batch = solve_batch(o, in, o.input);
  if (o.output.empty())
    std::fputs(batch.lines.c_str(), stdout);
  else
    write_file_atomically(o.output, batch.lines);
  return batch.failures ? 3 : 0;
}

}  // namespace

void register_solve_command(CLI::App& app, std::function<int()>& action) {
  auto o = std::make_shared<SolveSettings>();
  auto common = std::make_shared<CommonOptions>();
  CLI::App* c = app.add_subcommand(
      "solve", "Solve Problem 1 instances as LPs (one from flags, or JSON Lines)");
  add_common_options(*c, *common, /*has_output=*/false);
  // Shorthands of the option keys (solve_specs); given, they override the config file and --set.
  c->add_option("--basis", o->basis, "= --set basis=[...]")->delimiter(',');
  c->add_option("--interval", o->interval, "= --set interval=[lo, hi]")->delimiter(',');
  c->add_option("--grid", o->grid, "= --set grid=N")->check(CLI::Range(2, 1 << 24));
  c->add_option("--moments", o->moments, "= --set moments=[...]")->delimiter(',');
  c->add_option("--depths", o->depths, "= --set depths=[...] (a distribution, with --weights)")
      ->delimiter(',');
  c->add_option("--weights", o->weights, "= --set weights=[...]")->delimiter(',');
  c->add_option("--points", o->points, "= --set points=[...]")->delimiter(',');
  c->add_option("--zf", o->zf, "= --set zf=Z");
  c->add_option("--backend", o->backend, "= --set backend=NAME")
      ->check(CLI::IsMember(lp::backend_names()));
  c->add_option("--technique", o->technique, "= --set technique=NAME");
  c->add_option("--alpha", o->alpha, "= --set alpha=A")->check(CLI::Range(0.0, 0.999999));
  CLI::Option* input = c->add_option("--input", o->input, "= --set input=FILE");
  c->add_option("--output", o->output, "= --set output=FILE");
  c->add_flag("--check", o->check, "= --set check=true");
  c->add_flag("--quantize", o->quantize, "= --set quantize=true");
  c->add_option("--moment-tolerance", o->moment_tolerance, "= --set moment_tolerance=ULPS")
      ->check(CLI::Range(0.0, 1e15));
  c->add_option("--discretization", o->discretization, "= --set discretization=grid|continuous")
      ->check(CLI::IsMember({"grid", "continuous"}));
  // An instance comes from flags or from --input, never both (flags beside a batch were ignored).
  for (const char* flag : {"--basis", "--interval", "--moments", "--depths", "--weights",
                           "--points", "--zf", "--technique", "--alpha"})
    input->excludes(c->get_option(flag));
  c->callback([o, common, c, &action] {
    action = [o, common, c] { return run_solve_command(*c, *common, *o); };
  });
}

}  // namespace mb
