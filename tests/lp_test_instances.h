#pragma once
// Seeded random Problem 1 instances across every catalog function family, for tests and benches.
#include <algorithm>
#include <string>
#include <vector>

#include "basis/basis.h"
#include "lp/problem.h"
#include "scene/procedural.h"

namespace mb::testing_support {

struct RandomInstance {
  std::vector<std::string> basis;
  std::vector<double> depths, weights;
  double zf;
  int grid;
  bool boundary;  // at most two atoms: on the boundary of the moment space
};

inline RandomInstance random_instance(SeededRandom& random, int functions, int min_grid,
                                      int max_grid) {
  const auto& catalog = catalog_names();
  RandomInstance inst;
  // Families by catalog position: powers 0-5, exponentials 6-13, trigonometric 14-22, rational
  // and other 23-36. Half the instances draw within one family, half across the catalog.
  static const int family_start[] = {0, 6, 14, 23, 37};
  bool within = random.uniform() < 0.5;
  int family = int(random.uniform() * 4);
  std::vector<int> chosen;
  while (int(chosen.size()) < functions) {
    int lo = within ? family_start[family] : 0, hi = within ? family_start[family + 1] : 37;
    if (hi - lo < functions) lo = 0, hi = 37;
    int f = lo + int(random.uniform() * (hi - lo));
    if (std::find(chosen.begin(), chosen.end(), f) == chosen.end()) chosen.push_back(f);
  }
  std::sort(chosen.begin(), chosen.end());
  for (int f : chosen) inst.basis.push_back(catalog[f]);
  int atoms =
      random.uniform() < 0.4 ? 1 + int(random.uniform() * 2) : 1 + int(random.uniform() * 8);
  inst.boundary = atoms <= 2;
  double total = 0;
  for (int a = 0; a < atoms; ++a) {
    inst.depths.push_back(random.uniform());
    inst.weights.push_back(0.05 + random.uniform());
    total += inst.weights.back();
  }
  for (double& w : inst.weights) w /= total;
  // z_f near the atoms (the interesting case), or anywhere.
  inst.zf =
      random.uniform() < 0.6
          ? std::clamp(inst.depths[int(random.uniform() * atoms)] + random.uniform(-0.05, 0.05),
                       0.0, 1.0)
          : random.uniform();
  inst.grid = min_grid + int(random.uniform() * (max_grid - min_grid + 1));
  return inst;
}

}  // namespace mb::testing_support
