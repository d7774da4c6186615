#pragma once
// The sweep's results (docs/design.md §Data flow: ResultsStore): a SQLite database with one row per
// candidate, written in its own transaction, so a killed sweep (kill -9, power loss) keeps every
// finished candidate and nothing half-written; plus the reference techniques and the metadata
// (config and its hash) a resume or a merge must match.
#include <sqlite3.h>

#include <cstdint>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "eval/error_stats.h"

namespace mb {

struct ResultRow {
  uint64_t id = 0;   // candidate rank (references: 0, ordered by name)
  std::string name;  // the functions, "z; z^2; z^3; z^4", or the technique name
  uint64_t fragments = 0, solved = 0, skipped = 0, infeasible = 0, unstable = 0;
  double mean = 0, leak = 0, dark = 0, max = 0, share_over_tenth = 0;
  double max_dark = 0;           // the largest G - PCF at one fragment
  double darkening_bound = 0;    // Technique::darkening_bound (candidates: the LP's 1e-9)
  std::string darkening_reason;  // Technique::darkening_reason
  std::string view_errors;       // JSON object: "scene/view" -> mean error
  std::string histogram;         // comma-separated counts of ErrorStats::kHistogramBins bins
  double seconds = 0;            // wall time (not part of the results' identity)
  // A screened candidate that was not evaluated exactly (report only): `mean` is its estimate,
  // `se` the estimate's standard error, and the other statistics are unknown.
  bool estimated = false;
  double se = 0;
};

// A screened candidate (screen/screening.h): its estimated mean error, the standard error, and the
// sampled runs' error sums that the confirmation compares candidates by.
struct EstimateRow {
  uint64_t id = 0;
  int stage = 1;  // 1: every candidate on the screen's sample; 2: the refining sample
  std::string name;
  double mean = 0, se = 0;
  uint64_t solved = 0, failed = 0;  // LPs of the sample: optimal; infeasible or unstable
  std::vector<double> run_errors;   // stored as their bytes: the confirmation reads the same bits
  double seconds = 0;
  // Screened out by its shard (docs/sweeps.md, "Full scale"): its run errors were dropped, and
  // what proves it out of reach of the sweep's best is kept instead: reach_lower = mean - sigmas
  // x SE(this - against), `against` its shard's K-th best estimate (screen/screening.h).
  bool screened_out = false;
  double reach_lower = 0;
  uint64_t reach_against = 0;
};

class ResultsStore {
 public:
  // Creates a new database (the file must not exist) with these metadata.
  static ResultsStore create(const std::string& path,
                             const std::map<std::string, std::string>& meta);
  static ResultsStore open(const std::string& path);
  ResultsStore(ResultsStore&& other) noexcept;
  ~ResultsStore();

  std::map<std::string, std::string> meta() const;
  std::set<uint64_t> candidate_ids() const;
  void put_candidate(const ResultRow& row);  // one committed transaction (outside batch)
  void put_reference(const ResultRow& row);
  std::vector<ResultRow> candidates() const;  // by id
  std::vector<ResultRow> references() const;  // by name
  // Screening (sweep --screen): one committed row per screened candidate.
  std::set<uint64_t> estimate_ids(int stage) const;
  void put_estimate(const EstimateRow& row);  // replaces the row of its id and stage
  // By id; stage 0: every stage. Without `run_errors`, the rows' run_errors stay empty: a report
  // of 66 045 screened candidates reads a few MB, not the unit errors.
  std::vector<EstimateRow> estimates(int stage, bool run_errors = true) const;
  // Each candidate's most precise estimate (its last stage), by id, without run errors: what a
  // report shows for a candidate without an exact row, and what the confirmation compares.
  std::vector<EstimateRow> latest_estimates() const;
  // One candidate's run errors at `stage` (empty when screened out).
  std::vector<double> run_errors(uint64_t id, int stage) const;
  // Drops the run errors of `rows` (their id, reach_lower and reach_against) at `stage`, in one
  // transaction, and gives any free space back (VACUUM).
  void screen_out(int stage, const std::vector<EstimateRow>& rows);
  // Runs `puts` (any of the put_ calls) as one transaction: one commit, not one per row (merge's
  // 66 045 rows: one fsync instead of 66 045). Nothing of it is stored if it throws.
  template <class Puts>
  void batch(Puts puts) {
    exec("BEGIN");
    try {
      puts();
    } catch (...) {
      exec("ROLLBACK");
      throw;
    }
    exec("COMMIT");
  }

 private:
  ResultsStore(sqlite3* db, std::string path) : db_(db), path_(std::move(path)) {}
  void exec(const std::string& sql) const;
  void put(const char* table, const ResultRow& row);
  std::vector<ResultRow> rows(const char* table, const char* order) const;
  sqlite3* db_ = nullptr;
  std::string path_;
};

// The results database of `given`: a sweep's output directory (its results.sqlite) or the file
// itself (an existing file, or a name ending in .sqlite); a missing directory names its database.
std::string results_database_path(const std::string& given);

// A row from an evaluation's statistics.
ResultRow make_result_row(uint64_t id, const std::string& name, const ErrorStats& overall,
                          const std::vector<std::pair<std::string, double>>& view_errors);

}  // namespace mb
