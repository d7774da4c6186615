#pragma once
// The lp.* options: the lp: row's settings (techniques/lp_technique.h), which every user of the
// LP fragment solver reads (eval, soft's msm_soft:lp, oit's lp:, sweep's candidates, bounds). Their
// records are the only place their defaults are written; a default-made TechniqueParams holds them.
#include <string>
#include <vector>

#include "lp/problem.h"
#include "techniques/technique.h"
#include "util/config.h"

namespace mb {

std::vector<OptionSpec> lp_option_specs();
// The discretisation (lp.grid, lp.lo, lp.hi, lp.quantize, lp.discretization) and the backend
// alone, validated: for commands that solve no technique (bounds).
lp::Discretization lp_discretization_from(const Config& config);
std::string lp_backend_from(const Config& config);
// Every lp.* value of `config` into the LP fields of `params` (discretisation, backend, moment
// box, beta), validated (InputError naming the key). Keys `config` does not declare keep their
// defaults (scatter declares only those pss_lp reads). The same for the two above.
void read_lp_params(const Config& config, TechniqueParams& params);

}  // namespace mb
