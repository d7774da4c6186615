// Problem 1 as an LP (docs/reference.md §2): tiny LPs with known answers, then both backends on
// 100 000 seeded random instances, certified by the independent KKT checker.
#include <gtest/gtest.h>

#include <cmath>
#include <iomanip>
#include <random>

#include "eval/evaluation.h"
#include "eval/warm_runs.h"
#include "lp/exact_backend.h"
#include "lp/fallback_backend.h"
#include "lp/fast_backend.h"
#include "lp/glpk_backend.h"
#include "lp/kkt_checker.h"
#include "lp/problem.h"
#include "lp/solution.h"
#include "lp_test_instances.h"
#include "techniques/lp_technique.h"
#include "test_support.h"

namespace mb::lp {
namespace {

double cdf(const std::vector<double>& depths, const std::vector<double>& weights, double zf) {
  double f = 0;
  for (size_t i = 0; i < depths.size(); ++i) f += depths[i] < zf ? weights[i] : 0;
  return f;
}

Solution solve_with(const std::string& backend, const Problem& p) {
  return make_backend(backend)->solve(p);
}

class BothBackends : public ::testing::TestWithParam<std::string> {};

TEST_P(BothBackends, OnePointDistributionIsDeterminate) {
  // A single atom at 0.3: the moments (0.3, 0.09) of z, z^2 admit no other distribution.
  Basis basis = Basis::parse({"z", "z^2"});
  Discretization disc{0, 1, 11, false};
  for (auto [zf, expected] : {std::pair{0.5, 1.0}, {0.3, 0.0}, {0.2, 0.0}, {0.31, 1.0}}) {
    Problem p = make_problem_from_distribution(basis, disc, std::vector<double>{0.3},
                                               std::vector<double>{1.0}, zf);
    Solution s = solve_with(GetParam(), p);
    ASSERT_EQ(s.status, ProblemStatus::Optimal);
    EXPECT_NEAR(s.G, expected, 1e-9) << "zf " << zf;
    EXPECT_TRUE(check_kkt(p, s).ok) << check_kkt(p, s).describe();
  }
}

TEST_P(BothBackends, TwoPointsWithFourPowerMomentsReproduceTheCdf) {
  // Proposition 4 (seed 000): two depths make the 3x3 Hankel matrix singular; the distribution
  // is determined and the sharp bound equals F_Z.
  Basis basis = Basis::parse({"power4"});
  std::vector<double> depths = {0.2, 0.7}, weights = {0.4, 0.6};
  for (double zf : {0.1, 0.2, 0.45, 0.7, 0.8})
    for (auto disc : {Discretization{0, 1, 101, false}, Discretization{-4, 5, 257, false}}) {
      Problem p = make_problem_from_distribution(basis, disc, depths, weights, zf);
      Solution s = solve_with(GetParam(), p);
      ASSERT_EQ(s.status, ProblemStatus::Optimal);
      EXPECT_NEAR(s.G, cdf(depths, weights, zf), 1e-9) << "zf " << zf << " interval " << disc.lo;
    }
}

TEST_P(BothBackends, FragmentBehindOrInFrontOfAllMass) {
  Basis basis = Basis::parse({"power4"});
  std::vector<double> depths = {0.3, 0.5, 0.6}, weights = {0.2, 0.3, 0.5};
  Discretization disc{0, 1, 64, false};
  Solution front =
      solve_with(GetParam(), make_problem_from_distribution(basis, disc, depths, weights, 0.0));
  EXPECT_NEAR(front.G, 0.0, 1e-12);
  // z_f beyond the interval: every admissible point is in front of it.
  Solution behind =
      solve_with(GetParam(), make_problem_from_distribution(basis, disc, depths, weights, 1.5));
  EXPECT_NEAR(behind.G, 1.0, 1e-9);
}

TEST_P(BothBackends, MomentsOutsideTheMomentSpaceAreInfeasible) {
  // E[z^2] < E[z]^2: a negative variance.
  Basis basis = Basis::parse({"z", "z^2"});
  Problem p =
      make_problem(basis, Discretization{0, 1, 128, false}, std::vector<double>{0.5, 0.2}, 0.6);
  EXPECT_EQ(solve_with(GetParam(), p).status, ProblemStatus::Infeasible);
  // E[z] outside [0, 1].
  Problem q =
      make_problem(basis, Discretization{0, 1, 128, false}, std::vector<double>{1.2, 1.5}, 0.6);
  EXPECT_EQ(solve_with(GetParam(), q).status, ProblemStatus::Infeasible);
}

INSTANTIATE_TEST_SUITE_P(Lp, BothBackends, ::testing::Values("fast", "glpk", "exact"));

// A narrow kernel's LP from the default dataset's power4 sweep (the 81 taps of a 9x9 kernel, all
// within 0.3621-0.3655 of depth, 7 % of the mass in front of z_f, duals ~1e6): with the extra
// columns priced first, every start ended unstable, and GLPK's answer (1.3e-10, residual 2.3e-12)
// is rightly refused; the retry from scratch with Dantzig's rule over every column finds the
// optimum. The KKT checker certifies it independently.
TEST(LpFastBackend, NarrowKernelThatExtrasFirstPricingLeftUnstableIsSolved) {
  // (depth, weight) of each tap, in the kernel's order.
  const std::pair<double, double> taps[] = {
      {0.36358201594611927, 0.0019399121838833851}, {0.36347269023427264, 0.0035618554214704502},
      {0.3633838500579073, 0.0054975875716454107},  {0.36341660355658828, 0.0071329581725575759},
      {0.36353097285418445, 0.0077798074995837612}, {0.36354346371444735, 0.0071329581725575759},
      {0.36351887823217616, 0.0054975875716454107}, {0.36369605286905643, 0.0035618554214704502},
      {0.3639219734689581, 0.0019399121838833851},  {0.36433086201862619, 0.0035618554214704502},
      {0.3641875147930011, 0.0065398909027219593},  {0.36409310408815282, 0.010094071401662423},
      {0.36407091773966876, 0.013096760744698449},  {0.36405120854477208, 0.014284435012370986},
      {0.36405722458425482, 0.013096760744698449},  {0.36413920971602287, 0.010094071401662423},
      {0.36435442049043654, 0.0065398909027219593}, {0.36467426157926713, 0.0035618554214704502},
      {0.36468755702592187, 0.0054975875716454107}, {0.36454466231986254, 0.010094071401662423},
      {0.36444362794580959, 0.015579813024014143},  {0.36428529072370158, 0.020214349146474759},
      {0.36426669805213879, 0.022047478939941804},  {0.36429724050941453, 0.020214349146474759},
      {0.36443233546570097, 0.015579813024014143},  {0.36472694253574101, 0.010094071401662423},
      {0.36503284166493627, 0.0054975875716454107}, {0.36478702005528107, 0.0071329581725575759},
      {0.36470284645236251, 0.013096760744698449},  {0.36456022855491033, 0.020214349146474759},
      {0.36444110662101054, 0.026227523448821451},  {0.36438120708385158, 0.028605955437628509},
      {0.3644183330347176, 0.026227523448821451},   {0.36460611898936196, 0.020214349146474759},
      {0.36493289520344108, 0.013096760744698449},  {0.36525493786847402, 0.0071329581725575759},
      {0.36477361869146191, 0.0077798074995837612}, {0.36469880759401385, 0.014284435012370986},
      {0.36459108484146835, 0.022047478939941804},  {0.36450763201681963, 0.028605955437628509},
      {0.36445804232604445, 0.031200074536063709},  {0.36452634004446643, 0.028605955437628509},
      {0.36480950009766921, 0.022047478939941804},  {0.36518905645415661, 0.014284435012370986},
      {0.36546483226142118, 0.0077798074995837612}, {0.3645246161711731, 0.0071329581725575759},
      {0.364486265429523, 0.013096760744698449},    {0.36443007493478757, 0.020214349146474759},
      {0.3644397591961796, 0.026227523448821451},   {0.36450312108200694, 0.028605955437628509},
      {0.3646346111859442, 0.026227523448821451},   {0.36489845341075167, 0.020214349146474759},
      {0.36516812587016817, 0.013096760744698449},  {0.36553785623459634, 0.0071329581725575759},
      {0.36407960832390429, 0.0054975875716454107}, {0.36408480478334843, 0.010094071401662423},
      {0.36407313253065204, 0.015579813024014143},  {0.36414376113952757, 0.020214349146474759},
      {0.3642522554089766, 0.022047478939941804},   {0.36434982087856621, 0.020214349146474759},
      {0.36448472335427545, 0.015579813024014143},  {0.36478072570989611, 0.010094071401662423},
      {0.36519120665054849, 0.0054975875716454107}, {0.36326477877900715, 0.0035618554214704502},
      {0.3634118132341263, 0.0065398909027219593},  {0.36345609475922913, 0.010094071401662423},
      {0.36353921370449521, 0.013096760744698449},  {0.36362454925491383, 0.014284435012370986},
      {0.36371195647857568, 0.013096760744698449},  {0.36390038178346207, 0.010094071401662423},
      {0.36419553483890915, 0.0065398909027219593}, {0.36472894615055079, 0.0035618554214704502},
      {0.36213769834234466, 0.0019399121838833851}, {0.36235018879172332, 0.0035618554214704502},
      {0.36255216103188853, 0.0054975875716454107}, {0.36261872524792255, 0.0071329581725575759},
      {0.36279358058731076, 0.0077798074995837612}, {0.36292901963743313, 0.0071329581725575759},
      {0.36324516651322658, 0.0054975875716454107}, {0.36367826114497537, 0.0035618554214704502},
      {0.36431629607186994, 0.0019399121838833851}};
  std::vector<double> depths, weights;
  for (const auto& [depth, weight] : taps) {
    depths.push_back(depth);
    weights.push_back(weight);
  }
  const double zf = 0.36345804232604445;
  Problem p = make_problem_from_distribution(Basis::parse({"power4"}),
                                             Discretization{0, 1, 256, false}, depths, weights, zf);
  const Solution s = solve_with("fast", p);
  ASSERT_EQ(s.status, ProblemStatus::Optimal);
  const KktReport kkt = check_kkt(p, s);
  EXPECT_TRUE(kkt.ok) << kkt.describe();
  EXPECT_LE(kkt.error_bound, 1e-9);
  EXPECT_NEAR(s.G, 1.979189e-7, 1e-9);
  EXPECT_LE(s.G, cdf(depths, weights, zf) + 1e-12);
}

// How far GLPK's answer may be from ours and still be explained by our certificate: ours is
// exactly feasible (long double residual) with duals y, so by weak duality GLPK can only be lower
// through its own residual (|y . residual|), and only higher through its own dual infeasibility
// and gap (a premature stop).
bool difference_is_explained(const Problem& p, const Solution& ours, const Solution& glpk) {
  if (glpk.status != ProblemStatus::Optimal) return true;
  if (std::abs(ours.G - glpk.G) <= 1e-9) return true;
  KktReport k = check_kkt(p, glpk);
  if (glpk.G > ours.G) return glpk.G - ours.G <= k.dual_infeasibility + k.duality_gap + 1e-9;
  long double moved = 0;
  std::vector<long double> residual(p.rhs.begin(), p.rhs.end());
  for (size_t t = 0; t < glpk.support.size(); ++t)
    for (int r = 0; r < p.rows; ++r)
      residual[r] -= (long double)p.at(r, glpk.support[t]) * glpk.weights[t];
  for (int r = 0; r < p.rows; ++r) moved += std::abs(ours.duals[r] * residual[r]);
  return ours.G - glpk.G <= double(moved) + 1e-9;
}

// Both backends on 100 000 seeded instances across every catalog family, 40 % of them one or two
// atoms (the boundary of the moment space). Ours must be optimal, KKT-certified and <= F_Z, and
// agree with GLPK to 1e-9 wherever GLPK's answer is itself consistent. Measured: 34 of 100 000
// (one- or two-atom instances of nearly dependent functions such as z^3, z^6 or exp(-4z),
// exp(-8z)) end "unstable" because no basis certifies them; GLPK calls most of those infeasible,
// which is wrong (the kernel distribution is feasible).
TEST(LpBackends, AgreeOnOneHundredThousandRandomInstancesAcrossTheCatalog) {
  SeededRandom random(20261124);
  auto fast = make_backend("fast"), glpk = make_backend("glpk");
  const int kInstances = 100000;
  int boundary = 0, unstable = 0, glpk_inconsistent = 0, close = 0, fallback = 0;
  double max_difference = 0;
  for (int n = 0; n < kInstances; ++n) {
    auto inst = testing_support::random_instance(random, 1 + n % 4, 16, 96);
    Basis basis = Basis::parse(inst.basis);
    Discretization disc{0, 1, inst.grid, n % 5 == 0};
    Problem p = make_problem_from_distribution(basis, disc, inst.depths, inst.weights, inst.zf);
    Solution a = fast->solve(p), b = glpk->solve(p);
    boundary += inst.boundary;
    ASSERT_NE(a.status, ProblemStatus::Infeasible)
        << "instance " << n << ": the kernel distribution is feasible";
    if (a.status == ProblemStatus::Unstable) {
      ++unstable;
      continue;
    }
    KktReport ka = check_kkt(p, a);
    ASSERT_TRUE(ka.ok) << "instance " << n << ": " << ka.describe();
    double fz = 0;
    for (size_t i = 0; i < inst.depths.size(); ++i)
      fz += (disc.quantize ? quantize_to_grid(disc, inst.depths[i]) : inst.depths[i]) < inst.zf
                ? inst.weights[i]
                : 0;
    ASSERT_LE(a.G, fz + 1e-9) << "instance " << n;
    ASSERT_GE(a.G, -1e-12);
    if (a.engine == Engine::Glpk) {  // our fallback's answer is GLPK's own: no comparison
      ++fallback;
      continue;
    }
    if (b.status == ProblemStatus::Optimal && std::abs(a.G - b.G) <= 1e-9) {
      ++close;
      max_difference = std::max(max_difference, std::abs(a.G - b.G));
      continue;
    }
    ASSERT_TRUE(difference_is_explained(p, a, b))
        << "instance " << n << std::setprecision(17) << ": ours " << a.G << ", GLPK " << b.G << " ("
        << to_string(b.status) << ")";
    ++glpk_inconsistent;
  }
  std::printf(
      "random instances: %d (%d on the boundary); ours unstable %d; agreeing to 1e-9: %d (max |dG| "
      "%.2e); "
      "GLPK wrong by our certificate: %d; answered by our GLPK fallback (not compared): %d\n",
      kInstances, boundary, unstable, close, max_difference, glpk_inconsistent, fallback);
  EXPECT_LE(fallback, kInstances / 1000);
  EXPECT_GT(boundary, kInstances / 4);
  EXPECT_LE(unstable, kInstances / 1000);
  // GLPK's own error rate, not ours (each case is checked above): ~0.1 %; it counts a few more
  // since our solver certifies more of the boundary instances GLPK gets wrong (103 measured).
  EXPECT_LE(glpk_inconsistent, 2 * kInstances / 1000);
}

// The exact rational arbiter (QSopt_ex) on seeded instances across the catalog: it solves the LP
// as posed exactly, so our certified answers must agree with it to 1e-9 wherever ours is optimal
// and not our GLPK fallback's; GLPK is counted, not required to agree (docs/lp-engine.md § The
// exact arbiter).
TEST(LpBackends, OursAgreesWithTheExactRationalArbiter) {
  SeededRandom random(20261205);
  auto fast = make_backend("fast"), glpk = make_backend("glpk"), exact = make_backend("exact");
  const int kInstances = 1500;
  int compared = 0, glpk_agrees = 0;
  double max_difference = 0;
  for (int n = 0; n < kInstances; ++n) {
    auto inst = testing_support::random_instance(random, 1 + n % 4, 16, 96);
    const Basis basis = Basis::parse(inst.basis);
    const Problem p = make_problem_from_distribution(basis, Discretization{0, 1, inst.grid, false},
                                                     inst.depths, inst.weights, inst.zf);
    const Solution e = exact->solve(p);
    ASSERT_EQ(e.status, ProblemStatus::Optimal) << "instance " << n << ": it is feasible";
    ASSERT_EQ(e.engine, Engine::Exact);
    const Solution a = fast->solve(p), b = glpk->solve(p);
    glpk_agrees += b.status == ProblemStatus::Optimal && std::abs(b.G - e.G) <= 1e-9;
    if (a.status != ProblemStatus::Optimal || a.engine != Engine::Fast) continue;
    EXPECT_NEAR(a.G, e.G, 1e-9) << "instance " << n;
    max_difference = std::max(max_difference, std::abs(a.G - e.G));
    ++compared;
  }
  std::printf(
      "exact arbiter: %d instances; ours compared %d (max |dG| %.2e); GLPK within 1e-9: %d\n",
      kInstances, compared, max_difference, glpk_agrees);
  EXPECT_GE(compared, kInstances * 99 / 100);
}

// Narrow kernels (a 9x9 Gaussian over a plane whose depth changes by 0.001-0.05 across it, half
// with an occluder edge), power4 on the 256-point grid of [0, 1]: duals up to ~1e11 make G move by
// up to ~1e-5 when the right-hand side is rounded to double (results/FINDINGS.md §6b). Against the
// LP it was given (the rounded right-hand side, solved exactly) ours must agree to 1e-9; against
// the distribution's exact image it may not, and the test counts by how much.
TEST(LpBackends, NarrowKernelsAgreeWithTheExactLpTheyWereGiven) {
  std::mt19937_64 rng(45);
  std::uniform_real_distribution<double> unit(0, 1);
  auto fast = make_backend("fast"), as_rounded = make_exact_backend(ExactRhs::AsRounded),
       image = make_exact_backend(ExactRhs::DistributionImage),
       glpk_exact = make_glpk_backend(GlpkMode::Exact);
  const Basis basis = Basis::parse({"power4"});
  int compared = 0, rounded_infeasible = 0, image_apart = 0, glpk_exact_agrees = 0,
      glpk_exact_above = 0;
  double worst_image = 0, worst_glpk_exact = 0;
  for (int n = 0; n < 120; ++n) {
    const double change = 0.001 * std::pow(50.0, unit(rng)), angle = 6.283185307179586 * unit(rng);
    const double centre = 0.3 + 0.5 * unit(rng);
    const double gx = change / 8 * std::cos(angle), gy = change / 8 * std::sin(angle);
    const int edge_column = n % 2 ? int(unit(rng) * 7) - 3 : -10;
    std::vector<double> depths, weights;
    double total = 0;
    for (int dy = -4; dy <= 4; ++dy)
      for (int dx = -4; dx <= 4; ++dx) {
        depths.push_back(dx < edge_column ? centre - 0.2 + 0.1 * gx * dx
                                          : centre + gx * dx + gy * dy);
        weights.push_back(std::exp(-(dx * dx + dy * dy) / (2 * 2.4 * 2.4)));
        total += weights.back();
      }
    for (double& w : weights) w /= total;
    const double zf = centre - 0.0001 - 4 * (std::abs(gx) + std::abs(gy)) * unit(rng);
    const Problem p = make_problem_from_distribution(basis, Discretization{0, 1, 256, false},
                                                     depths, weights, zf);
    const Solution ours = fast->solve(p), exact = as_rounded->solve(p), meant = image->solve(p);
    ASSERT_EQ(meant.status, ProblemStatus::Optimal) << n;
    if (std::abs(ours.G - meant.G) > 1e-9) ++image_apart;
    worst_image = std::max(worst_image, std::abs(ours.G - meant.G));
    if (exact.status != ProblemStatus::Optimal) {
      ++rounded_infeasible;
      continue;
    }
    // GLPK's rational simplex solves the same rounded LP: measured, not asserted (FINDINGS §6b).
    const Solution g = glpk_exact->solve(p);
    const double g_apart = g.status == ProblemStatus::Optimal ? std::abs(g.G - exact.G) : 1.0;
    glpk_exact_agrees += g_apart <= 1e-9;
    glpk_exact_above += g.status == ProblemStatus::Optimal && g.G > exact.G + 1e-9;
    worst_glpk_exact = std::max(worst_glpk_exact, g_apart);
    if (ours.status != ProblemStatus::Optimal || ours.engine != Engine::Fast) continue;
    EXPECT_NEAR(ours.G, exact.G, 1e-9) << "kernel " << n << " change " << change;
    ++compared;
  }
  std::printf(
      "narrow kernels: ours vs the exact LP as rounded: %d compared, %d exactly infeasible; "
      "vs the distribution's exact image: %d beyond 1e-9, worst %.2e; GLPK's exact mode within "
      "1e-9 of the exact LP: %d (worst %.2e, 1 = not optimal; %d above the optimum)\n",
      compared, rounded_infeasible, image_apart, worst_image, glpk_exact_agrees, worst_glpk_exact,
      glpk_exact_above);
  EXPECT_GE(compared, 60);
}

TEST(LpProperties, ZeroCdfGivesZeroAndRefiningNeverRaisesTheBound) {
  SeededRandom random(7);
  auto fast = make_backend("fast");
  int compared = 0;
  for (int n = 0; n < 2000; ++n) {
    auto inst = testing_support::random_instance(random, 4, 17, 65);
    Basis basis = Basis::parse(inst.basis);
    // F_Z(z_f) = 0 when z_f is at or below every depth.
    double lowest = *std::min_element(inst.depths.begin(), inst.depths.end());
    Discretization disc{0, 1, inst.grid, false};
    Solution zero =
        fast->solve(make_problem_from_distribution(basis, disc, inst.depths, inst.weights, lowest));
    if (zero.status == ProblemStatus::Optimal) {
      EXPECT_LE(zero.G, 1e-9);
    }
    // A grid of 2n - 1 points contains the grid of n points: the admissible set only grows.
    Discretization fine{0, 1, 2 * inst.grid - 1, false};
    Solution coarse_s = fast->solve(
        make_problem_from_distribution(basis, disc, inst.depths, inst.weights, inst.zf));
    Solution fine_s = fast->solve(
        make_problem_from_distribution(basis, fine, inst.depths, inst.weights, inst.zf));
    if (coarse_s.status != ProblemStatus::Optimal || fine_s.status != ProblemStatus::Optimal)
      continue;
    ++compared;
    EXPECT_LE(fine_s.G, coarse_s.G + 1e-9) << "instance " << n << std::setprecision(17) << " fine "
                                           << fine_s.G << " coarse " << coarse_s.G;
  }
  EXPECT_GT(compared, 1990);
}

}  // namespace
}  // namespace mb::lp

