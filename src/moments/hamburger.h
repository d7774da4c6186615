#pragma once
// Hamburger moment shadow mapping (docs/reference.md §4; seed 000 Algorithm 3 with the authors'
// corrections, seed 004 for six moments): the sharp lower bound of Problem 1 for I = R and the
// power basis, from the canonical distribution with a node at z_f.
#include <cstddef>

namespace mb {

template <class Real>
struct MsmBound {
  Real lower = 0;      // G: the sharp lower bound on Z(z < z_f)
  Real at_zf = 0;      // the canonical distribution's weight at z_f: upper bound = lower + at_zf
  Real nodes[4] = {};  // z_f and the other nodes (ascending after z_f), for tests
  Real weights[4] = {};
  int node_count = 0;
};

// b = (b1, b2, b3, b4), already biased. Real = float or double.
template <class Real>
MsmBound<Real> hamburger4(const Real* b, Real zf);
// The lower bound alone for a stream of fragments: b holds 4 moments per fragment (unbiased),
// biased here towards b* = (1/2, ..) by alpha. Branch-free and vectorised (AVX-512 where
// available); it runs the same inlined steps as hamburger4.
void hamburger4_lower_batch(const double* b, const double* zf, double* lower, size_t count,
                            double alpha);
// MBOIT's four-moment reconstruction (docs/transparency.md §3) for one pixel's moments b (already
// biased) and many fragments: out[k] = clamp(G + beta w, 0, 1) with G = hamburger4(b, zf[k]).lower
// and w its at_zf (the same steps, vectorised over the fragments: equal to rounding, the vector
// code contracting other products); NaN where they are not finite.
void hamburger4_blend_batch(const double* b, const double* zf, size_t count, double beta,
                            double* out);
// b = (b1, .., b6), already biased (double). Seed 004 §2.5's stable steps (docs/reference.md §4,
// "Six moments, stably"): Cholesky of the 4x4 Hankel matrix, the cubic's roots in closed form
// plus one Newton step, the bounds through a Newton polynomial; the determinate distribution of
// fewer atoms where the Hankel matrix is singular.
MsmBound<double> hamburger6(const double* b, double zf);
// The same with one sign of the forward substitution flipped: a broken closed form, for the test
// that shows `verify` failing it (tests/verify_verification_test.cpp).
MsmBound<double> hamburger6_sign_flipped(const double* b, double zf);

}  // namespace mb
