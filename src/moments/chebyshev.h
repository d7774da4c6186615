#pragma once
// The one- and two-moment closed forms (docs/reference.md §4): VSM's one-sided Chebyshev (Cantelli)
// bound for I = R, basis (z, z^2); ESM's Markov bound for basis e^{cz}.
namespace mb {

// b = (b1, b2); variance clamped below by min_variance (the usual VSM guard).
double vsm_bound(const double* b, double zf, double min_variance);
// b1 = E[e^{c z}].
double esm_bound(double b1, double zf, double c);

}  // namespace mb
