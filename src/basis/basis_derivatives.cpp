#include "basis/basis_derivatives.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <limits>
#include <map>
#include <numbers>

namespace mb {

enum class Family { Power, Exp, Sine, AffinePower, Log, Pole, Atan, Tanh, Gauss, ZExp };

// One family and its parameters; what each field means depends on the family (see the table).
struct AnalyticForm {
  Family family;
  long double a = 0, b = 0, c = 0;
  int n = 0;
};

namespace {

using complex = std::complex<long double>;
constexpr long double kPi = std::numbers::pi_v<long double>;
constexpr long double kInf = std::numeric_limits<long double>::infinity();

// docs/reference.md §5, by family:
//   Power z^n (n); Exp e^{cz} (c); Sine sin(a z + b) (cos: b = pi/2);
//   AffinePower (a + c z)^b; Log log(1 + c z); Pole Re (n = 0) or Im (n = 1) of 1/(z - (a + ib));
//   Atan atan(c z), whose derivative is Im 1/(z - i/c); Tanh tanh(a (z - b));
//   Gauss e^{-a (z - b)^2}; ZExp z e^z.
const std::map<std::string, AnalyticForm>& forms() {
  static const std::map<std::string, AnalyticForm> table = [] {
    std::map<std::string, AnalyticForm> t;
    for (int n = 1; n <= 6; ++n)
      t[n == 1 ? "z" : "z^" + std::to_string(n)] = {Family::Power, 0, 0, 0, n};
    const std::pair<const char*, long double> exps[] = {
        {"exp(z)", 1},  {"exp(-z)", -1},  {"exp(2z)", 2}, {"exp(-2z)", -2},
        {"exp(4z)", 4}, {"exp(-4z)", -4}, {"exp(8z)", 8}, {"exp(-8z)", -8}};
    for (const auto& [name, c] : exps) t[name] = {Family::Exp, 0, 0, c};
    for (int k = 1; k <= 4; ++k) {
      const std::string w = k == 1 ? "pi z" : std::to_string(k) + " pi z";
      t["sin(" + w + ")"] = {Family::Sine, k * kPi, 0};
      t["cos(" + w + ")"] = {Family::Sine, k * kPi, kPi / 2};
    }
    t["sin(pi z / 2)"] = {Family::Sine, kPi / 2, 0};
    t["1/(1+z)"] = {Family::AffinePower, 1, -1, 1};
    t["1/(1+z)^2"] = {Family::AffinePower, 1, -2, 1};
    t["1/(2-z)"] = {Family::AffinePower, 2, -1, -1};
    t["1/(1+4z)"] = {Family::AffinePower, 1, -1, 4};
    t["sqrt(1+z)"] = {Family::AffinePower, 1, 0.5L, 1};
    t["1/(1+z^2)"] = {Family::Pole, 0, 1, 0, 1};  // Im 1/(z - i) = 1/(1+z^2)
    t["z/(1+z^2)"] = {Family::Pole, 0, 1, 0, 0};  // Re 1/(z - i) = z/(1+z^2)
    t["log(1+z)"] = {Family::Log, 0, 0, 1};
    t["log(1+4z)"] = {Family::Log, 0, 0, 4};
    t["atan(4z)"] = {Family::Atan, 0, 0, 4};
    t["tanh(4(z-1/2))"] = {Family::Tanh, 4, 0.5L};
    t["exp(-z^2)"] = {Family::Gauss, 1, 0};
    t["exp(-16(z-1/2)^2)"] = {Family::Gauss, 16, 0.5L};
    t["z exp(z)"] = {Family::ZExp};
    return t;
  }();
  return table;
}

// p (p - 1) .. (p - k + 1).
long double falling(long double p, int k) {
  long double f = 1;
  for (int i = 0; i < k; ++i) f *= p - i;
  return f;
}

long double factorial(int k) {
  return falling(k, k);
}

// d^k/dz^k 1/(z - w) = (-1)^k k! / (z - w)^(k+1).
complex pole_derivative(long double z, complex w, int k) {
  const complex q = 1.0L / (complex(z) - w);
  complex power = q;
  for (int i = 0; i < k; ++i) power *= q;
  return (k % 2 ? -1.0L : 1.0L) * factorial(k) * power;
}

// The distance from the real segment [a, b] to w: what bounds |1/(z - w)| there.
long double distance(long double a, long double b, complex w) {
  const long double dx = std::max({0.0L, a - w.real(), w.real() - b});
  return std::hypot(dx, w.imag());
}

// tanh's k-th derivative is P_k(tanh x): P_0 = t, P_{k+1} = P_k'(t) (1 - t^2). Coefficients by
// degree, up to kMaxDerivativeOrder.
using TanhPolynomial = std::array<long double, kMaxDerivativeOrder + 2>;
const std::array<TanhPolynomial, kMaxDerivativeOrder + 1>& tanh_polynomials() {
  static const auto table = [] {
    std::array<TanhPolynomial, kMaxDerivativeOrder + 1> p{};
    p[0][1] = 1;
    for (int k = 0; k < kMaxDerivativeOrder; ++k) {
      TanhPolynomial d{};  // P_k'
      for (int i = 1; i < int(d.size()); ++i) d[i - 1] = i * p[k][i];
      for (int i = 0; i < int(d.size()); ++i) {  // times (1 - t^2)
        p[k + 1][i] += d[i];
        if (i + 2 < int(d.size())) p[k + 1][i + 2] -= d[i];
      }
    }
    return p;
  }();
  return table;
}

// The smallest |a + c z| on [lo, hi]; 0 when it changes sign there.
long double affine_min_abs(long double a, long double c, long double lo, long double hi) {
  const long double u = a + c * lo, v = a + c * hi;
  if ((u <= 0) != (v <= 0) || u == 0 || v == 0) return 0;
  return std::min(std::abs(u), std::abs(v));
}

}  // namespace

const AnalyticForm* analytic_form(const std::string& catalog_name) {
  auto it = forms().find(catalog_name);
  return it == forms().end() ? nullptr : &it->second;
}

void form_derivatives(const AnalyticForm& f, long double z, int order, long double* out) {
  switch (f.family) {
    case Family::Power: {
      // z^(n - k) by multiplication, not powl: the certificate's scan evaluates these at every
      // cell (continuous/continuous.cpp), and powl of an exponent above 3 costs a microsecond.
      // At most 5 roundings, well within the scan's allowance of 64 ulp a term.
      const int top = std::min(order, f.n);
      long double power = 1;  // z^(n - k) for k = top, top - 1, ..., 0
      for (int i = top; i < f.n; ++i) power *= z;
      for (int k = order; k > top; --k) out[k] = 0.0L;
      for (int k = top; k >= 0; --k, power *= z) out[k] = falling(f.n, k) * power;
      return;
    }
    case Family::Exp: {
      const long double e = std::exp(f.c * z);
      long double ck = 1;
      for (int k = 0; k <= order; ++k, ck *= f.c) out[k] = ck * e;
      return;
    }
    case Family::Sine: {
      const long double s = std::sin(f.a * z + f.b), c = std::cos(f.a * z + f.b);
      const long double cycle[4] = {s, c, -s, -c};
      long double wk = 1;
      for (int k = 0; k <= order; ++k, wk *= f.a) out[k] = wk * cycle[k % 4];
      return;
    }
    case Family::AffinePower: {
      const long double u = f.a + f.c * z;
      long double ck = 1;
      for (int k = 0; k <= order; ++k, ck *= f.c)
        out[k] = falling(f.b, k) * ck * std::pow(u, f.b - k);
      return;
    }
    case Family::Log: {
      const long double u = 1 + f.c * z;
      out[0] = std::log1p(f.c * z);
      long double ck = f.c;
      for (int k = 1; k <= order; ++k, ck *= f.c)
        out[k] = (k % 2 ? 1.0L : -1.0L) * factorial(k - 1) * ck / std::pow(u, k);
      return;
    }
    case Family::Pole:
      for (int k = 0; k <= order; ++k) {
        const complex d = pole_derivative(z, complex(f.a, f.b), k);
        out[k] = f.n ? d.imag() : d.real();
      }
      return;
    case Family::Atan:
      out[0] = std::atan(f.c * z);
      for (int k = 1; k <= order; ++k)
        out[k] = pole_derivative(z, complex(0, 1 / f.c), k - 1).imag();
      return;
    case Family::Tanh: {
      const long double t = std::tanh(f.a * (z - f.b));
      const auto& p = tanh_polynomials();
      long double sk = 1;
      for (int k = 0; k <= order; ++k, sk *= f.a) {
        long double v = 0;
        for (int i = int(p[k].size()) - 1; i >= 0; --i) v = v * t + p[k][i];
        out[k] = sk * v;
      }
      return;
    }
    case Family::Gauss: {
      // d^k/dx^k e^{-x^2} = (-1)^k H_k(x) e^{-x^2} (physicists' Hermite), x = sqrt(a) (z - b).
      const long double r = std::sqrt(f.a), x = r * (z - f.b), g = std::exp(-x * x);
      long double h0 = 1, h1 = 2 * x, rk = 1;
      for (int k = 0; k <= order; ++k, rk *= r) {
        const long double hk = k == 0 ? h0 : h1;
        out[k] = (k % 2 ? -1.0L : 1.0L) * rk * hk * g;
        if (k >= 1) {
          const long double next = 2 * x * h1 - 2 * k * h0;
          h0 = h1, h1 = next;
        }
      }
      return;
    }
    case Family::ZExp: {
      const long double e = std::exp(z);
      for (int k = 0; k <= order; ++k) out[k] = (z + k) * e;
      return;
    }
  }
}

long double form_derivative_bound(const AnalyticForm& f, int K, long double a, long double b) {
  switch (f.family) {
    case Family::Power:
      return K > f.n ? 0.0L
                     : falling(f.n, K) * std::pow(std::max(std::abs(a), std::abs(b)), f.n - K);
    case Family::Exp:
      return std::pow(std::abs(f.c), K) * std::exp(std::max(f.c * a, f.c * b));
    case Family::Sine:
      return std::pow(f.a, K);
    case Family::AffinePower: {
      const long double m = affine_min_abs(f.a, f.c, a, b);
      const long double e = f.b - K;
      if (e >= 0)
        return std::abs(falling(f.b, K)) * std::pow(std::abs(f.c), K) *
               std::pow(std::max(std::abs(f.a + f.c * a), std::abs(f.a + f.c * b)), e);
      return m == 0 ? kInf
                    : std::abs(falling(f.b, K)) * std::pow(std::abs(f.c), K) * std::pow(m, e);
    }
    case Family::Log: {
      const long double m = affine_min_abs(1, f.c, a, b);
      if (m == 0) return kInf;
      if (K == 0) return std::max(std::abs(std::log1p(f.c * a)), std::abs(std::log1p(f.c * b)));
      return factorial(K - 1) * std::pow(std::abs(f.c), K) / std::pow(m, K);
    }
    case Family::Pole:
      return factorial(K) / std::pow(distance(a, b, complex(f.a, f.b)), K + 1);
    case Family::Atan:
      if (K == 0) return std::max(std::abs(std::atan(f.c * a)), std::abs(std::atan(f.c * b)));
      return factorial(K - 1) / std::pow(distance(a, b, complex(0, 1 / f.c)), K);
    case Family::Tanh: {
      long double sum = 0;  // |P_K(t)| <= sum |coefficients| for |t| <= 1
      for (long double c : tanh_polynomials()[K]) sum += std::abs(c);
      return std::pow(f.a, K) * sum;
    }
    case Family::Gauss:
      // Cramér's inequality: |H_k(x)| e^{-x^2/2} <= 1.086435 2^{k/2} sqrt(k!).
      return std::pow(f.a, K / 2.0L) * 1.0865L * std::sqrt(std::pow(2.0L, K) * factorial(K));
    case Family::ZExp:
      return std::max(std::abs(a + K), std::abs(b + K)) * std::exp(b);
  }
  return kInf;
}

}  // namespace mb
