#pragma once
// `lp:<basis>`: Problem 1 solved as a linear program for any basis (docs/reference.md §2), so LP
// rows appear in the same error tables as the closed forms.
#include <memory>
#include <string>
#include <vector>

#include "lp/solution.h"
#include "techniques/technique.h"

namespace mb {

// An LP answer is certified to within lp::kCertifiedError of the optimum over a set of
// distributions that holds the kernel's own (docs/reference.md §2), so it exceeds
// F_Z(z_f - delta_f) by at most that.
constexpr double kLpDarkeningBound = lp::kCertifiedError;

// `name` = "lp:" + a named set (power4, trig4, ...) or functions separated by ';' or ','.
std::unique_ptr<Technique> make_lp_technique(const std::string& name, const TechniqueParams& p);

// Problem 1 for `basis` over the moment box of a map stored as `storage` (lp_stored:, and
// pss_lp_stored: for the scattering rows' maps), whatever lp.moment_box says: every distribution
// whose stored moments lie within the format's rounding of the kernel's (docs/reference.md §8).
std::unique_ptr<Technique> make_lp_technique(const std::string& name, const Basis& basis,
                                             const MomentStorage& storage,
                                             const TechniqueParams& p);

// The functions of an `lp:` name.
std::vector<std::string> lp_technique_basis(const std::string& name);
// The `lp:` name of a basis given as in `lp:` ("power4", "z; z^2").
std::string lp_technique_name(const std::string& basis);

struct TechniqueRow;
// The `lp:` technique whose Problem 1 on the continuous interval [0, 1] `row` solves in closed
// form, as its verify recipe states (sharp, on [0, 1], one named basis): the sweep report measures
// the LP grid's bias against it (docs/reference.md §2). "" for any other row.
std::string continuous_lp_of(const TechniqueRow& row);

}  // namespace mb
