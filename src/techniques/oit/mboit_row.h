#pragma once
// The registry row of one MBOIT variant (docs/transparency.md §3): power and trigonometric moments
// share everything but the moments' kind, their count and how a variant is made and verified.
#include <string>

#include "techniques/registry.h"

namespace mb {

// MBOIT's overestimation beta: A = A- + beta (A+ - A-) (docs/transparency.md §3; oit.beta), an
// option of every MBOIT row.
extern const TechniqueOption kMboitBeta;

// `prefix` + moments + the variant's suffix (the technique's own file names the prefix) for storage
// variant `variant` of kOitStorageVariants, its moments described as `kind` moments ("power"),
// ranked `rank_base` + moments + the variant's rank.
TechniqueRow mboit_row(const std::string& prefix, const std::string& kind, int moments, int variant,
                       int rank_base, decltype(TechniqueRow::make_oit) make,
                       decltype(TechniqueRow::oit_verify) verify);

}  // namespace mb
