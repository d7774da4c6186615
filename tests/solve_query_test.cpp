// Problem 1 queries as a library: one instance and JSON Lines batches, answered without the CLI.
#include "solve/solve_query.h"

#include <gtest/gtest.h>

#include <sstream>

#include "util/error.h"

namespace mb {
namespace {

SolveSettings cantelli() {
  SolveSettings s;
  s.basis = {"z", "z^2"};
  s.grid = 256;
  s.moments = {0.5, 0.3};  // mean 0.5, variance 0.05
  s.zf = 0.7;
  return s;
}

// Cantelli's bound (0.2^2 / (0.05 + 0.2^2) = 4/9) is attained on a grid holding its two atoms
// (0.7 and 0.5 - 0.05/0.2 = 0.25), which the 256-point grid of [0, 1] does not: the grid's G
// lies at or above it.
TEST(SolveQuery, AnInstanceIsCantellisBoundOnAFineGrid) {
  SolveSettings s = cantelli();
  s.points = {0.25, 0.7};
  const auto answer = solve_instance(s);
  ASSERT_EQ(answer["status"], "optimal");
  EXPECT_NEAR(answer["G"].get<double>(), 4.0 / 9.0, 1e-9);
  s.points = {};
  EXPECT_GE(solve_instance(s)["G"].get<double>(), 4.0 / 9.0 - 1e-9);
}

TEST(SolveQuery, AClosedFormInstanceIsTheTechniquesAnswer) {
  SolveSettings s = cantelli();
  s.technique = "vsm";
  const auto answer = solve_instance(s);
  EXPECT_EQ(answer["backend"], "closed_form");
  EXPECT_NEAR(answer["G"].get<double>(), 4.0 / 9.0, 1e-15);
}

TEST(SolveQuery, ABatchAnswersEveryLineInOrderAndNamesTheBadOnes) {
  std::istringstream in(
      R"({"id": "a", "basis": ["z", "z^2"], "moments": [0.5, 0.3], "zf": 0.7, "points": [0.25, 0.7]})"
      "\n\n"
      R"({"basis": ["z", "z^2"], "moments": [0.5, 0.3], "zf": 0.7, "gird": 64})"
      "\n"
      R"({"technique": "vsm", "moments": [0.5, 0.3], "zf": 0.7})"
      "\n"
      "not json\n");
  const SolveBatch batch = solve_batch(SolveSettings(), in, "queries.jsonl", false);
  std::istringstream lines(batch.lines);
  std::vector<nlohmann::json> answers;
  for (std::string line; std::getline(lines, line);) answers.push_back(nlohmann::json::parse(line));
  ASSERT_EQ(answers.size(), 4u);  // the blank line is skipped
  EXPECT_EQ(answers[0]["id"], "a");
  EXPECT_NEAR(answers[0]["G"].get<double>(), 4.0 / 9.0, 1e-9);
  EXPECT_EQ(answers[1]["status"], "error");
  EXPECT_NE(answers[1]["message"].get<std::string>().find(
                "queries.jsonl:3: unknown key 'gird' (did you mean 'grid'?)"),
            std::string::npos);
  EXPECT_EQ(answers[2]["id"], 4);  // a line without an id gets its line number
  EXPECT_NEAR(answers[2]["G"].get<double>(), 4.0 / 9.0, 1e-15);
  EXPECT_NE(answers[3]["message"].get<std::string>().find("queries.jsonl:5: JSON syntax"),
            std::string::npos);
  EXPECT_EQ(batch.failures, 2);
}

// Lines that share a basis reuse one problem factory; a line that changes it gets its own. The
// answers must not depend on which line came before.
TEST(SolveQuery, BatchAnswersDoNotDependOnTheLineBefore) {
  const std::string power =
      R"({"basis": "power4", "moments": [0.4, 0.2, 0.11, 0.065], "zf": 0.5, "grid": 128})";
  const std::string trig =
      R"({"basis": "trig4", "moments": [0.1, 0.2, 0.05, 0.1], "zf": 0.5, "grid": 128})";
  std::istringstream alone(power + "\n"), after(trig + "\n" + power + "\n");
  const std::string a = solve_batch(SolveSettings(), alone, "x", false).lines;
  const std::string b = solve_batch(SolveSettings(), after, "x", false).lines;
  auto G = [](const std::string& line) { return nlohmann::json::parse(line).value("G", -1.0); };
  EXPECT_EQ(G(a.substr(0, a.find('\n'))), G(b.substr(b.find('\n') + 1)));
}

TEST(SolveQuery, MomentToleranceIsAKeyOfALine) {
  // A point mass's moments rounded off the cone: answered within a box of ulps, or refused with 0.
  std::istringstream in(
      R"({"basis": ["z", "z^2"], "moments": [0.3, 0.09000000000000002], "zf": 0.5, "moment_tolerance": 0})"
      "\n");
  const SolveBatch batch = solve_batch(SolveSettings(), in, "x", false);
  EXPECT_EQ(batch.lines.find("unknown key"), std::string::npos) << batch.lines;
}

// A distribution's depths must lie in the interval (docs/reference.md §1), as eval refuses an LP
// interval that excludes a view's depths: the answer would otherwise have its support outside I.
TEST(SolveQuery, DepthsOutsideTheIntervalAreRefused) {
  SolveSettings s;
  s.basis = {"z", "z^2"};
  s.depths = {0.1, 1.5};
  s.weights = {0.5, 0.5};
  try {
    solve_instance(s);
    FAIL() << "a depth outside [0, 1] was answered";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("depths (--depths): depth 1.5 lies outside interval (--interval) [0, 1]"),
              std::string::npos)
        << what;
  }
  s.interval = {0, 2};  // the same distribution on an interval that holds it is answered
  EXPECT_EQ(solve_instance(s)["status"], "optimal");
  s.interval = {0.2, 2};  // and the lower end is checked as the upper
  EXPECT_THROW(solve_instance(s), InputError);
  std::istringstream in(
      R"({"basis": ["z", "z^2"], "depths": [-0.5, 0.5], "weights": [0.5, 0.5], "zf": 0.5})"
      "\n"
      R"({"basis": ["z", "z^2"], "depths": [-0.5, 0.5], "weights": [0.5, 0.5], "zf": 0.5, "interval": [-1, 1]})"
      "\n");
  const SolveBatch batch = solve_batch(SolveSettings(), in, "q.jsonl", false);
  EXPECT_NE(batch.lines.find(
                "q.jsonl:1: key 'depths': depth -0.5 lies outside key 'interval' (default) [0, 1]"),
            std::string::npos)
      << batch.lines;
  EXPECT_EQ(batch.failures, 1);  // the second line's interval holds its depths
}

// Extra points refine the LP's discretisation of I and do not make a depth admissible: the refusal
// says so (docs/reference.md §1, Problem 1's admissible set is the interval).
TEST(SolveQuery, PointsDoNotAdmitADepthOutsideTheInterval) {
  SolveSettings s;
  s.basis = {"z", "z^2"};
  s.depths = {0.1, 1.5};
  s.weights = {0.5, 0.5};
  s.points = {1.5};
  try {
    solve_instance(s);
    FAIL() << "a depth outside [0, 1] was answered";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("points do not count"), std::string::npos) << e.what();
  }
}

