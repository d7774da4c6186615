#pragma once
// `lp:<basis>`: Problem 1 solved as a linear program for any basis (REFERENCE.md §2), so LP rows
// appear in the same error tables as the closed forms.
#include <memory>
#include <string>

#include "eval/technique.h"

namespace mb {

// `name` = "lp:" + a named set (power4, trig4, ...) or functions separated by ';' or ','.
std::unique_ptr<Technique> make_lp_technique(const std::string& name, const lp::Discretization& disc,
                                             const std::string& backend);
// The functions of an `lp:` name.
std::vector<std::string> lp_technique_basis(const std::string& name);

}  // namespace mb
