#include "cmd/command_common.h"

#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "util/error.h"
#include "util/install_paths.h"

namespace mb {

namespace {
std::vector<std::string> g_arguments;
}

void set_process_arguments(int argc, char** argv) {
  g_arguments.assign(argv, argv + argc);
}
const std::vector<std::string>& process_arguments() {
  return g_arguments;
}

void add_common_options(CLI::App& command, CommonOptions& options, bool has_output) {
  command.add_option("-c,--config", options.config_file,
                     "YAML config file (keys as printed by --print-config)");
  command.add_option("-s,--set", options.sets, "Override one option: key=value (repeatable)")
      ->take_all();
  command.add_flag("--print-config", options.print_config,
                   "Print the effective config as YAML and exit");
  if (has_output) {
    command.add_option("-o,--out", options.out,
                       "Output directory (must not exist, unless --force)");
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

bool print_config_if_asked(const Config& config, const CommonOptions& options) {
  if (!options.print_config) return false;
  std::fputs(config.to_yaml().c_str(), stdout);
  return true;
}

void write_run_record(const StagedOutputDir& out, const Config& config, const RunMetadata& meta) {
  write_file_atomically(out / "config.yaml", config.to_yaml());
  write_file_atomically(out / "run.yaml", to_yaml(meta));
}

CommandRun::CommandRun(Config config, const CommonOptions& options)
    : config_(std::move(config)), options_(&options) {
  for (const auto& spec : config_.specs())
    if (spec.name == "threads") threads_ = resolve_thread_count(int(config_.integer("threads")));
}

std::optional<CommandRun> CommandRun::begin(std::vector<OptionSpec> specs,
                                            const CommonOptions& options) {
  Config config = resolve_config(std::move(specs), options);
  if (print_config_if_asked(config, options)) return std::nullopt;
  return CommandRun(std::move(config), options);
}

std::optional<CommandRun> CommandRun::begin(std::vector<OptionSpec> specs,
                                            const CommonOptions& options, const CLI::App& command,
                                            const std::vector<FlagKey>& flags) {
  Config config = resolve_config(std::move(specs), options);
  apply_flags(command, config, flags);
  if (print_config_if_asked(config, options)) return std::nullopt;
  return CommandRun(std::move(config), options);
}

StagedOutputDir& CommandRun::out() {
  if (!out_) out_ = std::make_unique<StagedOutputDir>(options_->out, options_->force);
  return *out_;
}

const RunMetadata& CommandRun::metadata() {
  if (!metadata_) metadata_ = collect_run_metadata(threads_, process_arguments());
  return *metadata_;
}

void CommandRun::finish() {
  write_run_record(out(), config_, metadata());
  out_->commit();
}

void apply_flags(const CLI::App& command, Config& config, const std::vector<FlagKey>& flags) {
  for (const auto& f : flags)
    if (command.get_option(f.flag)->count() > 0) config.set_node(f.key, f.value(), f.flag);
}

std::vector<OptionSpec> dataset_option_specs() {
  return option_specs(dataset_option_records());
}

std::string run_plot_script(const std::string& script, std::vector<std::string> arguments,
                            const std::string& out_stem, const std::string& caption, bool quiet) {
  const std::string python = "/usr/bin/python3";
  if (run_program(python, {"-c", "import matplotlib"}, true) != 0) {
    std::string note =
        "No plot: /usr/bin/python3 with matplotlib is not available (apt install "
        "python3-matplotlib).\n\n";
    if (!quiet) std::fprintf(stderr, "%s", note.c_str());
    return note;
  }
  const std::string path = (data_root() / "scripts" / script).string();
  arguments.insert(arguments.begin(), path);
  arguments.push_back("--out");
  arguments.push_back(out_stem);
  if (run_program(python, arguments, quiet) != 0) {
    std::string command = python;
    for (const auto& a : arguments) command += " '" + a + "'";
    throw InputError("plot failed: " + command);
  }
  const std::string name = std::filesystem::path(out_stem).filename().string();
  return "![" + caption + "](" + name + ".png) (also " + name + ".pdf)\n\n";
}

}  // namespace mb
