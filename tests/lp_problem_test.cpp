// Building Problem 1 instances (src/lp/problem.h): ProblemFactory::move_zf, which the sweep uses
// for the fragments of one texel, must leave exactly the problem that building anew gives.
#include <gtest/gtest.h>

#include "basis/basis.h"
#include "lp/problem.h"

namespace mb::lp {
namespace {

void expect_same_problem(const Problem& a, const Problem& b) {
  EXPECT_EQ(a.rows, b.rows);
  EXPECT_EQ(a.grid, b.grid);
  EXPECT_EQ(a.extra.points, b.extra.points);
  EXPECT_EQ(a.extra.values, b.extra.values);
  EXPECT_EQ(a.extra.max_abs, b.extra.max_abs);
  EXPECT_EQ(a.rhs, b.rhs);
  EXPECT_EQ(a.zf, b.zf);
  EXPECT_EQ(a.moments, b.moments);
  EXPECT_EQ(a.start_support, b.start_support);
  EXPECT_EQ(a.start_weights, b.start_weights);
  EXPECT_EQ(a.atom_extra, b.atom_extra);
  EXPECT_EQ(a.extra_atom, b.extra_atom);
  EXPECT_EQ(a.zf_extra, b.zf_extra);
}

TEST(ProblemFactory, MovingZfGivesTheProblemBuiltAnew) {
  for (const char* set : {"power4", "trig4"}) {
    const Basis basis = Basis::parse({set});
    const ProblemFactory factory(basis, Discretization{0, 1, 64, false});
    // A kernel with a repeated depth (one extra column for two taps) and a zero weight.
    const std::vector<double> depths = {0.31, 0.31, 0.42, 0.57, 0.8};
    const std::vector<double> weights = {0.2, 0.1, 0.3, 0.0, 0.4};
    std::vector<std::vector<double>> columns(depths.size(), std::vector<double>(factory.rows()));
    std::vector<const double*> pointers;
    for (size_t t = 0; t < depths.size(); ++t) {
      factory.column(depths[t], columns[t].data());
      pointers.push_back(columns[t].data());
    }
    Problem moved;
    factory.from_distribution(depths, weights, pointers, 0.5, moved);
    for (double zf : {0.7, 0.05, 0.999, 0.3}) {
      ASSERT_TRUE(factory.move_zf(zf, moved)) << set << " zf " << zf;
      Problem fresh;
      factory.from_distribution(depths, weights, pointers, zf, fresh);
      expect_same_problem(moved, fresh);
    }
    // z_f on a kernel depth, or outside [lo, hi], has no column of its own: build anew.
    for (double zf : {0.42, 1.5, -0.1}) {
      const Problem before = moved;
      EXPECT_FALSE(factory.move_zf(zf, moved)) << set << " zf " << zf;
      expect_same_problem(moved, before);
    }
    Problem on_depth;
    factory.from_distribution(depths, weights, pointers, 0.42, on_depth);
    EXPECT_FALSE(factory.move_zf(0.6, on_depth));
  }
}

}  // namespace
}  // namespace mb::lp