// Raw moments of a point mass rounded to double lie just outside the moment cone, and the local
// box's frame degenerates (its deviation is the tolerances' alone): the box holds the atom, and is
// answered, G = 1 with the atom below z_f and 0 at or behind it (docs/reference.md §2).
TEST(SolveQuery, RawMomentsOfAPointMassAreAnswered) {
  struct Case {
    std::vector<double> moments;
    double zf, G;
  };
  const std::vector<Case> cases = {{{0.5, 0.25}, 0.6, 1},
                                   {{0.7, 0.49}, 0.6, 0},
                                   {{0.8, 0.64}, 0.6, 0},
                                   {{0.5, 0.25, 0.125, 0.0625}, 0.6, 1},
                                   {{0.5, 0.25, 0.125, 0.0625}, 0.4, 0}};
  for (const Case& c : cases) {
    SolveSettings s;
    s.basis = {c.moments.size() == 2 ? "power2" : "power4"};
    s.discretization = "continuous";
    s.moments = c.moments;
    s.zf = c.zf;
    const auto answer = solve_instance(s);
    ASSERT_EQ(answer["status"], "optimal") << answer.dump();
    EXPECT_EQ(answer["G"].get<double>(), c.G) << answer.dump();
    EXPECT_TRUE(answer["proven"].get<bool>()) << answer.dump();
    EXPECT_LE(answer["bracket"].get<double>(), 1e-12) << answer.dump();
    const double lower = answer["lower"], lo = answer["range"][0], hi = answer["range"][1];
    EXPECT_GE(lower, 0);
    EXPECT_LE(lo, c.G);
    EXPECT_GE(hi, c.G);
    EXPECT_LE(hi - lo, 1e-12) << answer.dump();
  }
  // A vector of no distribution stays infeasible: variance 0, but E[z^4] far from 0.5^4.
  SolveSettings s;
  s.basis = {"power4"};
  s.discretization = "continuous";
  s.moments = {0.5, 0.25, 0.125, 0.09};
  s.zf = 0.6;
  EXPECT_EQ(solve_instance(s)["status"], "infeasible");
}

