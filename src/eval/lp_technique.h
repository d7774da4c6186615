#pragma once
// `lp:<basis>`: Problem 1 solved as a linear program for any basis (REFERENCE.md §2), so LP rows
// appear in the same error tables as the closed forms.
#include <memory>
#include <string>

#include "eval/technique.h"

namespace mb {

// An LP answer is certified to within 1e-9 of the optimum over a set of distributions that holds
// the kernel's own (REFERENCE.md §2), so it exceeds F_Z(z_f - delta_f) by at most this.
constexpr double kLpDarkeningBound = 1e-9;

// `name` = "lp:" + a named set (power4, trig4, ...) or functions separated by ';' or ','.
std::unique_ptr<Technique> make_lp_technique(const std::string& name,
                                             const lp::Discretization& disc,
                                             const std::string& backend);
// The functions of an `lp:` name.
std::vector<std::string> lp_technique_basis(const std::string& name);

}  // namespace mb
