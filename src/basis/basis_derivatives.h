#pragma once
// Derivatives of the catalog functions (docs/reference.md §5) in long double, and proven bounds of
// |b^(k)| on an interval: what the continuous Problem 1's certificate needs (docs/reference.md §2:
// "phi(z) <= [z < z_f] + eps proven on all of I"). Each catalog function belongs to a family whose
// k-th derivative has a closed form (powers, exponentials, sinusoids, powers of an affine
// function, simple complex poles, tanh, Gaussians, z e^z); user expressions have none, and the
// continuous method then only samples (what it proves is stated with every answer).
#include <string>

namespace mb {

// The largest derivative order a form evaluates (Taylor models of order < this).
constexpr int kMaxDerivativeOrder = 12;

struct AnalyticForm;

// The form of a catalog function by its catalog name; null for anything else.
const AnalyticForm* analytic_form(const std::string& catalog_name);
// out[k] = b^(k)(z) for k = 0..order (order <= kMaxDerivativeOrder).
void form_derivatives(const AnalyticForm& form, long double z, int order, long double* out);
// An upper bound of |b^(order)(z)| over z in [a, b] (a <= b), proven from the family's closed
// form (+inf where b has a pole on [a, b]).
long double form_derivative_bound(const AnalyticForm& form, int order, long double a,
                                  long double b);

}  // namespace mb