namespace mb::lp {
namespace {

// Warm starts (Backend::solve_next) along runs of neighbouring fragments, as the sweep solves
// them: the same status and G to 1e-9 as solving each from scratch, KKT-certified, and fewer
// pivots in all (else the warm start is not doing its job). Real kernels of the tiny dataset.
// The iterations price the extra columns first (partial pricing), and the KKT checker, which
// prices every column itself, sees whether an optimum was declared too early; grid 1024 too.
TEST(LpWarmStart, RunsOfNeighbouringFragmentsGiveTheColdAnswers) {
  EvalSettings settings;
  settings.threads = 2;
  const auto views = prepare_views(load_dataset("tiny"), 0, settings, true);
  std::vector<double> depths(81), weights(81);
  const std::pair<const char*, int> cases[] = {{"power4", 128},
                                               {"trig4", 128},
                                               {"exp(-4z); z; sin(pi z); 1/(1+z)", 128},
                                               {"z^5; z^6; log(1+z); exp(8z)", 128},
                                               {"power4", 1024},
                                               {"trig4", 1024}};
  for (const auto& [basis_text, grid] : cases) {
    ProblemFactory factory(Basis::parse(mb::lp_technique_basis(std::string("lp:") + basis_text)),
                           Discretization{0, 1, grid, false});
    auto cold = make_backend("fast"), warm = make_backend("fast");
    const KernelAtomMap atoms(settings.kernel.size);
    int cold_pivots = 0, warm_pivots = 0, compared = 0, not_optimal = 0;
    for (const auto& v : views) {
      int run = -1;  // every third warm-start band, each in fragment order as the sweep solves it
      for (size_t k = 0; k < v.fragments.size(); ++k) {
        const size_t t = v.fragments.texel[k];
        const int x = int(t % v.map.width), y = int(t / v.map.width);
        if (mb::warm_run_of(t, v.map.width) % 3 != 0) continue;
        const bool first = mb::warm_run_of(t, v.map.width) != run;
        const double zf = v.fragments.ztest[k];
        if (v.fragments.oracle[k] == 0) continue;  // F_Z(z_f - delta_f) = 0: G = 0, no LP
        kernel_distribution(v.map, settings.kernel, x, y, depths, weights);
        const Problem p = factory.from_distribution(depths, weights, zf);
        const Solution a = cold->solve(p);
        const Solution b =
            first ? warm->solve(p)
                  : warm->solve_next(p, warm_start_at(v.fragments.layer[k], x, y, &atoms));
        run = mb::warm_run_of(t, v.map.width);
        cold_pivots += a.iterations;
        warm_pivots += b.iterations;
        ASSERT_EQ(a.status, b.status) << basis_text << " fragment " << k;
        if (a.status != ProblemStatus::Optimal) {
          ++not_optimal;
          continue;
        }
        ++compared;
        ASSERT_NEAR(a.G, b.G, 1e-9) << basis_text << " fragment " << k;
        const KktReport kkt = check_kkt(p, b);
        ASSERT_TRUE(kkt.ok) << basis_text << " fragment " << k << ": " << kkt.describe();
        // The certificate's own promise: the support reproduces the moments to 1e-12 (a clamped
        // negative weight once passed with 5e-7 where every basic point was behind z_f).
        ASSERT_LE(kkt.primal_residual, 1e-12)
            << basis_text << " fragment " << k << ": " << kkt.describe();
      }
    }
    std::printf("%s, grid %d: %d LPs, %.1f pivots cold, %.1f warm\n", basis_text, grid, compared,
                double(cold_pivots) / compared, double(warm_pivots) / compared);
    EXPECT_GT(compared, 300);
    EXPECT_EQ(not_optimal, 0) << basis_text << ", grid "
                              << grid;  // every tiny-dataset LP is certified
    EXPECT_LT(warm_pivots, cold_pivots / 2) << basis_text;
  }
}

// A basis carries over by texel (eval/warm_runs.h's KernelAtomMap over WarmStart::place): the same
// kernel solved again at the same texel maps every kernel column to itself, so the remembered basis
// and its inverse come back unchanged and the LP is optimal without a pivot; one texel to the right
// the same depths are one tap to the left, and the answer is still the cold one.
TEST(LpWarmStart, TheSameTexelGivesTheSameBasisBack) {
  EvalSettings settings;
  settings.threads = 1;
  const auto views = prepare_views(load_dataset("tiny"), 0, settings, true);
  const ViewData& v = views.front();
  ProblemFactory factory(Basis::parse({"power4"}), Discretization{0, 1, 256, false});
  std::vector<double> depths(81), weights(81);
  const KernelAtomMap atoms(settings.kernel.size);
  int checked = 0;
  for (size_t k = 0; k < v.fragments.size() && checked < 40; k += 7) {
    const size_t t = v.fragments.texel[k];
    const int x = int(t % v.map.width), y = int(t / v.map.width);
    const double zf = v.fragments.ztest[k];
    if (x + 1 >= v.map.width || v.fragments.oracle[k] == 0) continue;
    kernel_distribution(v.map, settings.kernel, x, y, depths, weights);
    const Problem p = factory.from_distribution(depths, weights, zf);
    auto warm = make_backend("fast"), cold = make_backend("fast");
    const Solution first = warm->solve(p);
    ASSERT_EQ(first.status, ProblemStatus::Optimal);
    const Solution again = warm->solve_next(p, warm_start_at(v.fragments.layer[k], x, y, &atoms));
    ASSERT_EQ(again.status, ProblemStatus::Optimal);
    EXPECT_EQ(again.iterations, 0) << "fragment " << k;
    EXPECT_NEAR(again.G, first.G, 1e-9) << "fragment " << k;
    kernel_distribution(v.map, settings.kernel, x + 1, y, depths, weights);
    const Problem right = factory.from_distribution(depths, weights, zf);
    const Solution next =
        warm->solve_next(right, warm_start_at(v.fragments.layer[k], x + 1, y, &atoms));
    const Solution reference = cold->solve(right);
    ASSERT_EQ(next.status, reference.status) << "fragment " << k;
    if (reference.status == ProblemStatus::Optimal) {
      EXPECT_NEAR(next.G, reference.G, 1e-9) << "fragment " << k;
    }
    ++checked;
  }
  EXPECT_GE(checked, 20);
}

// The texel mapping itself, on a surface whose every texel has its own depth (the tiny dataset's
// flat surfaces cannot tell it from the same-offset mapping): a sloped, wavy receiver under a
// sloped occluder edge, solved row by row as the sweep does, once with texel rows known (kernel
// columns come back as the same depths) and once without (row -1: the tap at the same offset).
// Both give the cold answers; the texel mapping needs fewer pivots (lp_bench's runs of the default
// dataset: 1.86 against 2.46 an LP).
TEST(LpWarmStart, MappingByTexelNeedsFewerPivotsThanBySameOffset) {
  auto depth = [](int x, int y) {
    const double receiver =
        0.55 + 0.002 * x + 0.0013 * y + 0.01 * std::sin(0.37 * x) * std::cos(0.23 * y);
    const double occluder = 0.30 + 0.001 * x - 0.0008 * y;
    return x + 0.6 * y < 30 ? occluder : receiver;  // an occluder edge crossing the rows
  };
  const GaussianKernel kernel = make_gaussian_kernel(9, 2.4);
  const int r = kernel.radius();
  const KernelAtomMap atoms(kernel.size);
  ProblemFactory factory(Basis::parse({"power4"}), Discretization{0, 1, 256, false});
  auto cold = make_backend("fast"), by_texel = make_backend("fast"),
       by_offset = make_backend("fast");
  std::vector<double> depths, weights;
  int texel_pivots = 0, offset_pivots = 0, solved = 0;
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 48; ++x) {
      depths.clear(), weights.clear();
      for (int dy = -r; dy <= r; ++dy)
        for (int dx = -r; dx <= r; ++dx)
          depths.push_back(depth(x + dx, y + dy)), weights.push_back(kernel.weight(dx, dy));
      const double zf = depth(x, y) - 1e-3;
      const Problem p = factory.from_distribution(depths, weights, zf);
      const Solution reference = cold->solve(p);
      const bool first = x == 0 && y == 0;
      const Solution a =
          first ? by_texel->solve(p) : by_texel->solve_next(p, warm_start_at(0, x, y, &atoms));
      const Solution b =
          first ? by_offset->solve(p) : by_offset->solve_next(p, warm_start_at(0, x, -1, &atoms));
      ASSERT_EQ(reference.status, ProblemStatus::Optimal) << x << ", " << y;
      ASSERT_EQ(a.status, ProblemStatus::Optimal) << x << ", " << y;
      ASSERT_EQ(b.status, ProblemStatus::Optimal) << x << ", " << y;
      ASSERT_NEAR(a.G, reference.G, 1e-9) << x << ", " << y;
      ASSERT_NEAR(b.G, reference.G, 1e-9) << x << ", " << y;
      texel_pivots += a.iterations, offset_pivots += b.iterations, ++solved;
    }
  std::printf("%d LPs: %.2f pivots an LP by texel, %.2f by the same offset\n", solved,
              double(texel_pivots) / solved, double(offset_pivots) / solved);
  EXPECT_LT(texel_pivots, offset_pivots);
}

}  // namespace
}  // namespace mb::lp

