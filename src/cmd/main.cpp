// momentbench: one binary, one subcommand per pipeline stage (docs/design.md §Commands).
#include <CLI/CLI.hpp>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <new>

#include "cmd/command_common.h"
#include "cmd/commands.h"
#include "util/error.h"

int main(int argc, char** argv) {
  mb::set_process_arguments(argc, argv);
  CLI::App app{
      "momentbench: moment shadow mapping benchmarks, from depth-layer stacks to LP ground truth"};
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
  mb::register_oit_command(app, action);
  mb::register_scatter_command(app, action);
  mb::register_storage_command(app, action);
  mb::register_options_command(app, action);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // --help and --version exit 0; every command-line mistake exits 1, as bad input does.
    return app.exit(e) == 0 ? 0 : 1;
  }
  try {
    return action ? action() : 0;
  } catch (const mb::InputError& e) {
    std::fprintf(stderr, "momentbench: error: %s\n", e.what());
    return 1;
  } catch (const std::bad_alloc&) {
    std::fprintf(
        stderr,
        "momentbench: error: out of memory; lower the resolution or the number of threads\n");
    return 1;
  } catch (const std::filesystem::filesystem_error& e) {
    // A path that exists but cannot be used (a directory for a file, no permission, disk full).
    std::fprintf(stderr, "momentbench: error: %s: %s\n", e.path1().c_str(),
                 e.code().message().c_str());
    return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "momentbench: internal error: %s\n", e.what());
    return 2;
  }
}
