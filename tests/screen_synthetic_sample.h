#pragma once
// A hand-made screening sample for the full-scale tests (docs/sweeps.md, "Full scale"): 3 views of
// 60 units, 12 sampled in each, a pilot of 2-5 per unit drawn from `random`.
#include <random>

#include "screen/screening.h"

namespace mb::testing_support {

inline ScreenSample synthetic_screen_sample(std::mt19937_64& random) {
  std::uniform_real_distribution<double> unit(0, 1);
  ScreenSample sample;
  sample.weight = 5000;
  for (int v = 0; v < 3; ++v) {
    ScreenStratum s;
    s.runs = 60;
    for (size_t i = 0; i <= 12; ++i) s.run_begin.push_back(i);
    for (int i = 0; i < 12; ++i) s.pilot.push_back(2 + 3 * unit(random));
    s.pilot_total = 60 * 3.5;
    sample.strata.push_back(s);
  }
  return sample;
}

}  // namespace mb::testing_support