namespace mb::lp {
namespace {

// A simplex held to one pivot a run stops at its iteration limit, says so (not "unstable"), and
// the fallback then answers with GLPK's certified optimum, tagged as GLPK's; the default settings
// answer the same LP themselves.
TEST(LpFastBackend, IterationLimitIsReportedAndTheFallbackAnswers) {
  const Basis basis = Basis::parse({"z", "z^2", "z^3", "z^4"});
  const Discretization disc{0, 1, 256, false};
  const std::vector<double> depths{0.2, 0.35, 0.5, 0.8}, weights{0.1, 0.4, 0.3, 0.2};
  // From its moments alone (no known distribution): phase 1 from artificials needs k pivots.
  std::vector<double> moments(4, 0.0);
  for (size_t i = 0; i < depths.size(); ++i)
    for (int j = 0; j < 4; ++j) moments[j] += weights[i] * std::pow(depths[i], j + 1);
  const Problem p = make_problem(basis, disc, moments, 0.6);

  const Solution exact = make_fast_backend()->solve(p);
  ASSERT_EQ(exact.status, ProblemStatus::Optimal);
  EXPECT_EQ(exact.engine, Engine::Fast);
  EXPECT_GT(exact.iterations, 1);

  fast::SimplexSettings held;
  held.max_iterations = 1;
  const Solution stopped = make_fast_backend(held)->solve(p);
  EXPECT_EQ(stopped.status, ProblemStatus::IterationLimit) << to_string(stopped.status);

  const Solution rescued = make_fallback_backend(make_fast_backend(held))->solve(p);
  ASSERT_EQ(rescued.status, ProblemStatus::Optimal);
  EXPECT_EQ(rescued.engine, Engine::Glpk);
  EXPECT_NEAR(rescued.G, exact.G, 2 * kCertifiedError);
}

}  // namespace
}  // namespace mb::lp
