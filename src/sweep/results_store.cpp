#include "sweep/results_store.h"

#include <unistd.h>

#include <cstring>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>

#include "util/error.h"

namespace mb {

namespace {

const char* kSchema =
    "CREATE TABLE meta (key TEXT PRIMARY KEY, value TEXT NOT NULL);"
    "CREATE TABLE candidates (id INTEGER PRIMARY KEY, name TEXT NOT NULL, fragments INTEGER, "
    "solved INTEGER,"
    " skipped INTEGER, infeasible INTEGER, unstable INTEGER, mean REAL, leak REAL, dark REAL, max "
    "REAL,"
    " share_over_tenth REAL, max_dark REAL, darkening_bound REAL, darkening_reason TEXT, "
    "view_errors TEXT, histogram TEXT,"
    " seconds REAL);"
    "CREATE TABLE references_ (name TEXT PRIMARY KEY, fragments INTEGER, solved INTEGER, skipped "
    "INTEGER,"
    " infeasible INTEGER, unstable INTEGER, mean REAL, leak REAL, dark REAL, max REAL, "
    "share_over_tenth REAL,"
    " max_dark REAL, darkening_bound REAL, darkening_reason TEXT, view_errors TEXT, histogram "
    "TEXT, seconds REAL);"
    "CREATE TABLE estimates (id INTEGER NOT NULL, stage INTEGER NOT NULL, name TEXT NOT NULL,"
    " mean REAL, se REAL, solved INTEGER, failed INTEGER, run_errors BLOB, seconds REAL,"
    " reach_lower REAL, reach_against INTEGER, PRIMARY KEY (id, stage));";

// Raised whenever the tables change (2: max_dark, darkening_bound, darkening_reason, the reference
// and per-fragment bias of docs/reference.md §3; 3: estimates, of a screened sweep; 4: an
// estimate's run_errors are per screening unit of one texel row, screen/screening.h; 5: an
// estimate screened out by its shard keeps reach_lower and reach_against instead of its run
// errors): an older database is refused, not misread.
constexpr const char* kSchemaVersion = "5";

struct Statement {
  sqlite3_stmt* s = nullptr;
  Statement(sqlite3* db, const std::string& sql, const std::string& path) {
    if (sqlite3_prepare_v2(db, sql.c_str(), -1, &s, nullptr) != SQLITE_OK)
      throw InputError(path + ": " + sqlite3_errmsg(db));
  }
  ~Statement() { sqlite3_finalize(s); }
};

}  // namespace

ResultsStore ResultsStore::create(const std::string& path,
                                  const std::map<std::string, std::string>& meta) {
  namespace fs = std::filesystem;
  if (fs::exists(path)) throw InputError(path + ": results database exists");
  // Schema and metadata are committed under a temporary name, then renamed into place: a kill at
  // any instant leaves either no database or a complete empty one, never one without its schema.
  const fs::path final_path(path),
      dir = final_path.parent_path().empty() ? fs::path(".") : final_path.parent_path();
  const std::string prefix = "." + final_path.filename().string() + ".new-";
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(dir, ec))
    if (entry.path().filename().string().rfind(prefix, 0) == 0) fs::remove(entry.path(), ec);
  const std::string temporary = (dir / (prefix + std::to_string(getpid()))).string();
  {
    sqlite3* db = nullptr;
    if (sqlite3_open_v2(temporary.c_str(), &db, SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE,
                        nullptr) != SQLITE_OK) {
      std::string message = db ? sqlite3_errmsg(db) : "out of memory";
      sqlite3_close(db);
      throw InputError(path + ": cannot create results database: " + message);
    }
    ResultsStore store(db, path);
    store.exec("BEGIN");
    store.exec(kSchema);
    auto rows = meta;
    rows["schema_version"] = kSchemaVersion;
    for (const auto& [key, value] : rows) {
      Statement st(db, "INSERT INTO meta VALUES (?, ?)", path);
      sqlite3_bind_text(st.s, 1, key.c_str(), -1, SQLITE_TRANSIENT);
      sqlite3_bind_text(st.s, 2, value.c_str(), -1, SQLITE_TRANSIENT);
      if (sqlite3_step(st.s) != SQLITE_DONE) throw InputError(path + ": " + sqlite3_errmsg(db));
    }
    store.exec("COMMIT");
  }
  fs::rename(temporary, final_path, ec);
  if (ec) throw InputError(path + ": cannot create results database: " + ec.message());
  return open(path);
}

