#pragma once
// What the hard-shadow rows share (techniques/registry.h): the wording of their bounds, the options
// several of them read, and verify's recipes for a fixed basis.
#include <string>
#include <vector>

#include "techniques/registry.h"

namespace mb {

inline const char* const kProvenBound =
    "0: a sharp or classic lower bound (Cantelli, Markov) in double";
inline const char* const kAlphaBound = "alpha: the moment bias, at beta = 0 (docs/reference.md §4)";
inline const char* const kNotProven = "not proven";

// Options read by the rows of more than one file.
extern const TechniqueOption kHamburgerBeta;  // hamburger.beta (power_moments.cpp)
extern const TechniqueOption kEsmC;           // esm.c (esm.cpp)

// verify's LP basis of a row whose basis does not depend on its options (VerifyRecipe::lp_basis).
template <const char* kSet>
std::vector<std::string> fixed_lp_basis(const TechniqueParams&) {
  return {kSet};
}
inline constexpr char kPower2[] = "power2", kPower4[] = "power4", kPower6[] = "power6",
                      kTrig4[] = "trig4";

// verify's recipe of a storage row (float32, 16-bit): a lower bound of Problem 1 over its storage's
// moment box (docs/reference.md §6).
inline VerifyRecipe storage_box(std::vector<std::string> (*basis)(const TechniqueParams&),
                                double lo, double hi, bool on_r, const TechniqueOption* alpha) {
  return {.judge = VerifyRecipe::Judge::StorageBox,
          .lp_basis = basis,
          .lo = lo,
          .hi = hi,
          .on_r = on_r,
          .alpha = alpha};
}

}  // namespace mb