// G lies in [0, 1]: a certificate whose lower end lost its digits (two depths 1e-7 apart, z_f
// between them) is clamped to 0 and not called proven; the bracket is then [0, G].
TEST(SolveQuery, TheBracketLiesInTheUnitIntervalAndIsProvenOnlyWhereInformative) {
  SolveSettings s;
  s.basis = {"power2"};
  s.discretization = "continuous";
  s.depths = {0.5, 0.5000001};
  s.weights = {0.5, 0.5};
  s.zf = 0.50000005;
  const auto answer = solve_instance(s);
  ASSERT_EQ(answer["status"], "optimal") << answer.dump();
  const double G = answer["G"], lower = answer["lower"], bracket = answer["bracket"];
  EXPECT_GE(lower, 0);
  EXPECT_LE(G, 1);
  EXPECT_LE(lower, G);
  EXPECT_EQ(bracket, G - lower);
  if (answer.contains("certificate_lower")) {
    EXPECT_FALSE(answer["proven"].get<bool>()) << answer.dump();
    EXPECT_EQ(lower, 0);
  }
  // A well-conditioned instance keeps its proof and needs no clamping.
  s.depths = {0.3, 0.7};
  s.zf = 0.5;
  const auto wide = solve_instance(s);
  EXPECT_TRUE(wide["proven"].get<bool>()) << wide.dump();
  EXPECT_FALSE(wide.contains("certificate_lower"));
}

}  // namespace
}  // namespace mb

namespace mb {
namespace {

// A default-made SolveSettings holds its records' defaults (written there only): what a config of
// nothing but defaults reads.
TEST(SolveQuery, DefaultSettingsAreTheRecordsDefaults) {
  const SolveSettings made;
  const SolveSettings read = solve_settings_from(Config(solve_option_specs()));
  EXPECT_EQ(made.basis, read.basis);
  EXPECT_EQ(made.interval, read.interval);
  EXPECT_EQ(made.grid, read.grid);
  EXPECT_EQ(made.zf, read.zf);
  EXPECT_EQ(made.backend, read.backend);
  EXPECT_EQ(made.alpha, read.alpha);
  EXPECT_EQ(made.discretization, read.discretization);
  EXPECT_EQ(made.moment_tolerance, read.moment_tolerance);
  EXPECT_EQ(made.grid, 1024);  // solve's record: finer than eval's lp.grid 256
}

}  // namespace
}  // namespace mb
