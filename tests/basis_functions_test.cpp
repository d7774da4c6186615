// Basis functions (src/basis/, docs/reference.md §1 and §5): the 37 catalog functions against
// closed forms written out here, named sets and expressions, the closed-form derivatives against
// hand-derived ones and finite differences, their proven bounds, and the errors of bad input.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "basis/basis.h"
#include "basis/basis_derivatives.h"
#include "test_support.h"
#include "util/error.h"

namespace mb {
namespace {

constexpr double kPi = std::numbers::pi;

struct ClosedForm {
  std::string name;
  std::function<double(double)> value, first, second;
};

// docs/reference.md §5, each function with its first and second derivative derived by hand.
std::vector<ClosedForm> closed_forms() {
  auto sq = [](double x) { return x * x; };
  std::vector<ClosedForm> f = {
      {"z", [](double z) { return z; }, [](double) { return 1.0; }, [](double) { return 0.0; }},
      {"exp(z)", [](double z) { return std::exp(z); }, [](double z) { return std::exp(z); },
       [](double z) { return std::exp(z); }},
      {"1/(1+z)", [](double z) { return 1 / (1 + z); },
       [](double z) { return -1 / ((1 + z) * (1 + z)); },
       [](double z) { return 2 / std::pow(1 + z, 3); }},
      {"1/(1+z)^2", [](double z) { return std::pow(1 + z, -2); },
       [](double z) { return -2 * std::pow(1 + z, -3); },
       [](double z) { return 6 * std::pow(1 + z, -4); }},
      {"1/(2-z)", [](double z) { return 1 / (2 - z); },
       [](double z) { return 1 / ((2 - z) * (2 - z)); },
       [](double z) { return 2 / std::pow(2 - z, 3); }},
      {"1/(1+z^2)", [](double z) { return 1 / (1 + z * z); },
       [sq](double z) { return -2 * z / sq(1 + z * z); },
       [](double z) { return (6 * z * z - 2) / std::pow(1 + z * z, 3); }},
      {"z/(1+z^2)", [](double z) { return z / (1 + z * z); },
       [sq](double z) { return (1 - z * z) / sq(1 + z * z); },
       [](double z) { return (2 * z * z * z - 6 * z) / std::pow(1 + z * z, 3); }},
      {"1/(1+4z)", [](double z) { return 1 / (1 + 4 * z); },
       [sq](double z) { return -4 / sq(1 + 4 * z); },
       [](double z) { return 32 / std::pow(1 + 4 * z, 3); }},
      {"log(1+z)", [](double z) { return std::log(1 + z); }, [](double z) { return 1 / (1 + z); },
       [sq](double z) { return -1 / sq(1 + z); }},
      {"log(1+4z)", [](double z) { return std::log(1 + 4 * z); },
       [](double z) { return 4 / (1 + 4 * z); }, [sq](double z) { return -16 / sq(1 + 4 * z); }},
      {"atan(4z)", [](double z) { return std::atan(4 * z); },
       [](double z) { return 4 / (1 + 16 * z * z); },
       [sq](double z) { return -128 * z / sq(1 + 16 * z * z); }},
      {"tanh(4(z-1/2))", [](double z) { return std::tanh(4 * (z - 0.5)); },
       [sq](double z) { return 4 * (1 - sq(std::tanh(4 * (z - 0.5)))); },
       [sq](double z) {
         const double t = std::tanh(4 * (z - 0.5));
         return -32 * t * (1 - sq(t));
       }},
      {"exp(-z^2)", [](double z) { return std::exp(-z * z); },
       [](double z) { return -2 * z * std::exp(-z * z); },
       [](double z) { return (4 * z * z - 2) * std::exp(-z * z); }},
      {"exp(-16(z-1/2)^2)", [sq](double z) { return std::exp(-16 * sq(z - 0.5)); },
       [sq](double z) { return -32 * (z - 0.5) * std::exp(-16 * sq(z - 0.5)); },
       [sq](double z) { return (1024 * sq(z - 0.5) - 32) * std::exp(-16 * sq(z - 0.5)); }},
      {"z exp(z)", [](double z) { return z * std::exp(z); },
       [](double z) { return (z + 1) * std::exp(z); },
       [](double z) { return (z + 2) * std::exp(z); }},
      {"sqrt(1+z)", [](double z) { return std::sqrt(1 + z); },
       [](double z) { return 0.5 / std::sqrt(1 + z); },
       [](double z) { return -0.25 / std::pow(1 + z, 1.5); }},
      {"sin(pi z / 2)", [](double z) { return std::sin(kPi * z / 2); },
       [](double z) { return kPi / 2 * std::cos(kPi * z / 2); },
       [](double z) { return -kPi * kPi / 4 * std::sin(kPi * z / 2); }},
  };
  for (int n = 2; n <= 6; ++n)
    f.push_back({"z^" + std::to_string(n), [n](double z) { return std::pow(z, n); },
                 [n](double z) { return n * std::pow(z, n - 1); },
                 [n](double z) { return n * (n - 1) * std::pow(z, n - 2); }});
  for (double c : {-8.0, -4.0, -2.0, -1.0, 2.0, 4.0, 8.0}) {
    const std::string factor = c == -1 ? "-" : std::to_string(int(c));
    f.push_back({"exp(" + factor + "z)", [c](double z) { return std::exp(c * z); },
                 [c](double z) { return c * std::exp(c * z); },
                 [c](double z) { return c * c * std::exp(c * z); }});
  }
  for (int k = 1; k <= 4; ++k) {
    const double w = k * kPi;
    const std::string arg = k == 1 ? "pi z" : std::to_string(k) + " pi z";
    f.push_back({"sin(" + arg + ")", [w](double z) { return std::sin(w * z); },
                 [w](double z) { return w * std::cos(w * z); },
                 [w](double z) { return -w * w * std::sin(w * z); }});
    f.push_back({"cos(" + arg + ")", [w](double z) { return std::cos(w * z); },
                 [w](double z) { return -w * std::sin(w * z); },
                 [w](double z) { return -w * w * std::cos(w * z); }});
  }
  return f;
}

double relative(double a, double b) {
  return std::abs(a - b) / std::max(1.0, std::abs(b));
}

TEST(Basis, CatalogFunctionsEvaluateTheirClosedForms) {
  const auto forms = closed_forms();
  ASSERT_EQ(forms.size(), catalog_names().size());
  const std::vector<double> z = {0, 0.03, 0.25, 0.5, 0.61, 0.97, 1, -0.2, 1.8};
  std::vector<double> values(z.size());
  for (const auto& form : forms) {
    const BasisFunction f = BasisFunction::parse(form.name);
    EXPECT_EQ(f.name(), form.name);
    f.evaluate(z, values);
    for (size_t i = 0; i < z.size(); ++i) {
      EXPECT_LE(relative(f(z[i]), form.value(z[i])), 1e-14) << form.name << " at " << z[i];
      EXPECT_EQ(values[i], f(z[i])) << form.name << " at " << z[i];  // arrays = one at a time
    }
  }
}

TEST(Basis, NamedSetsExpandToTheirFunctionsInOrder) {
  using Names = std::vector<std::string>;
  EXPECT_EQ(Basis::parse({"power2"}).names(), (Names{"z", "z^2"}));
  EXPECT_EQ(Basis::parse({"power4"}).names(), (Names{"z", "z^2", "z^3", "z^4"}));
  EXPECT_EQ(Basis::parse({"power6"}).names(), (Names{"z", "z^2", "z^3", "z^4", "z^5", "z^6"}));
  EXPECT_EQ(Basis::parse({"trig2"}).names(), (Names{"sin(2 pi z)", "cos(2 pi z)"}));
  EXPECT_EQ(Basis::parse({"trig4"}).names(),
            (Names{"sin(2 pi z)", "cos(2 pi z)", "sin(4 pi z)", "cos(4 pi z)"}));
  // Sets and single functions mix, in the order given.
  EXPECT_EQ(Basis::parse({"exp(-z)", "power2", "z^2*exp(-z)"}).names(),
            (Names{"exp(-z)", "z", "z^2", "z^2*exp(-z)"}));
  // A candidate as a sweep prints it ("a; b; c"), alone or beside other items.
  EXPECT_EQ(Basis::parse({"z^3; cos(pi z); 1/(1+z^2); exp(-z^2)"}).names(),
            (Names{"z^3", "cos(pi z)", "1/(1+z^2)", "exp(-z^2)"}));
  EXPECT_EQ(Basis::parse({"exp(-z); power2", "z^3"}).names(),
            (Names{"exp(-z)", "z", "z^2", "z^3"}));
  EXPECT_THROW(Basis::parse({" ; "}), InputError);
  // CSM's channels: cos and sin of (2k - 1) pi z, k = 1..M, for M = 1..7 only, written with the
  // parser's `pi` (std::numbers::pi, not muparser's `_pi`, which GCC builds of muparser define as
  // 3.141592653589, 2.5e-13 relative below pi).
  for (int m = 1; m <= 7; ++m) {
    const Basis csm = Basis::parse({"csm" + std::to_string(m)});
    ASSERT_EQ(csm.size(), size_t(2 * m));
    for (int k = 1; k <= m; ++k)
      for (double z : {0.1, 0.45, 0.9}) {
        EXPECT_NEAR(csm[2 * k - 2](z), std::cos((2 * k - 1) * kPi * z), 1e-13) << m << " " << k;
        EXPECT_NEAR(csm[2 * k - 1](z), std::sin((2 * k - 1) * kPi * z), 1e-13) << m << " " << k;
      }
  }
  for (const char* not_a_set : {"csm0", "csm8", "csm", "power5", "trig3", "Power4", "z"})
    EXPECT_TRUE(named_basis_set(not_a_set).empty()) << not_a_set;
}

TEST(Basis, NamesMatchTheCatalogWithSpacesAndStarsIgnored) {
  EXPECT_EQ(BasisFunction::parse(" exp( -4 * z ) ").name(), "exp(-4z)");
  EXPECT_EQ(BasisFunction::parse("z*exp(z)").name(), "z exp(z)");
  EXPECT_EQ(BasisFunction::parse("tanh(4*(z-1/2))").name(), "tanh(4(z-1/2))");
  EXPECT_TRUE(BasisFunction::parse("sin(pi*z/2)").has_derivatives());
  // Not in the catalog (another spelling of the same function): an expression, evaluated by
  // muparser, with the same values but no closed-form derivatives.
  const BasisFunction spelled = BasisFunction::parse("exp(-4*z+0)");
  EXPECT_EQ(spelled.name(), "exp(-4*z+0)");
  EXPECT_FALSE(spelled.has_derivatives());
  for (double z : {0.0, 0.3, 1.0}) EXPECT_NEAR(spelled(z), std::exp(-4 * z), 1e-15);
}

TEST(Basis, ExpressionsEvaluateInZWithPiDefinedToDoublePrecision) {
  const BasisFunction f = BasisFunction::parse("z^2*exp(-z) + sin(pi*z) - cos(2*pi*z)/3");
  const std::vector<double> z = {0, 0.2, 0.5, 0.77, 1};
  std::vector<double> values(z.size());
  f.evaluate(z, values);
  for (size_t i = 0; i < z.size(); ++i) {
    const double expected =
        z[i] * z[i] * std::exp(-z[i]) + std::sin(kPi * z[i]) - std::cos(2 * kPi * z[i]) / 3;
    EXPECT_NEAR(f(z[i]), expected, 1e-15) << z[i];
    EXPECT_EQ(values[i], f(z[i])) << z[i];
  }
}

TEST(Basis, BadInputIsRefusedNamingTheFunction) {
  using testing_support::input_error_of;
  std::string m = input_error_of([] { Basis::parse({}); });
  EXPECT_NE(m.find("basis: no functions given"), std::string::npos) << m;
  for (const char* bad : {"sin(z", "y^2", "power5", "z +* 2", ""}) {
    m = input_error_of([bad] { Basis::parse({"z", bad}); });
    EXPECT_NE(m.find(std::string("basis function '") + bad +
                     "': not a catalog name and not a valid expression in z"),
              std::string::npos)
        << bad << ": " << m;
  }
}

TEST(Basis, FunctionsNotFiniteOrWithAPoleOnTheIntervalAreRefused) {
  using testing_support::input_error_of;
  // A pole on a sample point: not finite there, naming the interval and its keys.
  std::string m = input_error_of([] { Basis::parse({"z", "1/(z-0.5)"}).check_admissible(0, 1); });
  EXPECT_NE(m.find("basis function '1/(z-0.5)' is not finite at z = 0.5 on [0, 1] (the "
                   "admissible interval, lp.lo and lp.hi)"),
            std::string::npos)
      << m;
  // Between samples: found by bisecting the sign change (odd pole) or narrowing the peak (even).
  for (const char* pole : {"1/(z-0.31)", "1/(z-0.31)^2", "-3/(0.31-z)^3"}) {
    m = input_error_of([pole] { Basis::parse({pole}).check_admissible(0, 1); });
    const std::string said = std::string("basis function '") + pole + "' has a pole near z = ";
    const size_t at = m.find(said);
    ASSERT_NE(at, std::string::npos) << pole << ": " << m;
    EXPECT_NEAR(std::stod(m.substr(at + said.size())), 0.31, 1e-3) << pole << ": " << m;
    EXPECT_NE(m.find("on [0, 1]"), std::string::npos) << m;
  }
  m = input_error_of([] { Basis::parse({"sqrt(z)"}).check_admissible(-0.5, 1); });
  EXPECT_NE(m.find("'sqrt(z)' is not finite at z = -0.5"), std::string::npos) << m;
  // The same functions away from their poles, steep ones and zeros (sign changes) are admissible.
  for (const char* fine : {"1/(z-0.31)", "1/(z-0.31)^2", "sqrt(z)"})
    EXPECT_EQ(input_error_of([fine] { Basis::parse({fine}).check_admissible(0.4, 1); }), "")
        << fine;
  EXPECT_EQ(input_error_of([] {
              Basis::parse({"exp(40*z)", "sin(50*z)", "z-0.3", "tan(z)"}).check_admissible(0, 1);
            }),
            "");
  EXPECT_EQ(input_error_of([] { Basis::parse({"1/(2-z)"}).check_admissible(-1, 1.5); }), "");
  m = input_error_of([] { Basis::parse({"1/(2-z)"}).check_admissible(1, 3); });
  EXPECT_NE(m.find("'1/(2-z)'"), std::string::npos) << m;
}

TEST(BasisDerivatives, FirstAndSecondDerivativesAreTheClosedForms) {
  for (const auto& form : closed_forms()) {
    const BasisFunction f = BasisFunction::parse(form.name);
    ASSERT_TRUE(f.has_derivatives()) << form.name;
    for (double z : {0.0, 0.12, 0.5, 0.83, 1.0, -0.2, 1.4}) {
      long double d[3];
      f.derivatives(z, 2, d);
      EXPECT_LE(relative(double(d[0]), form.value(z)), 1e-14) << form.name << " at " << z;
      EXPECT_LE(relative(double(d[1]), form.first(z)), 1e-13) << form.name << " at " << z;
      EXPECT_LE(relative(double(d[2]), form.second(z)), 1e-12) << form.name << " at " << z;
    }
  }
  // Beyond its degree a power's derivatives vanish; a sinusoid's cycle with period four.
  const BasisFunction cube = BasisFunction::parse("z^3");
  long double d[kMaxDerivativeOrder + 1];
  cube.derivatives(0.7L, kMaxDerivativeOrder, d);
  EXPECT_EQ(double(d[3]), 6.0);
  for (int k = 4; k <= kMaxDerivativeOrder; ++k) EXPECT_EQ(double(d[k]), 0.0) << k;
  const BasisFunction sine = BasisFunction::parse("sin(2 pi z)");
  sine.derivatives(0.3L, kMaxDerivativeOrder, d);
  for (int k = 4; k <= kMaxDerivativeOrder; ++k)
    EXPECT_NEAR(double(d[k] / std::pow(2 * std::numbers::pi_v<long double>, 4)), double(d[k - 4]),
                1e-9 * std::max(1.0L, std::abs(d[k - 4])))
        << k;
}

TEST(BasisDerivatives, ClosedFormsMatchDifferencesAndBoundsHold) {
  // Each catalog function's derivatives against central differences of the one before (long
  // double), and each bound against the derivative's values on a fine sample of the interval.
  for (const std::string& name : catalog_names()) {
    const BasisFunction f = BasisFunction::parse(name);
    ASSERT_TRUE(f.has_derivatives()) << name;
    for (long double z : {0.05L, 0.37L, 0.81L}) {
      long double d[kMaxDerivativeOrder + 1], plus[kMaxDerivativeOrder + 1],
          minus[kMaxDerivativeOrder + 1];
      const long double h = 1e-6L;
      f.derivatives(z, 8, d);
      f.derivatives(z + h, 8, plus);
      f.derivatives(z - h, 8, minus);
      EXPECT_NEAR(double(d[0]), f(double(z)), 1e-15 * std::max(1.0, std::abs(double(d[0]))))
          << name;
      for (int k = 1; k <= 8; ++k) {
        const long double difference = (plus[k - 1] - minus[k - 1]) / (2 * h);
        EXPECT_NEAR(double(d[k]), double(difference), 1e-5 * std::max(1.0L, std::abs(d[k])))
            << name << " order " << k << " at " << double(z);
      }
    }
    for (int order : {1, 4, 8}) {
      const long double bound = f.derivative_bound(order, 0.2L, 0.6L);
      for (int i = 0; i <= 400; ++i) {
        long double d[kMaxDerivativeOrder + 1];
        f.derivatives(0.2L + 0.4L * i / 400, order, d);
        EXPECT_LE(std::abs(d[order]), bound * (1 + 1e-15L)) << name << " order " << order;
      }
    }
  }
}

TEST(BasisDerivatives, BoundsHoldOnEveryIntervalAndAreInfiniteAtPoles) {
  // Intervals beyond [0, 1], to either side of zero and up to every order the continuous
  // method asks for; a bound is infinite only where the function has a pole on the interval.
  const std::pair<long double, long double> intervals[] = {
      {0, 1}, {-0.2L, 0.3L}, {0.9L, 1.7L}, {-0.24L, -0.1L}, {0.45L, 0.45L}};
  for (const std::string& name : catalog_names()) {
    const BasisFunction f = BasisFunction::parse(name);
    for (const auto& [a, b] : intervals) {
      for (int order : {0, 2, 5, kMaxDerivativeOrder}) {
        const long double bound = f.derivative_bound(order, a, b);
        bool finite_everywhere = true;
        long double largest = 0;
        for (int i = 0; i <= 200; ++i) {
          long double d[kMaxDerivativeOrder + 1];
          f.derivatives(a + (b - a) * i / 200, order, d);
          finite_everywhere &= std::isfinite(d[order]);
          largest = std::max(largest, std::abs(d[order]));
        }
        if (std::isinf(bound)) continue;  // checked by the poles below
        EXPECT_TRUE(finite_everywhere) << name << " on [" << double(a) << ", " << double(b) << "]";
        EXPECT_LE(largest, bound * (1 + 1e-12L))
            << name << " order " << order << " on [" << double(a) << ", " << double(b) << "]";
      }
    }
  }
  const std::pair<const char*, std::pair<long double, long double>> poles[] = {
      {"1/(1+z)", {-1.5L, 0}},   {"1/(1+z)^2", {-2, -0.5L}}, {"1/(2-z)", {1.5L, 2.5L}},
      {"1/(1+4z)", {-0.5L, 0}},  {"log(1+z)", {-1, 0}},      {"log(1+4z)", {-0.3L, 0.2L}},
      {"sqrt(1+z)", {-1.5L, 0}},  // its derivatives' pole at -1
  };
  for (const auto& [name, interval] : poles)
    EXPECT_TRUE(
        std::isinf(BasisFunction::parse(name).derivative_bound(3, interval.first, interval.second)))
        << name;
  // Powers beyond their degree: exactly zero; exactly the endpoint's value where it is attained.
  EXPECT_EQ(double(BasisFunction::parse("z^3").derivative_bound(4, -1, 1)), 0.0);
  EXPECT_EQ(double(BasisFunction::parse("z^3").derivative_bound(1, 0.2L, 0.5L)), 3 * 0.25);
}

// BasisFunction::reflected, v -> f(-v) (docs/reference.md §2, "The maximum"): its values are f's
// at -v, its derivatives (-1)^k f^(k)(-v) (central differences of the order before, so a sign
// error shows), its bounds hold on intervals away from zero where f's own on [a, b] would not,
// and reflecting twice gives f back.
TEST(Basis, ReflectedFunctionsAreFAtMinusZWithTheirDerivativesAndBounds) {
  for (const std::string& name : catalog_names()) {
    const BasisFunction f = BasisFunction::parse(name);
    const BasisFunction g = BasisFunction::reflected(f);
    EXPECT_EQ(g.name(), "reflected(" + f.name() + ")");
    ASSERT_TRUE(g.has_derivatives()) << name;
    const std::vector<double> v = {-0.81, -0.37, -0.05};
    std::vector<double> values(v.size());
    g.evaluate(v, values);
    for (size_t i = 0; i < v.size(); ++i) {
      EXPECT_EQ(g(v[i]), f(-v[i])) << name;
      EXPECT_EQ(values[i], f(-v[i])) << name;
      long double d[kMaxDerivativeOrder + 1], original[kMaxDerivativeOrder + 1],
          plus[kMaxDerivativeOrder + 1], minus[kMaxDerivativeOrder + 1];
      const long double h = 1e-6L;
      g.derivatives(v[i], 8, d);
      f.derivatives(-(long double)v[i], 8, original);
      g.derivatives(v[i] + h, 8, plus);
      g.derivatives(v[i] - h, 8, minus);
      for (int k = 0; k <= 8; ++k)
        EXPECT_EQ(double(d[k]), double(k % 2 ? -original[k] : original[k])) << name << " " << k;
      for (int k = 1; k <= 8; ++k) {
        const long double difference = (plus[k - 1] - minus[k - 1]) / (2 * h);
        EXPECT_NEAR(double(d[k]), double(difference), 1e-5 * std::max(1.0L, std::abs(d[k])))
            << name << " order " << k << " at " << v[i];
      }
    }
    // On [-0.6, -0.2] (f's [0.2, 0.6] reflected): the bound is f's there, and holds.
    for (int order : {0, 1, 4, 8}) {
      const long double bound = g.derivative_bound(order, -0.6L, -0.2L);
      EXPECT_EQ(double(bound), double(f.derivative_bound(order, 0.2L, 0.6L))) << name;
      for (int i = 0; i <= 400; ++i) {
        long double d[kMaxDerivativeOrder + 1];
        g.derivatives(-0.6L + 0.4L * i / 400, order, d);
        EXPECT_LE(std::abs(d[order]), bound * (1 + 1e-15L)) << name << " order " << order;
      }
    }
    const BasisFunction twice = BasisFunction::reflected(g);
    EXPECT_EQ(twice.name(), f.name());
    EXPECT_EQ(twice(0.3), f(0.3)) << name;
  }
  // exp(4z) reflected on [-0.6, -0.2]: |g^(k)| reaches 4^k e^2.4 at -0.6, far above f's own bound
  // on [-0.6, -0.2], 4^k e^-0.8: the bound must come from [0.2, 0.6].
  const BasisFunction g = BasisFunction::reflected(BasisFunction::parse("exp(4z)"));
  EXPECT_GE(double(g.derivative_bound(3, -0.6L, -0.2L)), 64 * std::exp(2.4) * (1 - 1e-12));
  // An expression: evaluated at -v, no derivatives; a basis reflects function by function.
  const BasisFunction e = BasisFunction::parse("z^2*exp(-z) + sin(pi*z)");
  const BasisFunction r = BasisFunction::reflected(e);
  EXPECT_FALSE(r.has_derivatives());
  EXPECT_EQ(r.name(), "reflected(z^2*exp(-z) + sin(pi*z))");
  for (double v : {-0.7, -0.1, 0.4}) {
    EXPECT_EQ(r(v), e(-v));
    EXPECT_NEAR(r(v), v * v * std::exp(v) - std::sin(kPi * v), 1e-15);
  }
  const Basis basis = Basis::parse({"power4"}).reflected();
  EXPECT_EQ(basis.names(), (std::vector<std::string>{"reflected(z)", "reflected(z^2)",
                                                     "reflected(z^3)", "reflected(z^4)"}));
  EXPECT_EQ(basis[2](0.5), -0.125);
}

TEST(Basis, CatalogHas37DistinctIndependentFunctions) {
  EXPECT_EQ(catalog_names().size(), 37u);
  for (const auto& name : catalog_names()) EXPECT_EQ(BasisFunction::parse(name).name(), name);
  // Each catalog function with the constant is independent; so are the power and trig sets.
  Basis::parse({"power4"}).check_independent(0, 1);
  Basis::parse({"trig4"}).check_independent(0, 1);
  Basis::parse({"power6"}).check_independent(0, 1);
  // Names match with spaces and '*' ignored; expressions work through muparser.
  EXPECT_EQ(BasisFunction::parse("sin(2*pi*z)").name(), "sin(2 pi z)");
  EXPECT_NEAR(BasisFunction::parse("z^2*exp(-z)")(0.5), 0.25 * std::exp(-0.5), 1e-15);
}

TEST(Basis, DependentSetsAreRejectedNamingTheFunctions) {
  std::string m = testing_support::input_error_of([] {
    Basis::parse({"z", "z^2", "3*z"}).check_independent(0, 1);
  });
  EXPECT_NE(m.find("linearly dependent"), std::string::npos) << m;
  EXPECT_NE(m.find("3*z"), std::string::npos) << m;
  m = testing_support::input_error_of([] { Basis::parse({"1+z", "z"}).check_independent(0, 1); });
  EXPECT_NE(m.find("linearly dependent"), std::string::npos) << m;
  m = testing_support::input_error_of([] {
    Basis::parse({"z", "cos(pi*z)^2", "cos(2 pi z)"}).check_independent(0, 1);
  });
  EXPECT_NE(m.find("linearly dependent"), std::string::npos) << m;
  EXPECT_NE(testing_support::input_error_of([] {
              BasisFunction::parse("sin(z");
            }).find("not a valid expression"),
            std::string::npos);
}

}  // namespace
}  // namespace mb
