// `momentbench report`: a sweep's results database -> ranked table, reference techniques, rank of
// the power and trigonometric bases, histogram CSV, and the Figure 4-style plot (issue 5).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <sstream>

#include "cmd/command_common.h"
#include "cmd/commands.h"
#include "eval/error_stats.h"
#include "eval/results_store.h"
#include "moments/basis.h"
#include "util/error.h"
#include "util/output_dir.h"

namespace mb {

namespace {

struct ReportOptions {
  std::string results, out;
  bool force = false, quiet = false, plot = true;
  int bins = 60;
};

std::string row_line(size_t rank, const ResultRow& r) {
  std::ostringstream s;
  s << "| " << rank << " | " << r.id << " | " << r.name << " | " << percent_text(r.mean) << " | " << percent_text(r.leak) << " | "
    << percent_text(r.dark) << " | " << r.solved << " | " << (r.infeasible + r.unstable) << " |";
  return s.str();
}

// A candidate's name as the sweep writes it ("f1; f2; ..."), for a named basis set.
std::string candidate_name(const std::string& set) {
  std::string name;
  for (const auto& f : named_basis_set(set)) name += (name.empty() ? "" : "; ") + f;
  return name;
}

int run_report(const ReportOptions& o) {
  std::string db = std::filesystem::is_directory(o.results)
                       ? (std::filesystem::path(o.results) / "results.sqlite").string()
                       : o.results;
  ResultsStore store = ResultsStore::open(db);
  auto meta = store.meta();
  auto candidates = store.candidates();
  auto references = store.references();
  if (candidates.empty()) throw InputError(db + ": no candidates evaluated yet");
  StagedOutputDir out(o.out, o.force);

  // Ranked by mean error; ties by id, so the order is reproducible.
  std::vector<ResultRow> ranked = candidates;
  std::stable_sort(ranked.begin(), ranked.end(), [](const auto& a, const auto& b) { return a.mean < b.mean; });
  auto rank_of = [&](double mean) {
    return size_t(std::count_if(ranked.begin(), ranked.end(), [&](const auto& r) { return r.mean < mean; })) + 1;
  };

  std::ostringstream md, csv, refs, hist;
  md << "# Sweep report\n\n"
     << "- results: `" << db << "`, dataset " << meta["dataset"] << ", config hash " << meta["config_hash"]
     << ", shard " << meta["shard"] << "\n- " << meta["settings"] << "\n- candidates evaluated: " << candidates.size()
     << " of " << meta["planned"] << " planned (combinations of " << meta["combination_size"] << " from "
     << meta["catalog_size"] << " functions)\n\n";
  uint64_t failures = 0, lps = 0;
  for (const auto& r : candidates) failures += r.infeasible + r.unstable, lps += r.solved + r.infeasible + r.unstable;
  md << "- LPs: " << lps << ", of which infeasible or unstable: " << failures << " ("
     << percent_text(lps ? double(failures) / lps : 0) << " %; these fragments count as lit)\n\n";

  md << "## Reference techniques on the same dataset\n\n| technique | mean error % | leak % | over-darkening % | "
        "rank among candidates |\n|---|---|---|---|---|\n";
  refs << "technique,mean_error,leak,over_darkening\n";
  for (const auto& r : references) {
    md << "| " << r.name << " | " << percent_text(r.mean) << " | " << percent_text(r.leak) << " | " << percent_text(r.dark) << " | "
       << (r.name == "pcf" ? std::string("-") : std::to_string(rank_of(r.mean))) << " |\n";
    refs << '"' << r.name << "\"," << r.mean << "," << r.leak << "," << r.dark << "\n";
  }
  md << "\n## Power and trigonometric bases among the candidates\n\n";
  for (const auto& [label, set] : {std::pair{"power moments", "power4"}, std::pair{"trigonometric moments", "trig4"}}) {
    const std::string name = candidate_name(set), reference = std::string("lp:") + set;
    auto it = std::find_if(candidates.begin(), candidates.end(), [&](const auto& r) { return r.name == name; });
    auto ref = std::find_if(references.begin(), references.end(), [&](const auto& r) { return r.name == reference; });
    if (it == candidates.end() && ref == references.end()) continue;
    double mean = it != candidates.end() ? it->mean : ref->mean;
    const size_t better = rank_of(mean) - 1;
    md << "- " << label << " (" << name << "): mean error " << percent_text(mean) << " %; " << better << " of "
       << candidates.size() << " candidates are better (percentile " << percent_text(double(better) / candidates.size())
       << ")"
       << (it == candidates.end() ? ", from the reference row (not among the evaluated candidates)" : "") << "\n";
  }
  const std::string header = "| rank | id | functions | mean error % | leak % | over-darkening % | LPs solved | failed |\n"
                             "|---|---|---|---|---|---|---|---|\n";
  md << "\n## Best 50 candidates\n\n" << header;
  for (size_t i = 0; i < std::min<size_t>(50, ranked.size()); ++i) md << row_line(i + 1, ranked[i]) << "\n";
  md << "\n## Worst 10 candidates\n\n" << header;
  for (size_t i = ranked.size() > 10 ? ranked.size() - 10 : 0; i < ranked.size(); ++i)
    md << row_line(i + 1, ranked[i]) << "\n";

  csv << "rank,id,functions,mean_error,leak,over_darkening,max_error,share_over_0.1,fragments,solved,skipped,"
         "infeasible,unstable,view_errors\n";
  for (size_t i = 0; i < ranked.size(); ++i) {
    const auto& r = ranked[i];
    std::string views = r.view_errors;
    std::replace(views.begin(), views.end(), '"', '\'');
    csv << i + 1 << "," << r.id << ",\"" << r.name << "\"," << r.mean << "," << r.leak << "," << r.dark << "," << r.max
        << "," << r.share_over_tenth << "," << r.fragments << "," << r.solved << "," << r.skipped << ","
        << r.infeasible << "," << r.unstable << ",\"" << views << "\"\n";
  }
  // Histogram of candidates' mean errors (the seed paper's Figure 4), over [best, worst].
  const double lo = ranked.front().mean, hi = std::max(ranked.back().mean, lo + 1e-12);
  std::vector<uint64_t> counts(o.bins, 0);
  for (const auto& r : ranked) counts[std::min(o.bins - 1, int((r.mean - lo) / (hi - lo) * o.bins))]++;
  hist << "error_lo,error_hi,candidates\n";
  for (int b = 0; b < o.bins; ++b)
    hist << lo + (hi - lo) * b / o.bins << "," << lo + (hi - lo) * (b + 1) / o.bins << "," << counts[b] << "\n";

  write_file_atomically(out / "candidates.csv", csv.str());
  write_file_atomically(out / "references.csv", refs.str());
  write_file_atomically(out / "histogram.csv", hist.str());
  std::string plot_note;
  if (o.plot)
    plot_note = run_plot_script("plot_histogram.py",
                                "--histogram '" + (out / "histogram.csv").string() + "' --references '" +
                                    (out / "references.csv").string() + "'",
                                (out / "histogram").string(), "candidate histogram", o.quiet);
  std::string text = md.str();
  text.insert(text.find("## Reference techniques"), "## Histogram\n\n" + plot_note);
  write_file_atomically(out / "report.md", text);
  out.commit();
  std::fputs(text.c_str(), stdout);
  return 0;
}

}  // namespace

void register_report_command(CLI::App& app, std::function<int()>& action) {
  auto options = std::make_shared<ReportOptions>();
  CLI::App* command = app.add_subcommand("report", "Ranked table, histogram and plot from a sweep's results");
  command->add_option("results", options->results, "Sweep output directory (or its results.sqlite)")->required();
  command->add_option("-o,--out", options->out, "Report directory (must not exist, unless --force)")->required();
  command->add_flag("-f,--force", options->force, "Replace an existing report directory");
  command->add_flag("-q,--quiet", options->quiet, "Nothing on stderr");
  command->add_flag("!--no-plot", options->plot, "Do not call scripts/plot_histogram.py");
  command->add_option("--bins", options->bins, "Histogram bins")->check(CLI::Range(1, 10000));
  command->callback([options, &action] { action = [options] { return run_report(*options); }; });
}

}  // namespace mb
