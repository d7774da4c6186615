#pragma once
// msm_soft's blocker search audited on every view lit by an area light (docs/soft-shadows.md §3):
// the rows of techniques/soft/soft_technique.h's blocker_audit, with the view they come from.
#include <string>
#include <vector>

#include "eval/evaluation.h"

namespace mb {

struct ViewBlockerAudit {
  std::string scene, view;
  double angle_deg = 0;
  std::vector<BlockerAuditRow> rows;
};

// One audit per view whose light has an extent, in view order; none when settings.soft.audit is 0.
std::vector<ViewBlockerAudit> audit_blocker_searches(const std::vector<ViewData>& views,
                                                     const EvalSettings& settings);

}  // namespace mb
