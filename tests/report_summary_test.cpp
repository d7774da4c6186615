// Reports open with three lines (what ran, the headline numbers, what needs attention) before
// any table; attention names failed fragments and an exact technique above its proven bound, and
// nothing else.
#include <gtest/gtest.h>

#include <limits>

#include "report/eval_report.h"

namespace mb {
namespace {

EvalRow row(const std::string& technique, double pcf, double g, double bound) {
  EvalRow r;
  r.technique = technique;
  r.scene = "all";
  r.stats.add(pcf, g);
  r.darkening_bound = bound;
  return r;
}

std::string summary_of(const std::vector<EvalRow>& rows) {
  EvalReportContext ctx;
  ctx.dataset = "tiny";
  ctx.views = 4;
  ctx.receivers = 1;
  const std::string md = render_eval_report(ctx, rows, {}, {}).markdown;
  const size_t begin = md.find("**Summary.**"), tables = md.find("## All views");
  EXPECT_NE(begin, std::string::npos);
  EXPECT_LT(begin, tables);
  EXPECT_LT(begin, md.find("- option"));  // before the settings, right under the title
  return md.substr(begin, md.find("\n\n", begin) - begin);
}

TEST(ReportSummary, NamesWhatRanTheLowestErrorAndNothingToAttendTo) {
  const std::string s = summary_of(
      {row("pcf", 0.5, 0.5, 0), row("vsm", 0.5, 0.3, 0), row("hamburger4", 0.5, 0.4, 0)});
  EXPECT_NE(s.find("3 techniques on dataset tiny: 4 views, 1 receivers"), std::string::npos) << s;
  EXPECT_NE(s.find("vsm 20.0000 %"), std::string::npos) << s;
  EXPECT_NE(s.find("(lowest: hamburger4)"), std::string::npos) << s;  // pcf is the reference
  EXPECT_NE(s.find("Needs attention: nothing."), std::string::npos) << s;
}

TEST(ReportSummary, FlagsFailuresAndABrokenBoundButNotADeclaredOverDarkening) {
  EvalRow failed = row("lp:power4", 0.5, 0.4, 1e-9);
  failed.stats.failures = 3;
  const EvalRow broken = row("hamburger4", 0.5, 0.6, 1e-10);  // 0.1 above a proven 1e-10
  const EvalRow declared =
      row("hamburger4_float", 0.5, 0.6, std::numeric_limits<double>::infinity());
  const std::string s = summary_of({failed, broken, declared});
  EXPECT_NE(s.find("lp:power4: 3 fragments failed"), std::string::npos) << s;
  EXPECT_NE(s.find("**hamburger4 over-darkens above its proven bound**"), std::string::npos) << s;
  EXPECT_EQ(s.find("hamburger4_float over-darkens"), std::string::npos) << s;
}

}  // namespace
}  // namespace mb