ResultsStore ResultsStore::open(const std::string& path) {
  if (!std::filesystem::exists(path)) throw InputError(path + ": no results database here");
  sqlite3* db = nullptr;
  if (sqlite3_open_v2(path.c_str(), &db, SQLITE_OPEN_READWRITE, nullptr) != SQLITE_OK) {
    std::string message = db ? sqlite3_errmsg(db) : "out of memory";
    sqlite3_close(db);
    throw InputError(path + ": cannot open results database: " + message);
  }
  sqlite3_busy_timeout(db, 60000);
  ResultsStore store(db, path);
  // A file that is not a momentbench results database (another SQLite file, or none at all).
  char* error = nullptr;
  if (sqlite3_exec(db,
                   "SELECT count(*) FROM meta; SELECT count(*) FROM candidates; SELECT count(*) "
                   "FROM references_",
                   nullptr, nullptr, &error) != SQLITE_OK) {
    sqlite3_free(error);
    throw InputError(
        path +
        ": not a momentbench results database (expected the tables meta, candidates and "
        "references_ that `sweep` writes)");
  }
  const std::string version = store.meta()["schema_version"];
  if (version != kSchemaVersion)
    throw InputError(path + ": written by another momentbench version (results schema " +
                     (version.empty() ? std::string("1") : version) + ", this one reads " +
                     kSchemaVersion + "); re-run its sweep");
  return store;
}

ResultsStore::ResultsStore(ResultsStore&& o) noexcept : db_(o.db_), path_(std::move(o.path_)) {
  o.db_ = nullptr;
}
ResultsStore::~ResultsStore() {
  if (db_) sqlite3_close(db_);
}

void ResultsStore::exec(const std::string& sql) const {
  char* error = nullptr;
  if (sqlite3_exec(db_, sql.c_str(), nullptr, nullptr, &error) != SQLITE_OK) {
    std::string message = error ? error : "unknown error";
    sqlite3_free(error);
    throw InputError(path_ + ": " + message);
  }
}

std::map<std::string, std::string> ResultsStore::meta() const {
  std::map<std::string, std::string> out;
  Statement st(db_, "SELECT key, value FROM meta", path_);
  while (sqlite3_step(st.s) == SQLITE_ROW)
    out[reinterpret_cast<const char*>(sqlite3_column_text(st.s, 0))] =
        reinterpret_cast<const char*>(sqlite3_column_text(st.s, 1));
  return out;
}

std::set<uint64_t> ResultsStore::candidate_ids() const {
  std::set<uint64_t> out;
  Statement st(db_, "SELECT id FROM candidates", path_);
  while (sqlite3_step(st.s) == SQLITE_ROW) out.insert(uint64_t(sqlite3_column_int64(st.s, 0)));
  return out;
}

void ResultsStore::put(const char* table, const ResultRow& row) {
  const bool candidate = std::string(table) == "candidates";
  std::string sql = std::string("INSERT INTO ") + table + " VALUES (" + (candidate ? "?, " : "") +
                    "?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)";
  Statement st(db_, sql, path_);
  int c = 1;
  if (candidate) sqlite3_bind_int64(st.s, c++, int64_t(row.id));
  sqlite3_bind_text(st.s, c++, row.name.c_str(), -1, SQLITE_TRANSIENT);
  for (uint64_t v : {row.fragments, row.solved, row.skipped, row.infeasible, row.unstable})
    sqlite3_bind_int64(st.s, c++, int64_t(v));
  for (double v : {row.mean, row.leak, row.dark, row.max, row.share_over_tenth, row.max_dark,
                   row.darkening_bound})
    sqlite3_bind_double(st.s, c++, v);
  sqlite3_bind_text(st.s, c++, row.darkening_reason.c_str(), -1, SQLITE_TRANSIENT);
  sqlite3_bind_text(st.s, c++, row.view_errors.c_str(), -1, SQLITE_TRANSIENT);
  sqlite3_bind_text(st.s, c++, row.histogram.c_str(), -1, SQLITE_TRANSIENT);
  sqlite3_bind_double(st.s, c++, row.seconds);
  if (sqlite3_step(st.s) != SQLITE_DONE)
    throw InputError(path_ + ": cannot store '" + row.name + "': " + sqlite3_errmsg(db_));
}

void ResultsStore::put_candidate(const ResultRow& row) {
  put("candidates", row);
}
void ResultsStore::put_reference(const ResultRow& row) {
  put("references_", row);
}

