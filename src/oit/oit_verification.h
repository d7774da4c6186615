#pragma once
// `verify`'s transparency rows (docs/transparency.md §6): every MBOIT closed form in double with
// beta = 0 against the LP on the same basis, on seeded random pixels. Power moments: Hamburger's
// bound on R equals the continuous LP (certified) on an interval wide enough for the canonical
// nodes; trigonometric moments: the canonical reconstruction is never below the LP's sharp bound on
// the circle (docs/transparency.md §5: it is not the sharp bound itself).
#include <cstdint>
#include <string>
#include <vector>

namespace mb {

struct OitVerifyRow {
  std::string technique, lp_basis;  // lp_basis: the LP technique it was compared with
  std::string kind;                 // "equal" or "never below"
  double lo = 0, hi = 0;            // the LP's interval (of the warped depth u)
  double tolerance = 0;             // in T
  size_t pixels = 0, fragments = 0, beyond = 0, lp_failures = 0;
  double largest = 0;  // largest |dT| (equal) or largest T above the LP's (never below)
  bool passed() const { return beyond == 0 && lp_failures == 0; }
};

// The transmittance rows with a verify recipe (TechniqueRow::oit_verify), in registry order;
// InputError naming them for any other.
std::vector<std::string> oit_verify_names();
void check_oit_verify_technique(const std::string& technique);
OitVerifyRow verify_mboit(const std::string& technique, int pixels, uint64_t seed);

}  // namespace mb
