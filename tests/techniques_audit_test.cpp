// The audit of claimed bounds (docs/reference.md §3, §4): every technique whose darkening bound is
// finite delivers it on real receivers, fragment by fragment, on the default dataset at its own
// resolution and on the translucent dataset at 512², against the biased reference. A technique that
// over-darkens beyond its claim fails here, before a report calls a known property a bug.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "eval/evaluation.h"
#include "report/darkening.h"
#include "techniques/registry.h"

namespace mb {
namespace {

struct Audited {
  std::string dataset;
  int resolution;  // 0: the dataset's own
};

TEST(TechniqueAudit, NoTechniqueClaimsMoreThanItDelivers) {
  if (!std::filesystem::exists(std::string(MOMENTBENCH_SOURCE_DIR) + "/data/buildings.obj"))
    GTEST_SKIP() << "data/ not fetched (scripts/fetch_data)";
  EvalSettings settings;
  settings.threads = 2;
  for (const Audited& audited : {Audited{"default", 0}, Audited{"translucent", 512}}) {
    const auto views =
        prepare_views(load_dataset(audited.dataset), audited.resolution, settings, true);
    size_t checked = 0;
    for (const TechniqueRow* row : family_rows(TechniqueFamily::HardShadow)) {
      std::vector<std::string> names{row->name};
      if (row->prefix()) names = {"lp:power4", "lp:trig4", "lp:z;exp(-z);sin(pi z);z^3"};
      for (const std::string& name : names) {
        const double bound = make_technique(name, settings.technique)->darkening_bound();
        if (can_over_darken(bound)) continue;  // claims nothing: not audited here
        double max_dark = 0;
        for (const auto& view : views) {
          const TechniqueResult r = evaluate_technique(view, name, settings, nullptr);
          for (size_t k = 0; k < r.shadow.size(); ++k)
            max_dark = std::max(max_dark, r.shadow[k] - view.fragments.pcf[k]);
        }
        EXPECT_LE(max_dark, bound + kDarkeningSlack)
            << name << " on " << audited.dataset << " claims " << bound;
        ++checked;
      }
    }
    EXPECT_GE(checked, 12u) << audited.dataset;  // pcf .. tmsm and three LP bases
  }
}

}  // namespace
}  // namespace mb