std::vector<ResultRow> ResultsStore::rows(const char* table, const char* order) const {
  const bool candidate = std::string(table) == "candidates";
  Statement st(db_, std::string("SELECT * FROM ") + table + " ORDER BY " + order, path_);
  std::vector<ResultRow> out;
  while (sqlite3_step(st.s) == SQLITE_ROW) {
    ResultRow r;
    int c = 0;
    if (candidate) r.id = uint64_t(sqlite3_column_int64(st.s, c++));
    r.name = reinterpret_cast<const char*>(sqlite3_column_text(st.s, c++));
    for (uint64_t* v : {&r.fragments, &r.solved, &r.skipped, &r.infeasible, &r.unstable})
      *v = uint64_t(sqlite3_column_int64(st.s, c++));
    for (double* v :
         {&r.mean, &r.leak, &r.dark, &r.max, &r.share_over_tenth, &r.max_dark, &r.darkening_bound})
      *v = sqlite3_column_double(st.s, c++);
    r.darkening_reason = reinterpret_cast<const char*>(sqlite3_column_text(st.s, c++));
    r.view_errors = reinterpret_cast<const char*>(sqlite3_column_text(st.s, c++));
    r.histogram = reinterpret_cast<const char*>(sqlite3_column_text(st.s, c++));
    r.seconds = sqlite3_column_double(st.s, c++);
    out.push_back(std::move(r));
  }
  return out;
}

std::vector<ResultRow> ResultsStore::candidates() const {
  return rows("candidates", "id");
}
std::vector<ResultRow> ResultsStore::references() const {
  return rows("references_", "name");
}

std::set<uint64_t> ResultsStore::estimate_ids(int stage) const {
  std::set<uint64_t> out;
  Statement st(db_, "SELECT id FROM estimates WHERE stage = " + std::to_string(stage), path_);
  while (sqlite3_step(st.s) == SQLITE_ROW) out.insert(uint64_t(sqlite3_column_int64(st.s, 0)));
  return out;
}

void ResultsStore::put_estimate(const EstimateRow& row) {
  Statement st(db_, "INSERT OR REPLACE INTO estimates VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)",
               path_);
  sqlite3_bind_int64(st.s, 1, int64_t(row.id));
  sqlite3_bind_int64(st.s, 2, row.stage);
  sqlite3_bind_text(st.s, 3, row.name.c_str(), -1, SQLITE_TRANSIENT);
  sqlite3_bind_double(st.s, 4, row.mean);
  sqlite3_bind_double(st.s, 5, row.se);
  sqlite3_bind_int64(st.s, 6, int64_t(row.solved));
  sqlite3_bind_int64(st.s, 7, int64_t(row.failed));
  if (row.screened_out)
    sqlite3_bind_null(st.s, 8);
  else
    sqlite3_bind_blob(st.s, 8, row.run_errors.data(), int(row.run_errors.size() * sizeof(double)),
                      SQLITE_TRANSIENT);
  sqlite3_bind_double(st.s, 9, row.seconds);
  if (row.screened_out) {
    sqlite3_bind_double(st.s, 10, row.reach_lower);
    sqlite3_bind_int64(st.s, 11, int64_t(row.reach_against));
  } else {
    sqlite3_bind_null(st.s, 10);
    sqlite3_bind_null(st.s, 11);
  }
  if (sqlite3_step(st.s) != SQLITE_DONE)
    throw InputError(path_ + ": cannot store the estimate of '" + row.name +
                     "': " + sqlite3_errmsg(db_));
}

namespace {

// The run_errors blob of column `c` (empty when NULL).
std::vector<double> blob_doubles(sqlite3_stmt* s, int c, const std::string& path, uint64_t id) {
  const auto* bytes = static_cast<const char*>(sqlite3_column_blob(s, c));
  const size_t size = size_t(sqlite3_column_bytes(s, c));
  if (size % sizeof(double))
    throw InputError(path + ": the estimate of candidate " + std::to_string(id) +
                     " has a damaged run_errors blob");
  std::vector<double> out(size / sizeof(double));
  if (size) std::memcpy(out.data(), bytes, size);
  return out;
}

}  // namespace

