#pragma once
// The transmittance family's shared options (oit.warp, oit.depth_range): their records,
// the only place their defaults are written (a default-made OitParams holds them), and OitParams
// from a resolved config, for the oit command and a sweep's transparency target alike.
#include <vector>

#include "techniques/oit/oit_technique.h"
#include "util/config.h"

namespace mb {

std::vector<OptionSpec> oit_option_specs();
// The OitParams of `config`: the oit.* keys it declares (a sweep declares oit.beta and oit.warp;
// the others keep their records' defaults) and the lp.* keys of the lp: rows, validated.
OitParams oit_params_from(const Config& config);

}  // namespace mb
