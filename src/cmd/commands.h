#pragma once
// One register function per subcommand; each sets `action` when its subcommand is chosen.
#include <CLI/CLI.hpp>
#include <functional>

namespace mb {

void register_render_command(CLI::App& app, std::function<int()>& action);
void register_eval_command(CLI::App& app, std::function<int()>& action);
void register_solve_command(CLI::App& app, std::function<int()>& action);
void register_sweep_command(CLI::App& app, std::function<int()>& action);
void register_merge_command(CLI::App& app, std::function<int()>& action);
void register_report_command(CLI::App& app, std::function<int()>& action);
void register_verify_command(CLI::App& app, std::function<int()>& action);
void register_bounds_command(CLI::App& app, std::function<int()>& action);

}  // namespace mb
