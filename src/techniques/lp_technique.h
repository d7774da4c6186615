#pragma once
// `lp:<basis>`: Problem 1 solved as a linear program for any basis (docs/reference.md §2), so LP
// rows appear in the same error tables as the closed forms.
#include <memory>
#include <optional>
#include <span>
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

// `lp.moment_box` (docs/reference.md §2, "Moments with a tolerance"): Problem 1 over every
// distribution whose moments, stored as `storage` holds them, lie within `tolerance` of the
// kernel's stored moments: the sharpest bound a shader reading such a map can claim.
struct LpMomentBox {
  MomentStorage storage;
  std::vector<double> tolerance;  // per stored value (moments/storage.h, storage_tolerance)
};
// "none" -> no box; "double", "float32", "unorm16" (theta_4 or theta_2: power4 and power2 only).
std::optional<LpMomentBox> lp_moment_box(const std::string& setting, const Basis& basis);
// G of the box problem around the kernel's stored moments, on the grid ∪ the kernel's depths or
// (disc.continuous) on all of [lo, hi] by the exchange method (continuous/moment_box.h). The status
// says whether G is an answer.
lp::ProblemStatus solve_box_fragment(const LpMomentBox& box, const Basis& basis,
                                     const lp::Discretization& disc, std::span<const double> depths,
                                     std::span<const double> weights, double zf, double& G);
// The functions of an `lp:` name.
std::vector<std::string> lp_technique_basis(const std::string& name);

}  // namespace mb
