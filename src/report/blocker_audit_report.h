#pragma once
// The blocker audit's outputs (docs/soft-shadows.md §3): blocker_audit.csv, one row per audited
// receiver, and report.md's section summarising it per light angle.
#include <string>
#include <vector>

#include "eval/blocker_audit_run.h"

namespace mb {

// Columns: scene, view, light_angle, receiver, zs, blocker_exact, blocker_seed, blocker_lo,
// blocker_hi (depths), penumbra_exact, penumbra_seed, penumbra_lo, penumbra_hi (texels), outside
// (1 where seed 004's estimate lies outside the sharp bounds).
std::string blocker_audit_csv(const std::vector<ViewBlockerAudit>& audits);

// Markdown, per light angle: receivers audited, the share whose estimate leaves the bounds, how
// far the estimate's penumbra is from the region's own, and how wide the bounds leave it.
std::string blocker_audit_section(const std::vector<ViewBlockerAudit>& audits);

}  // namespace mb
