#include "eval/blocker_audit_run.h"

namespace mb {

std::vector<ViewBlockerAudit> audit_blocker_searches(const std::vector<ViewData>& views,
                                                     const EvalSettings& settings) {
  std::vector<ViewBlockerAudit> audits;
  if (settings.soft.audit == 0) return audits;
  for (const ViewData& view : views) {
    if (view.soft.angle_deg <= 0) continue;
    audits.push_back(
        {view.scene, view.view, view.soft.angle_deg,
         blocker_audit(view.map, view.fragments, view.soft, settings.kernel, settings.bias,
                       settings.soft, settings.technique, settings.threads)});
  }
  return audits;
}

}  // namespace mb
