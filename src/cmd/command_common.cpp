#include "cmd/command_common.h"

namespace mb {

namespace {
std::vector<std::string> g_arguments;
}

void set_process_arguments(int argc, char** argv) { g_arguments.assign(argv, argv + argc); }
const std::vector<std::string>& process_arguments() { return g_arguments; }

void add_common_options(CLI::App& command, CommonOptions& options, bool has_output) {
  command.add_option("-c,--config", options.config_file, "YAML config file (keys as printed by --print-config)");
  command.add_option("-s,--set", options.sets, "Override one option: key=value (repeatable)")->take_all();
  command.add_flag("--print-config", options.print_config, "Print the effective config as YAML and exit");
  if (has_output) {
    command.add_option("-o,--out", options.out, "Output directory (must not exist, unless --force)");
    command.add_flag("-f,--force", options.force, "Replace an existing output directory");
  }
  command.add_flag("-q,--quiet", options.quiet, "No progress output on stderr");
}

Config resolve_config(std::vector<OptionSpec> specs, const CommonOptions& options) {
  Config config(std::move(specs));
  if (!options.config_file.empty()) config.load_file(options.config_file);
  for (const auto& s : options.sets) config.set(s);
  return config;
}

std::vector<OptionSpec> dataset_option_specs() {
  return {
      {"dataset", OptionType::String, "default",
       "Dataset: a YAML file, or the name of one in configs/datasets/ (tiny, default, paper)."},
      {"resolution", OptionType::Integer, "0", "Shadow-map resolution for every view; 0 keeps the dataset's.", 0,
       16384},
      {"threads", OptionType::Integer, "0", "OpenMP threads; 0 uses every core.", 0, 4096},
  };
}

}  // namespace mb
