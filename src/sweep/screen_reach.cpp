#include "sweep/screen_reach.h"

#include <algorithm>
#include <limits>
#include <map>
#include <numeric>
#include <set>

#include "util/error.h"

namespace mb {

namespace {

// The positions of `rows` (by id) by estimate, ties by id, as candidates_to_confirm orders them.
std::vector<size_t> by_estimate(const std::vector<EstimateRow>& rows) {
  std::vector<size_t> order(rows.size());
  std::iota(order.begin(), order.end(), size_t(0));
  std::stable_sort(order.begin(), order.end(),
                   [&](size_t a, size_t b) { return rows[a].mean < rows[b].mean; });
  return order;
}

// The estimates at `stage` of `ids` (ascending): the candidates the confirmation compares.
std::vector<EstimateRow> estimates_of(const ResultsStore& store, int stage,
                                      const std::vector<uint64_t>& ids) {
  std::vector<EstimateRow> rows = store.estimates(stage, false);
  std::erase_if(rows, [&](const EstimateRow& r) {
    return !std::binary_search(ids.begin(), ids.end(), r.id);
  });
  return rows;
}

}  // namespace

std::pair<size_t, size_t> screen_out_unreachable(ResultsStore& store, int stage,
                                                 const std::vector<uint64_t>& ids,
                                                 const ScreenSample& sample, const ScreenRule& rule,
                                                 double keep_sigmas) {
  std::vector<EstimateRow> rows = estimates_of(store, stage, ids);
  if (rule.top <= 0 || rows.size() <= size_t(rule.top)) return {0, rows.size()};
  const std::vector<size_t> order = by_estimate(rows);
  const EstimateRow& r = rows[order[size_t(rule.top) - 1]];
  // A K-th best without unit errors (a merged database whose shards disagree on ties): nothing is
  // screened out until it is screened again (unproven_screened_out).
  if (r.screened_out) return {0, rows.size()};
  const std::vector<double> r_errors = store.run_errors(r.id, stage);
  std::vector<bool> best(rows.size(), false);
  for (int k = 0; k < rule.top; ++k) best[order[size_t(k)]] = true;
  // Every K-th best that a screened-out candidate was proven against keeps its unit errors: they
  // are that proof's (a merged database's own K-th best differs from its shards').
  std::set<uint64_t> anchors;
  for (const auto& c : rows)
    if (c.screened_out) anchors.insert(c.reach_against);
  std::vector<EstimateRow> out;
  for (size_t i = 0; i < rows.size(); ++i) {
    EstimateRow& c = rows[i];
    if (c.screened_out || anchors.count(c.id)) continue;
    // One candidate's unit errors at a time: a shard's 33 000 of them are 500 MB.
    const std::vector<double> errors = store.run_errors(c.id, stage);
    if (keeps_unit_errors(sample, errors, c.mean, r_errors, r.mean, best[i], rule, keep_sigmas))
      continue;
    c.screened_out = true;
    c.reach_lower = reach_lower_bound(sample, errors, c.mean, r_errors, rule);
    c.reach_against = r.id;
    out.push_back(std::move(c));
  }
  store.screen_out(stage, out);
  return {out.size(), rows.size()};
}

std::vector<uint64_t> unproven_screened_out(const ResultsStore& store, int stage,
                                            const std::vector<uint64_t>& ids,
                                            const ScreenSample& sample, const ScreenRule& rule) {
  const std::vector<EstimateRow> rows = estimates_of(store, stage, ids);
  std::vector<uint64_t> out;
  if (rule.top <= 0 || rows.size() <= size_t(rule.top)) {
    for (const auto& c : rows)  // every candidate is confirmed: each needs its unit errors
      if (c.screened_out) out.push_back(c.id);
    return out;
  }
  const std::vector<size_t> order = by_estimate(rows);
  for (int k = 0; k < rule.top; ++k)
    if (rows[order[size_t(k)]].screened_out) out.push_back(rows[order[size_t(k)]].id);
  if (!out.empty()) {
    std::sort(out.begin(), out.end());
    return out;
  }
  const EstimateRow& rp = rows[order[size_t(rule.top) - 1]];
  const std::vector<double> rp_errors = store.run_errors(rp.id, stage);
  std::map<uint64_t, std::vector<double>> against;  // each shard's K-th best
  for (size_t k = size_t(rule.top); k < order.size(); ++k) {
    const EstimateRow& c = rows[order[k]];
    if (!c.screened_out) continue;
    auto it = against.find(c.reach_against);
    if (it == against.end()) {
      std::vector<double> errors;
      try {
        errors = store.run_errors(c.reach_against, stage);
      } catch (const InputError&) {  // not in this database (a partial merge): no proof
      }
      it = against.emplace(c.reach_against, std::move(errors)).first;
    }
    // Its shard's K-th best has no unit errors here (screened out in turn, or absent): no proof.
    if (it->second.size() != sample.sampled_runs() ||
        !proven_out_of_reach(sample, c.reach_lower, it->second, rp_errors, rp.mean, rule))
      out.push_back(c.id);
  }
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<uint64_t> estimates_ahead_of_best_exact(const ResultsStore& store,
                                                    const std::vector<uint64_t>& ids) {
  const std::set<uint64_t> planned(ids.begin(), ids.end());
  std::set<uint64_t> exact;
  double best = std::numeric_limits<double>::infinity();
  for (const ResultRow& row : store.candidates())
    if (planned.count(row.id)) exact.insert(row.id), best = std::min(best, row.mean);
  if (exact.empty()) return {};
  std::vector<uint64_t> ahead;  // by the latest stage's estimate, as the report shows it
  for (const EstimateRow& e : store.latest_estimates())
    if (planned.count(e.id) && !exact.count(e.id) && e.mean < best) ahead.push_back(e.id);
  return ahead;
}

}  // namespace mb
