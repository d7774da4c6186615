#include "report/sweep_series.h"

#include <algorithm>
#include <set>
#include <sstream>

#include "report/series_identity.h"
#include "util/error.h"
#include "util/name_list.h"
#include "util/number_text.h"

namespace mb {

size_t better_than(const SweepSeries& s, double mean) {
  return size_t(std::lower_bound(s.ranked.begin(), s.ranked.end(), mean,
                                 [](const ResultRow& r, double m) { return r.mean < m; }) -
                s.ranked.begin());
}

double SweepSeries::median() const {
  const size_t n = ranked.size();
  return n % 2 ? ranked[n / 2].mean : 0.5 * (ranked[n / 2 - 1].mean + ranked[n / 2].mean);
}

size_t SweepSeries::within(double margin) const {
  return better_than(*this, best() + margin * (1 + 1e-12));
}

std::string rank_text(const SweepSeries& s, double mean) {
  const size_t better = better_than(s, mean);
  std::ostringstream out;
  if (better == s.ranked.size()) {
    out << "behind all " << s.ranked.size() << " candidates";
    return out.str();
  }
  out << "rank " << better + 1 << " of " << s.ranked.size() << " (" << better << " better, "
      << percent_text(double(better) / double(s.ranked.size())) << " %)";
  return out.str();
}

std::vector<SweepSeries> load_sweep_series(const std::vector<std::string>& databases,
                                           const SeriesIdentity& identity) {
  if (databases.empty()) throw InputError("report: expected at least one results database");
  std::vector<SweepSeries> out;
  std::map<std::string, int> labels;
  for (const auto& given : databases) {
    SweepSeries s;
    s.database = results_database_path(given);
    ResultsStore store = ResultsStore::open(s.database);
    s.meta = store.meta();
    s.ranked = store.candidates();
    s.references = store.references();
    s.exact = s.ranked.size();
    // Screened candidates without an exact row join as estimates.
    std::set<uint64_t> exact;
    for (const auto& r : s.ranked) exact.insert(r.id);
    for (const EstimateRow& e : store.latest_estimates()) {
      if (exact.count(e.id)) continue;
      ResultRow r;
      r.id = e.id;
      r.name = e.name;
      r.mean = e.mean;
      r.se = e.se;
      r.solved = e.solved;
      r.unstable = e.failed;
      r.estimated = true;
      s.ranked.push_back(std::move(r));
      ++s.estimated;
    }
    if (s.ranked.empty()) throw InputError(s.database + ": no candidates evaluated yet");
    std::stable_sort(s.ranked.begin(), s.ranked.end(),
                     [](const auto& a, const auto& b) { return a.mean < b.mean; });
    s.size = std::stoi(s.meta["combination_size"]);
    s.label = std::to_string(s.size) + (s.size == 1 ? " function" : " functions");
    if (s.estimated) s.label += " (screened)";
    drop_bounds_under_area_light(s, identity);
    out.push_back(std::move(s));
  }
  // What the errors are measured with must agree (report/series_identity.h).
  check_series_identity(out, identity);
  // Two series of one size (two samples, say) are told apart by their position.
  for (const auto& s : out) ++labels[s.label];
  std::map<std::string, int> seen;
  for (auto& s : out)
    if (labels[s.label] > 1) s.label += " #" + std::to_string(++seen[s.label]);
  return out;
}

const SweepSeries& main_series(const std::vector<SweepSeries>& series) {
  const SweepSeries* main = &series.front();
  for (const auto& s : series)
    if (s.size > main->size) main = &s;
  return *main;
}

std::set<std::string> candidate_functions(const std::string& candidate) {
  const std::vector<std::string> items = split_list(candidate, ";");
  return {items.begin(), items.end()};
}

const ResultRow* find_candidate(const SweepSeries& s, const std::set<std::string>& functions) {
  for (const auto& r : s.ranked)
    if (candidate_functions(r.name) == functions) return &r;
  return nullptr;
}

}  // namespace mb
