#pragma once
// The series of a sweep report (docs/design.md §Data flow: report): each results database opened
// as its candidates ranked by mean error (exact rows and, of a screened sweep, the estimates of
// the rest), its reference rows and its identity, and the series of one report checked to be
// measured alike (report/series_identity.h).
#include <map>
#include <set>
#include <string>
#include <vector>

#include "sweep/results_store.h"
#include "util/config.h"

namespace mb {

struct SweepSeries {
  std::string database;                     // path of its results.sqlite
  std::string label;                        // "4 functions", unique within a report
  std::map<std::string, std::string> meta;  // ResultsStore::meta
  // Candidates by mean error, ties by id. A screened sweep's (sweep --screen) holds every screened
  // candidate: the exact row where it was evaluated exactly, its estimate (estimated) otherwise.
  std::vector<ResultRow> ranked;
  size_t exact = 0, estimated = 0;    // rows of each kind in `ranked`
  std::vector<ResultRow> references;  // by name
  int size = 0;                       // functions per candidate
  // Its identity as the report states it (report/series_identity.h): "key value" of the options
  // allowed to differ between series, and of the other measurement options off their defaults.
  std::vector<std::string> own_values, off_default;
  double best() const { return ranked.front().mean; }
  double median() const;
  // Candidates whose mean error is at most the best's plus `margin` (absolute, as a fraction).
  size_t within(double margin) const;
  // Its target (sweep/sweep_target.h): shadows, transparency or scattering; older databases are
  // shadow sweeps.
  std::string target() const {
    const auto it = meta.find("target");
    return it == meta.end() ? "shadows" : it->second;
  }
  bool transparency() const { return target() == "transparency"; }
};

// Candidates of `s` strictly better than `mean`.
size_t better_than(const SweepSeries& s, double mean);
// "rank r of N (b better, p %)", or "behind all N candidates".
std::string rank_text(const SweepSeries& s, double mean);

// What the series of one report must share: the value of every measurement option of `specs`
// (the sweep's option records, sweep/run_identity.h) but those in `allow_different`.
struct SeriesIdentity {
  std::vector<OptionSpec> specs;
  std::vector<std::string> allow_different;  // report --allow-different
};

// Opens each database (InputError for one with no candidates, or for series whose measurement
// options differ: each differing key with both values, unless the identity allows it).
std::vector<SweepSeries> load_sweep_series(const std::vector<std::string>& databases,
                                           const SeriesIdentity& identity);

// A candidate's functions ("z; z^2" -> {z, z^2}), and the candidate of `s` with exactly these
// functions (nullptr when not evaluated).
std::set<std::string> candidate_functions(const std::string& candidate);
const ResultRow* find_candidate(const SweepSeries& s, const std::set<std::string>& functions);

// The series the ranked tables and reference rows come from: the most functions per candidate.
const SweepSeries& main_series(const std::vector<SweepSeries>& series);

}  // namespace mb
