#pragma once
// The options that decide how shadows are evaluated (kernel, PCF bias, moment bias, technique
// parameters, LP discretisation), declared once for `eval`, `sweep` and `verify`.
#include <string>
#include <vector>

#include "eval/evaluation.h"
#include "util/config.h"

namespace mb {

std::vector<OptionSpec> shadow_option_specs();
// The options a hard shadow's numbers depend on (of a hard-shadow sweep): shadow_option_specs()
// without what only an area light and the soft techniques read (light.directions, soft.*).
std::vector<OptionSpec> hard_shadow_option_specs();
// The kernel.* keys alone (commands that need no technique parameters; the lp.* keys:
// techniques/lp_options.h).
GaussianKernel kernel_from(const Config& config);
// Validated settings from a resolved config (InputError naming the key on bad values).
EvalSettings shadow_settings_from(const Config& config, int threads);
// `techniques` with the `oracle` row added where the receiver-plane reference needs it
// (docs/reference.md §3: every table then shows the oracle floor, the bias's own error).
std::vector<std::string> with_oracle_row(std::vector<std::string> techniques,
                                         const BiasParams& bias);
// One report line per setting that matters for reproducing numbers.
std::string describe_settings(const EvalSettings& settings);

}  // namespace mb