std::vector<EstimateRow> ResultsStore::estimates(int stage, bool run_errors) const {
  Statement st(db_,
               std::string("SELECT id, stage, name, mean, se, solved, failed, ") +
                   (run_errors ? "run_errors" : "NULL") +
                   ", seconds, reach_lower, reach_against FROM estimates" +
                   (stage ? " WHERE stage = " + std::to_string(stage) : std::string()) +
                   " ORDER BY id, stage",
               path_);
  std::vector<EstimateRow> out;
  while (sqlite3_step(st.s) == SQLITE_ROW) {
    EstimateRow r;
    r.id = uint64_t(sqlite3_column_int64(st.s, 0));
    r.stage = int(sqlite3_column_int64(st.s, 1));
    r.name = reinterpret_cast<const char*>(sqlite3_column_text(st.s, 2));
    r.mean = sqlite3_column_double(st.s, 3);
    r.se = sqlite3_column_double(st.s, 4);
    r.solved = uint64_t(sqlite3_column_int64(st.s, 5));
    r.failed = uint64_t(sqlite3_column_int64(st.s, 6));
    r.run_errors = blob_doubles(st.s, 7, path_, r.id);
    r.seconds = sqlite3_column_double(st.s, 8);
    r.screened_out = sqlite3_column_type(st.s, 10) != SQLITE_NULL;
    if (r.screened_out) {
      r.reach_lower = sqlite3_column_double(st.s, 9);
      r.reach_against = uint64_t(sqlite3_column_int64(st.s, 10));
    }
    out.push_back(std::move(r));
  }
  return out;
}

std::vector<EstimateRow> ResultsStore::latest_estimates() const {
  std::vector<EstimateRow> all = estimates(0, false);  // by id, then stage
  std::vector<EstimateRow> out;
  for (size_t i = 0; i < all.size(); ++i)
    if (i + 1 == all.size() || all[i + 1].id != all[i].id) out.push_back(std::move(all[i]));
  return out;
}

std::vector<double> ResultsStore::run_errors(uint64_t id, int stage) const {
  Statement st(db_, "SELECT run_errors FROM estimates WHERE id = ? AND stage = ?", path_);
  sqlite3_bind_int64(st.s, 1, int64_t(id));
  sqlite3_bind_int64(st.s, 2, stage);
  if (sqlite3_step(st.s) != SQLITE_ROW)
    throw InputError(path_ + ": no stage " + std::to_string(stage) + " estimate of candidate " +
                     std::to_string(id));
  return blob_doubles(st.s, 0, path_, id);
}

void ResultsStore::screen_out(int stage, const std::vector<EstimateRow>& rows) {
  if (!rows.empty())
    batch([&] {
      Statement st(db_,
                   "UPDATE estimates SET run_errors = NULL, reach_lower = ?, reach_against = ? "
                   "WHERE id = ? AND stage = ?",
                   path_);
      for (const EstimateRow& r : rows) {
        sqlite3_reset(st.s);
        sqlite3_bind_double(st.s, 1, r.reach_lower);
        sqlite3_bind_int64(st.s, 2, int64_t(r.reach_against));
        sqlite3_bind_int64(st.s, 3, int64_t(r.id));
        sqlite3_bind_int64(st.s, 4, stage);
        if (sqlite3_step(st.s) != SQLITE_DONE)
          throw InputError(path_ + ": cannot screen out candidate " + std::to_string(r.id) + ": " +
                           sqlite3_errmsg(db_));
      }
    });
  // The dropped unit errors' space goes back to the file system, also when a kill came between the
  // commit above and the end of an earlier VACUUM (which is atomic). Unit errors of a few hundred
  // units fit inside their table pages: dropping them leaves those pages sparse without freeing
  // any, so anything dropped here is reason enough to VACUUM, not only free pages.
  int64_t free = 0;
  {  // finalized before VACUUM, which refuses to run beside an open statement
    Statement pages(db_, "PRAGMA freelist_count", path_);
    if (sqlite3_step(pages.s) == SQLITE_ROW) free = sqlite3_column_int64(pages.s, 0);
  }
  if (free > 0 || !rows.empty()) exec("VACUUM");
}

std::string results_database_path(const std::string& given) {
  namespace fs = std::filesystem;
  const bool file = fs::is_regular_file(given) ||
                    (given.size() >= 7 && given.compare(given.size() - 7, 7, ".sqlite") == 0);
  return !fs::is_directory(given) && file ? given : (fs::path(given) / "results.sqlite").string();
}

ResultRow make_result_row(uint64_t id, const std::string& name, const ErrorStats& s,
                          const std::vector<std::pair<std::string, double>>& view_errors) {
  ResultRow r;
  r.id = id;
  r.name = name;
  r.fragments = s.count;
  r.mean = s.mean();
  r.leak = s.leak();
  r.dark = s.dark();
  r.max = s.max;
  r.share_over_tenth = s.share_over_tenth();
  r.max_dark = s.max_dark;
  nlohmann::ordered_json views = nlohmann::ordered_json::object();
  for (const auto& [view, error] : view_errors) views[view] = error;
  r.view_errors = views.dump();
  std::ostringstream h;
  for (size_t b = 0; b < s.histogram.size(); ++b) h << (b ? "," : "") << s.histogram[b];
  r.histogram = h.str();
  return r;
}

}  // namespace mb
