#include "report/verify_report.h"

#include <algorithm>
#include <cstdio>
#include <sstream>

#include "util/name_list.h"
#include "util/number_text.h"

namespace mb {

namespace {

std::string num(double v) {
  return format_number(v, "%.3g");
}
std::string full(double v) {
  return round_trip(v);
}
// A ground truth's column name: a grid size, or 0 for the continuous interval.
std::string ground_truth(int grid) {
  return grid ? "grid " + std::to_string(grid) : std::string("continuous");
}
std::string joined(const std::vector<double>& v, const char* separator) {
  std::string s;
  for (size_t i = 0; i < v.size(); ++i) s += (i ? separator : "") + full(v[i]);
  return s;
}

std::string verdict(const VerifySolverResult& r) {
  if (r.target.exceedance)
    return "reported (not a lower bound: above the sharp bound on " +
           std::to_string(r.above_finest) + " instances and " + std::to_string(r.above_lp) +
           " LP witnesses, by up to " + num(std::max(0.0, r.largest_excess)) + ")";
  if (!r.judged()) return "reported (bias)";
  if (r.box_judged) {
    if (r.passed()) return "pass (below its storage box)";
    return std::string(r.decides_exit() ? "**FAIL**" : "**exceeds its storage box**") +
           " (by up to " + num(r.largest_excess) + ")";
  }
  return (r.passed() ? "pass" : "**FAIL**") +
         (r.target.lower_bound
              ? " (lower bound: " + std::to_string(r.above_finest) + " above the LP)"
              : std::string());
}

}  // namespace

namespace {

// Three lines before the rules and tables: what ran, the verdicts, what needs attention.
std::string summary_lines(std::span<const VerifySolverResult> results,
                          std::span<const VerifyInstance> instances, bool continuous) {
  size_t passed = 0, reported = 0;
  std::string failed, noted;
  for (const auto& r : results) {
    if (!r.judged())
      ++reported;
    else if (r.passed())
      ++passed;
    else if (r.decides_exit())
      failed += (failed.empty() ? "" : ", ") + r.target.technique;
    else
      noted += (noted.empty() ? "" : ", ") + r.target.technique;
  }
  std::string attention = failed.empty() ? "" : "**" + failed + " fail**";
  // The failing row's instance furthest beyond its allowance, so that the summary names it.
  for (const auto& r : results)
    if (r.judged() && !r.passed() && r.decides_exit() && !r.worst_outside.empty() &&
        r.worst_outside.front().beyond() > 0) {
      const VerifyJudgement& j = r.worst_outside.front();
      attention += " (" + r.target.technique + " furthest: instance " +
                   std::to_string(j.c.instance) + ", " + instances[j.c.instance].source + ", " +
                   (j.upper ? "G+ " : "G ") + num(j.closed_form) + " outside [" + num(j.lo) + ", " +
                   num(j.hi) + "] by " + num(j.outside()) + ", allowed " + num(j.allowed) + ")";
    }
  if (!noted.empty())
    attention += (attention.empty() ? "" : "; ") + noted +
                 " exceed their storage box (quantization noise, reported: seed 000 §4.3)";
  std::ostringstream s;
  s << "**Summary.** " << results.size() << " closed forms against the LP on " << instances.size()
    << " instances, ground truth " << (continuous ? "the continuous interval" : "the finest grid")
    << ".  \n"
    << passed << " pass, " << reported << " reported without a verdict (biased, or not lower "
    << "bounds), " << results.size() - passed - reported << " do not pass.  \nNeeds attention: "
    << (attention.empty() ? std::string("nothing") : attention) << ".\n\n";
  return s.str();
}

void write_pass_rule(std::ostream& md, const VerifyReportContext& ctx, bool continuous);
void write_storage_rule(std::ostream& md, std::span<const VerifySolverResult> results);
void write_rounding_box_rule(std::ostream& md, std::span<const VerifySolverResult> results);

// What was run and how it is judged.
void write_header(std::ostream& md, const VerifyReportContext& ctx,
                  std::span<const VerifySolverResult> results,
                  std::span<const VerifyInstance> instances, bool continuous) {
  md << "# Closed forms against the LP (docs/reference.md §6)\n\n"
     << "Made by momentbench " << ctx.version << " (git " << ctx.git_sha << "), " << ctx.threads
     << " threads, " << ctx.started << ".\n\n"
     << summary_lines(results, instances, continuous) << "- " << ctx.random_count
     << " seeded random distributions (seed " << ctx.seed << "; 1-8 atoms, two-bump mixtures), "
     << instances.size() - ctx.random_count << " real receiver kernels of dataset " << ctx.dataset
     << " (at z_f - delta_f, delta_f = " << num(ctx.bias.constant) << " + " << num(ctx.bias.slope)
     << " * " << ctx.kernel_radius << " * (|dz/dx| + |dz/dy|))\n"
     << "- The LP sees the exact distribution (its depths join the grid); the closed form sees its "
        "moments as its "
        "map stores them. Exact solvers run with alpha = 0; float/16-bit ones with their own "
        "bias.\n"
     << (continuous
             ? "- Ground truth: Problem 1 on the whole interval (R for Hamburger and VSM) by the "
               "exchange method, power bases in the distribution's local coordinates "
               "(docs/reference.md §2). Its certificate brackets G in [lower, G]: |dG| is measured "
               "to "
               "G, judged from the bracket; `unproven`: a basis of expressions, whose certificate "
               "samples instead of proving.\n"
             : "");
  write_pass_rule(md, ctx, continuous);
  write_storage_rule(md, results);
  write_rounding_box_rule(md, results);
}

// When a closed form passes: within the tolerance plus its rounding allowance, never above a
// witness.
void write_pass_rule(std::ostream& md, const VerifyReportContext& ctx, bool continuous) {
  md << "- Pass: on the " << (continuous ? "continuous ground truth" : "finest grid")
     << " |dG| <= " << num(ctx.tolerance)
     << " plus the instance's rounding allowance (the first-order change of G when the moments "
        "are rounded to double, from the certificate's coefficients: the closed form reads "
        "rounded moments) for every instance, and never above an LP witness: each LP optimum is a "
        "distribution on "
        "I (its moments "
        "miss the instance's by the LP tolerance, which near singular moments moves G by more than "
     << round_trip(kAboveLpSlack)
     << "), so the closed form evaluated on that distribution's own moments must not exceed its "
        "mass below z_f by more than "
     << round_trip(kAboveLpSlack)
     << ". Undefined: the closed form gave no number (singular moments at alpha = 0).\n\n";
}

// How the float32 and 16-bit rows are judged: against the box of their storage's rounding.
void write_storage_rule(std::ostream& md, std::span<const VerifySolverResult> results) {
  md << (std::any_of(results.begin(), results.end(),
                     [](const VerifySolverResult& r) { return r.box_judged; })
             ? "- Storage rows (float32, 16-bit): their continuous column is Problem 1 over every "
               "distribution on [0, 1] whose stored values lie within the format's rounding of "
               "the ones the closed form read (docs/reference.md §2 \"Moments with a tolerance\"; "
               "float32: 2^-24 max |b_j|, 16-bit: half a step of theta_4's coordinates). A "
               "storage variant passes when it never exceeds that box's G, nor an LP witness's "
               "mass, by more than its bias alpha + " +
                   round_trip(kAboveLpSlack) +
                   " (the biased moments are a mixture's). "
                   "Seed 000 §4.3 reports quantization noise at these alphas, so exceeding is "
                   "reported, not failed, unless verify.moment_box = strict.\n"
             : "");
}

// How six moments are judged: over their double rounding box (verify/rounding_box.h).
void write_rounding_box_rule(std::ostream& md, std::span<const VerifySolverResult> results) {
  for (const auto& r : results)
    if (r.target.rounding_box && !r.grids.empty() && r.grids.back().grid == 0)
      md << "- " << r.target.technique
         << ": over the double rounding box of its moments. Problem 1 at the moments the "
            "closed form read (not the kernel's own: for narrow kernels rounding six moments "
            "moves G by up to ~0.02) lies between the exact moments' certificate applied to them "
            "and a 50-digit witness distribution with exactly those moments; judged is the "
            "closed form's distance outside that bracket (largest: "
         << num(r.box_max_outside) << "). " << r.unwitnessed
         << " instances whose read moments have no witness (singular, or outside the moment "
            "cone) are judged against the exact moments' LP as above.\n";
}

// One row per solver in verify.md and one per solver and grid in verify.csv; true when every
// solver that decides the exit status passed.
bool write_summary(std::ostream& md, std::ostream& csv, const VerifyReportContext& ctx,
                   std::span<const VerifySolverResult> results, bool continuous) {
  md << "| technique | LP basis | interval | instances | undefined |";
  for (int g : ctx.grids) md << " " << ground_truth(g) << ": max / mean abs dG |";
  if (continuous) md << " widest bracket | brackets > 1e-6 | unproven |";
  md << " beyond tol. | above witness | verdict |\n|---|---|---|---|---|";
  for (size_t k = 0; k < ctx.grids.size() + (continuous ? 3 : 0); ++k) md << "---|";
  md << "---|---|---|\n";
  csv << "technique,lp_basis,lo,hi,grid,instances,undefined,compared,lp_failures,max_abs_dG,mean_"
         "abs_dG,beyond_tolerance,"
         "above_lp,exact,passed\n";
  bool all_passed = true;
  for (const auto& r : results) {
    const std::string basis = mb::joined(r.target.lp_basis, ",");
    md << "| " << r.target.technique << " | " << basis << " | [" << num(r.target.lo) << ", "
       << num(r.target.hi) << "]" << (r.box_judged ? "; box [0, 1]" : "") << " | " << r.instances
       << " | " << r.undefined << " |";
    for (const auto& g : r.grids)
      md << " " << num(g.max_difference) << " / " << num(g.mean_difference) << " |";
    if (continuous)
      md << " " << num(r.widest_bracket) << " | " << r.unresolved << " | " << r.unproven << " |";
    md << " " << r.beyond_tolerance << " | " << r.above_lp << " | " << verdict(r) << " |\n";
    for (const auto& g : r.grids)
      csv << r.target.technique << ",\"" << basis << "\"," << full(r.target.lo) << ","
          << full(r.target.hi) << "," << g.grid << "," << r.instances << "," << r.undefined << ","
          << g.compared << "," << g.lp_failures << "," << full(g.max_difference) << ","
          << full(g.mean_difference) << "," << r.beyond_tolerance << "," << r.above_lp << ","
          << (r.judged() ? 1 : 0) << "," << (r.passed() ? 1 : 0) << "\n";
    all_passed = all_passed && (r.passed() || !r.decides_exit());
  }
  return all_passed;
}

// Hamburger's upper bounds against the LP's maximum (VerifyTarget::upper).
void write_upper_bounds(std::ostream& md, std::span<const VerifySolverResult> results) {
  bool any = false;
  for (const auto& r : results) any = any || r.target.upper;
  if (!any) return;
  md << "\n## Upper bounds against the LP's maximum\n\n"
        "Hamburger's upper bound G + w_1 (seed 004's beta = 1: the canonical distribution's weight "
        "at z_f added) against the maximum of the mass at or in front of z_f over the finest grid "
        "with the canonical nodes added (docs/reference.md §2). Where a node lies beyond ten "
        "interval widths the LP's maximum may only be lower, and only that is judged. Both in the "
        "kernel's "
        "local coordinates (verification.cpp, solve_upper). Six moments: G + w_1 on the moments "
        "the closed form read, judged against G+ there, bracketed by the mirrored problem's "
        "certificate and 50-digit witnesses (verify/rounding_box.h; max abs dG+ is the distance "
        "outside that bracket).\n\n"
        "| technique | compared | node beyond reach | max abs dG+ | beyond tol. | verdict |\n"
        "|---|---|---|---|---|---|\n";
  for (const auto& r : results)
    if (r.target.upper)
      md << "| " << r.target.technique << " | " << r.upper_compared << " | " << r.upper_limited
         << " | " << num(r.upper_max_difference) << " | " << r.upper_beyond << " | "
         << (!r.target.upper_judged ? "reported"
             : r.upper_beyond       ? "**FAIL**"
                                    : "pass")
         << " |\n";
}

// The worst cases per solver in verify.md (with `solve` commands to re-run them) and worst.csv.
void write_worst_cases(std::ostream& md, std::ostream& worst, const VerifyReportContext& ctx,
                       std::span<const VerifySolverResult> results,
                       std::span<const VerifyInstance> instances, bool continuous) {
  worst << "technique,kind,rank,source,zf,moments,depths,weights,G_closed_form";
  for (int g : ctx.grids) worst << ",G_lp_" << (g ? std::to_string(g) : "continuous");
  worst << ",G_lp_exact,bracket_lo,bracket_hi,allowed,outside\n";
  md << "\n## Worst cases\n\nPer solver: the instances outside the bracket the verdict judges "
        "them against, failures first (beyond > 0: beyond the allowance), then by distance "
        "(`outside`/`outside_upper` in "
        "worst.csv, with the bracket, allowance and distance), the largest |dG| on the finest "
        "grid, then (if any) the cases furthest above an LP. Re-run one with the printed `solve` "
        "commands (closed form, then the LP with the "
        "distribution's depths "
        "as extra points). `G exact LP` is the finest grid's LP solved in rational arithmetic "
        "(the arbiter, docs/lp-engine.md): where it differs from the grid's column, the double "
        "LP is off, not the closed form.\n";
  // One table (and its worst.csv rows) per list of cases; `kind` names the ordering.
  const auto write_cases = [&](const VerifySolverResult& r, const std::vector<VerifyCase>& cases,
                               const char* kind, const char* heading) {
    if (cases.empty()) return;
    md << "\n### " << r.target.technique << ": " << heading
       << "\n\n| rank | source | z_f | G closed form |";
    for (int g : ctx.grids) md << " G LP " << ground_truth(g) << " |";
    md << " G exact LP |\n|---|---|---|---|---|";
    for (size_t k = 0; k < ctx.grids.size(); ++k) md << "---|";
    md << "\n";
    for (size_t k = 0; k < cases.size(); ++k) {
      const VerifyCase& c = cases[k];
      const VerifyInstance& inst = instances[c.instance];
      md << "| " << k + 1 << " | " << inst.source << " | " << full(inst.zf) << " | "
         << full(c.closed_form) << " |";
      for (double g : c.lp) md << " " << full(g) << " |";
      md << " " << full(c.lp_exact) << " |\n";
      worst << r.target.technique << "," << kind << "," << k + 1 << ",\"" << inst.source << "\","
            << full(inst.zf) << ",\"" << joined(c.moments, " ") << "\",\""
            << joined(inst.depths, " ") << "\",\"" << joined(inst.weights, " ") << "\","
            << full(c.closed_form);
      for (double g : c.lp) worst << "," << full(g);
      worst << "," << full(c.lp_exact) << ",,,,\n";
    }
    const std::string basis = mb::joined(r.target.lp_basis, ",");
    const VerifyCase& c = cases.front();
    const VerifyInstance& inst = instances[c.instance];
    md << "\n```\nmomentbench solve --technique " << r.target.technique
       << (r.target.exact ? " --alpha 0" : "") << " --moments " << joined(c.moments, ",")
       << " --zf " << full(inst.zf) << "\nmomentbench solve --basis '" << basis << "' --interval "
       << num(r.target.lo) << "," << num(r.target.hi) << " --grid "
       << ctx.grids[ctx.grids.size() - (continuous && ctx.grids.size() > 1 ? 2 : 1)] << " --zf "
       << full(inst.zf) << " --points " << joined(inst.depths, ",")
       << " --moments <E[b] of those points>\n```\n";
  };
  // The judged brackets: failures first, then the instances furthest outside (keep_worst_outside).
  const auto write_outside = [&](const VerifySolverResult& r) {
    if (r.worst_outside.empty()) return;
    md << "\n### " << r.target.technique
       << ": furthest outside the judged bracket\n\n| rank | instance | source | z_f | bound | "
          "closed form | judged bracket | against | distance outside | allowed | beyond |\n"
          "|---|---|---|---|---|---|---|---|---|---|---|\n";
    for (size_t k = 0; k < r.worst_outside.size(); ++k) {
      const VerifyJudgement& j = r.worst_outside[k];
      const VerifyInstance& inst = instances[j.c.instance];
      const char* against = j.read_box ? "read moments' box" : "LP";
      md << "| " << k + 1 << " | " << j.c.instance << " | " << inst.source << " | " << full(inst.zf)
         << " | " << (j.upper ? "G+" : "G") << " | " << full(j.closed_form) << " | [" << full(j.lo)
         << ", " << full(j.hi) << "] | " << against << " | " << num(j.outside()) << " | "
         << num(j.allowed) << " | "
         << (j.beyond() > 0 ? "**" + num(j.beyond()) + "**" : num(j.beyond())) << " |\n";
      worst << r.target.technique << "," << (j.upper ? "outside_upper" : "outside") << "," << k + 1
            << ",\"" << inst.source << "\"," << full(inst.zf) << ",\"" << joined(j.c.moments, " ")
            << "\",\"" << joined(inst.depths, " ") << "\",\"" << joined(inst.weights, " ") << "\","
            << full(j.closed_form);
      for (double g : j.c.lp) worst << "," << full(g);
      worst << "," << full(j.c.lp_exact) << "," << full(j.lo) << "," << full(j.hi) << ","
            << full(j.allowed) << "," << full(j.outside()) << "\n";
    }
  };
  for (const auto& r : results) {
    write_outside(r);
    write_cases(r, r.worst, "largest_dG", "largest |dG| on the finest grid");
    write_cases(r, r.worst_above, "above_lp", "furthest above an LP witness");
  }
}

}  // namespace

VerifyReport render_verify_report(const VerifyReportContext& ctx,
                                  std::span<const VerifySolverResult> results,
                                  std::span<const VerifyInstance> instances) {
  std::ostringstream md, csv, worst;
  const bool continuous = !ctx.grids.empty() && ctx.grids.back() == 0;
  write_header(md, ctx, results, instances, continuous);
  const bool all_passed = write_summary(md, csv, ctx, results, continuous);
  write_upper_bounds(md, results);
  write_worst_cases(md, worst, ctx, results, instances, continuous);
  return {md.str(), csv.str(), worst.str(), all_passed};
}

}  // namespace mb
