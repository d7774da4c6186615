#include "sweep/sweep_plan.h"

#include <algorithm>
#include <set>

#include "basis/basis.h"
#include "lp/solution.h"
#include "scene/procedural.h"
#include "sweep/candidates.h"
#include "techniques/technique.h"
#include "util/error.h"
#include "util/name_list.h"

namespace mb {

uint64_t SweepPlan::total() const {
  return binomial(int(catalog.size()), size);
}

std::vector<std::string> SweepPlan::functions(uint64_t id) const {
  std::vector<std::string> out;
  for (int i : combination_unrank(id, int(catalog.size()), size)) out.push_back(catalog[i]);
  return out;
}

std::string SweepPlan::name(uint64_t id) const {
  return joined(functions(id), "; ");
}

SweepPlan make_sweep_plan(const std::vector<std::string>& catalog, int size,
                          const std::vector<std::string>& explicit_candidates, uint64_t sample,
                          uint64_t seed) {
  SweepPlan plan;
  plan.catalog = catalog.empty() ? catalog_names() : catalog;
  plan.size = size;
  std::set<std::string> seen;
  for (auto& name : plan.catalog) {
    name = BasisFunction::parse(name).name();  // validates, and canonical catalog spelling
    if (!seen.insert(name).second)
      throw InputError("catalog: function '" + name + "' appears twice");
  }
  if (size < 1 || size > int(plan.catalog.size()))
    throw InputError("combination_size: " + std::to_string(size) +
                     " functions cannot be drawn from a catalog of " +
                     std::to_string(plan.catalog.size()));
  const uint64_t total = plan.total();
  for (const auto& text : explicit_candidates) {
    std::vector<int> indices;
    for (const std::string& item : split_list(text, ";")) {
      std::string canonical = BasisFunction::parse(item).name();
      auto it = std::find(plan.catalog.begin(), plan.catalog.end(), canonical);
      if (it == plan.catalog.end())
        throw InputError("candidates: '" + item + "' in '" + text + "' is not in the catalog");
      indices.push_back(int(it - plan.catalog.begin()));
    }
    std::sort(indices.begin(), indices.end());
    if (int(indices.size()) != size ||
        std::adjacent_find(indices.begin(), indices.end()) != indices.end())
      throw InputError("candidates: '" + text + "' must name " + std::to_string(size) +
                       " distinct functions");
    plan.ids.push_back(combination_rank(indices, int(plan.catalog.size())));
  }
  if (sample > total) {
    throw InputError(
        "sample: " + std::to_string(sample) + " candidates asked for, but there are only " +
        std::to_string(total) + " combinations of " + std::to_string(size) + " from " +
        std::to_string(plan.catalog.size()) + " functions (sample: 0 evaluates them all)");
  } else if (sample > 0 && sample < total) {
    // Floyd's algorithm: `sample` distinct ranks, deterministic for a seed. Explicit candidates
    // join the sample (e.g. the power moments a report places among sampled ones).
    SeededRandom random(seed);
    std::set<uint64_t> chosen;
    for (uint64_t j = total - sample; j < total; ++j) {
      uint64_t t = uint64_t(random.uniform() * double(j + 1));
      if (t > j) t = j;
      if (!chosen.insert(t).second) chosen.insert(j);
    }
    plan.ids.insert(plan.ids.end(), chosen.begin(), chosen.end());
  } else if (sample == total || explicit_candidates.empty()) {
    plan.ids.clear();
    for (uint64_t id = 0; id < total; ++id) plan.ids.push_back(id);
  }
  std::sort(plan.ids.begin(), plan.ids.end());
  plan.ids.erase(std::unique(plan.ids.begin(), plan.ids.end()), plan.ids.end());
  return plan;
}

std::vector<uint64_t> shard_ids(const SweepPlan& plan, int k, int n) {
  std::vector<uint64_t> out;
  for (size_t i = size_t(k - 1); i < plan.ids.size(); i += size_t(n)) out.push_back(plan.ids[i]);
  return out;
}

std::pair<int, int> parse_shard(const std::string& text) {
  int k = 0, n = 0;
  char slash = 0, extra = 0;
  if (std::sscanf(text.c_str(), "%d%c%d%c", &k, &slash, &n, &extra) != 3 || slash != '/' || n < 1 ||
      k < 1 || k > n)
    throw InputError("--shard: expected K/N with 1 <= K <= N, got '" + text + "'");
  return {k, n};
}

void check_plan(const SweepPlan& plan, const TechniqueParams& technique) {
  std::vector<BasisFunction> functions;
  for (const auto& name : plan.catalog) functions.push_back(BasisFunction::parse(name));
  Basis(functions).check_admissible(technique.lp.lo, technique.lp.hi);
  // A unorm box is fitted to each candidate's certified ranges (docs/reference.md §8), which an
  // expression has no derivatives to prove: refused here rather than in every candidate with it.
  if (technique.lp_moment_box.rfind("unorm", 0) == 0)
    for (const BasisFunction& f : functions)
      if (!f.has_derivatives())
        throw InputError("catalog: '" + f.name() +
                         "' is an expression, and lp.moment_box = " + technique.lp_moment_box +
                         " needs certified ranges of every candidate's functions (catalog "
                         "functions have them, docs/reference.md §8); expected catalog functions "
                         "or lp.moment_box none, double or float32");
  lp::check_backend_rows(technique.lp_backend, plan.size, "combination_size");
}

}  // namespace mb
