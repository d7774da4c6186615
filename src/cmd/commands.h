#pragma once
// One register function per subcommand; each sets `action` when its subcommand is chosen.
#include <CLI/CLI.hpp>
#include <functional>
#include <vector>

#include "util/config.h"

namespace mb {

void register_render_command(CLI::App& app, std::function<int()>& action);
void register_eval_command(CLI::App& app, std::function<int()>& action);
void register_solve_command(CLI::App& app, std::function<int()>& action);
void register_sweep_command(CLI::App& app, std::function<int()>& action);
void register_merge_command(CLI::App& app, std::function<int()>& action);
void register_report_command(CLI::App& app, std::function<int()>& action);
void register_verify_command(CLI::App& app, std::function<int()>& action);
void register_bounds_command(CLI::App& app, std::function<int()>& action);
void register_oit_command(CLI::App& app, std::function<int()>& action);
void register_scatter_command(CLI::App& app, std::function<int()>& action);
void register_storage_command(CLI::App& app, std::function<int()>& action);
// `momentbench options`: every command's option table as Markdown (the README's lists).
void register_options_command(CLI::App& app, std::function<int()>& action);

// Each command's option table (keys for --config, --set and --print-config).
std::vector<OptionSpec> render_specs();
std::vector<OptionSpec> eval_specs();
std::vector<OptionSpec> solve_specs();
std::vector<OptionSpec> sweep_specs();
std::vector<OptionSpec> merge_specs();
std::vector<OptionSpec> report_specs();
std::vector<OptionSpec> verify_specs();
std::vector<OptionSpec> bounds_specs();
std::vector<OptionSpec> oit_specs();
std::vector<OptionSpec> scatter_specs();
std::vector<OptionSpec> storage_specs();

}  // namespace mb
