// momentbench: one binary, one subcommand per pipeline stage (DESIGN.md §Command line).
#include <CLI/CLI.hpp>
#include <cstdio>
#include <functional>

#include "cmd/command_common.h"
#include "cmd/commands.h"
#include "util/error.h"

int main(int argc, char** argv) {
  mb::set_process_arguments(argc, argv);
  CLI::App app{"momentbench: moment shadow mapping benchmarks, from depth-layer stacks to LP ground truth"};
  app.require_subcommand(1);
  app.set_version_flag("--version", MOMENTBENCH_VERSION);
  std::function<int()> action;
  mb::register_render_command(app, action);
  mb::register_eval_command(app, action);
  mb::register_solve_command(app, action);
  mb::register_sweep_command(app, action);
  mb::register_merge_command(app, action);
  mb::register_report_command(app, action);
  mb::register_verify_command(app, action);
  mb::register_bounds_command(app, action);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }
  try {
    return action ? action() : 0;
  } catch (const mb::InputError& e) {
    std::fprintf(stderr, "momentbench: error: %s\n", e.what());
    return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "momentbench: internal error: %s\n", e.what());
    return 2;
  }
}
