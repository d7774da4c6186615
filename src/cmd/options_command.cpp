// `momentbench options`: every command's option table as Markdown, from the same declarations
// that validate --config and --set (util/config.h). The README's option lists are this output
// (scripts/update_readme_options.sh writes them; ctest readme.options_current checks them).
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "cmd/commands.h"
#include "techniques/registry.h"
#include "util/error.h"

namespace mb {

namespace {

std::vector<std::pair<std::string, std::vector<OptionSpec>>> command_option_tables() {
  return {{"render", render_specs()},   {"eval", eval_specs()},      {"solve", solve_specs()},
          {"sweep", sweep_specs()},     {"merge", merge_specs()},    {"report", report_specs()},
          {"verify", verify_specs()},   {"bounds", bounds_specs()},  {"oit", oit_specs()},
          {"scatter", scatter_specs()}, {"storage", storage_specs()}};
}

int run_options(const std::string& only) {
  bool found = false;
  std::string text;
  if (only.empty() || only == "techniques") {
    found = true;
    text += "#### Techniques (`techniques`, sweep `references`, verify targets)\n\n" +
            technique_table_markdown() + "\n";
  }
  for (const auto& [command, specs] : command_option_tables()) {
    if (!only.empty() && only != command) continue;  // "techniques" prints the registry alone
    found = true;
    text += "#### `" + command + "`\n\n" + Config(specs).options_markdown() + "\n";
  }
  if (!found) throw InputError("options: no command '" + only + "'");
  std::fputs(text.c_str(), stdout);
  return 0;
}

}  // namespace

void register_options_command(CLI::App& app, std::function<int()>& action) {
  auto only = std::make_shared<std::string>();
  CLI::App* command = app.add_subcommand(
      "options", "Every command's options (keys for --config and --set) as Markdown tables");
  command->add_option("command", *only, "Only this command's table");
  command->callback([only, &action] { action = [only] { return run_options(*only); }; });
}

}  // namespace mb
