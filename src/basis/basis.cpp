#include "basis/basis.h"

#include <muParser.h>

#include <cmath>
#include <map>
#include <mutex>
#include <numbers>

#include "basis/basis_derivatives.h"
#include "util/eigen.h"
#include "util/error.h"
#include "util/name_list.h"
#include "util/number_text.h"

namespace mb {

namespace {
constexpr double kPi = std::numbers::pi;

// docs/reference.md §5. Built in (not parsed) so the sweep evaluates them at full speed and exactly
// as written; their names are the stable identifiers stored in results.
const std::vector<std::pair<std::string, std::function<double(double)>>>& catalog() {
  static const std::vector<std::pair<std::string, std::function<double(double)>>> table = {
      {"z", [](double z) { return z; }},
      {"z^2", [](double z) { return z * z; }},
      {"z^3", [](double z) { return z * z * z; }},
      {"z^4", [](double z) { return (z * z) * (z * z); }},
      {"z^5", [](double z) { return (z * z) * (z * z) * z; }},
      {"z^6", [](double z) { return (z * z * z) * (z * z * z); }},
      {"exp(z)", [](double z) { return std::exp(z); }},
      {"exp(-z)", [](double z) { return std::exp(-z); }},
      {"exp(2z)", [](double z) { return std::exp(2 * z); }},
      {"exp(-2z)", [](double z) { return std::exp(-2 * z); }},
      {"exp(4z)", [](double z) { return std::exp(4 * z); }},
      {"exp(-4z)", [](double z) { return std::exp(-4 * z); }},
      {"exp(8z)", [](double z) { return std::exp(8 * z); }},
      {"exp(-8z)", [](double z) { return std::exp(-8 * z); }},
      {"sin(pi z)", [](double z) { return std::sin(kPi * z); }},
      {"cos(pi z)", [](double z) { return std::cos(kPi * z); }},
      {"sin(2 pi z)", [](double z) { return std::sin(2 * kPi * z); }},
      {"cos(2 pi z)", [](double z) { return std::cos(2 * kPi * z); }},
      {"sin(3 pi z)", [](double z) { return std::sin(3 * kPi * z); }},
      {"cos(3 pi z)", [](double z) { return std::cos(3 * kPi * z); }},
      {"sin(4 pi z)", [](double z) { return std::sin(4 * kPi * z); }},
      {"cos(4 pi z)", [](double z) { return std::cos(4 * kPi * z); }},
      {"sin(pi z / 2)", [](double z) { return std::sin(kPi * z / 2); }},
      {"1/(1+z)", [](double z) { return 1 / (1 + z); }},
      {"1/(1+z)^2", [](double z) { return 1 / ((1 + z) * (1 + z)); }},
      {"1/(2-z)", [](double z) { return 1 / (2 - z); }},
      {"1/(1+z^2)", [](double z) { return 1 / (1 + z * z); }},
      {"z/(1+z^2)", [](double z) { return z / (1 + z * z); }},
      {"1/(1+4z)", [](double z) { return 1 / (1 + 4 * z); }},
      {"log(1+z)", [](double z) { return std::log1p(z); }},
      {"log(1+4z)", [](double z) { return std::log1p(4 * z); }},
      {"atan(4z)", [](double z) { return std::atan(4 * z); }},
      {"tanh(4(z-1/2))", [](double z) { return std::tanh(4 * (z - 0.5)); }},
      {"exp(-z^2)", [](double z) { return std::exp(-z * z); }},
      {"exp(-16(z-1/2)^2)", [](double z) { return std::exp(-16 * (z - 0.5) * (z - 0.5)); }},
      {"z exp(z)", [](double z) { return z * std::exp(z); }},
      {"sqrt(1+z)", [](double z) { return std::sqrt(1 + z); }},
  };
  return table;
}

std::string normalized(const std::string& s) {
  std::string out;
  for (char c : s)
    if (c != ' ' && c != '*') out += c;
  return out;
}
}  // namespace

// muparser evaluates one expression object at a time; each BasisFunction owns its parser and
// serialises access (expressions are evaluated once per grid or map, not in inner loops).
struct ExpressionEvaluator {
  mu::Parser parser;
  double z = 0;
  std::mutex mutex;
};

const std::vector<std::string>& catalog_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> n;
    for (const auto& [name, _] : catalog()) n.push_back(name);
    return n;
  }();
  return names;
}

std::vector<std::string> csm_channels(int terms) {
  std::vector<std::string> functions;
  for (int k = 1; k <= terms; ++k) {
    const std::string c = std::to_string(2 * k - 1) + "*pi*z";
    functions.push_back("cos(" + c + ")");
    functions.push_back("sin(" + c + ")");
  }
  return functions;
}

std::vector<std::string> named_basis_set(const std::string& name) {
  static const std::map<std::string, std::vector<std::string>> sets = {
      {"power4", {"z", "z^2", "z^3", "z^4"}},
      {"power6", {"z", "z^2", "z^3", "z^4", "z^5", "z^6"}},
      {"power2", {"z", "z^2"}},
      {"trig4", {"sin(2 pi z)", "cos(2 pi z)", "sin(4 pi z)", "cos(4 pi z)"}},
      {"trig2", {"sin(2 pi z)", "cos(2 pi z)"}},
  };
  auto it = sets.find(name);
  if (it != sets.end()) return it->second;
  // csm1 .. csm7: so that lp:csm3 is the sharp bound of CSM's own information (M = 8 would
  // need 16 functions, beyond the LP's 15).
  if (name.size() == 4 && name.rfind("csm", 0) == 0 && name[3] >= '1' && name[3] <= '7')
    return csm_channels(name[3] - '0');
  return {};
}

BasisFunction BasisFunction::parse(const std::string& text) {
  BasisFunction f;
  for (const auto& [name, function] : catalog()) {
    if (normalized(name) == normalized(text)) {
      f.name_ = name;
      f.scalar_ = function;
      f.analytic_ = analytic_form(name);
      return f;
    }
  }
  auto evaluator = std::make_shared<ExpressionEvaluator>();
  try {
    evaluator->parser.DefineVar("z", &evaluator->z);
    evaluator->parser.DefineConst("pi", kPi);
    evaluator->parser.SetExpr(text);
    evaluator->z = 0.5;
    evaluator->parser.Eval();  // syntax errors surface here
  } catch (const mu::Parser::exception_type& e) {
    throw InputError("basis function '" + text +
                     "': not a catalog name and not a valid expression in z (" + e.GetMsg() + ")");
  }
  f.name_ = text;
  f.expression_ = evaluator;
  return f;
}

BasisFunction BasisFunction::reflected(const BasisFunction& f) {
  BasisFunction g = f;
  static const std::string kPrefix = "reflected(";
  g.reflected_ = !f.reflected_;
  g.name_ = g.reflected_ ? kPrefix + f.name_ + ")"
                         : f.name_.substr(kPrefix.size(), f.name_.size() - kPrefix.size() - 1);
  return g;
}

double BasisFunction::operator()(double z) const {
  if (reflected_) z = -z;  // exact: f(-v) is f's own value at the negated point
  if (scalar_) return scalar_(z);
  std::lock_guard lock(expression_->mutex);
  expression_->z = z;
  return expression_->parser.Eval();
}

void BasisFunction::evaluate(std::span<const double> z, std::span<double> out) const {
  const double sign = reflected_ ? -1.0 : 1.0;
  if (scalar_) {
    for (size_t i = 0; i < z.size(); ++i) out[i] = scalar_(sign * z[i]);
    return;
  }
  std::lock_guard lock(expression_->mutex);
  for (size_t i = 0; i < z.size(); ++i) {
    expression_->z = sign * z[i];
    out[i] = expression_->parser.Eval();
  }
}

void BasisFunction::derivatives(long double z, int order, long double* out) const {
  if (!reflected_) return form_derivatives(*analytic_, z, order, out);
  // d^k/dv^k f(-v) = (-1)^k f^(k)(-v).
  form_derivatives(*analytic_, -z, order, out);
  for (int k = 1; k <= order; k += 2) out[k] = -out[k];
}

long double BasisFunction::derivative_bound(int order, long double a, long double b) const {
  // |(-1)^k f^(k)(-v)| over v in [a, b] is |f^(k)| over [-b, -a].
  return reflected_ ? form_derivative_bound(*analytic_, order, -b, -a)
                    : form_derivative_bound(*analytic_, order, a, b);
}

Basis Basis::parse(const std::vector<std::string>& items) {
  std::vector<BasisFunction> functions;
  // An item may be a whole candidate as a sweep prints it ("z; z^2; z^3; z^4").
  for (const auto& given : items) {
    std::vector<std::string> listed = split_list(given, ";");
    if (listed.empty()) listed = {given};  // "" or " ; ": refused below, naming the item
    for (const std::string& item : listed) {
      auto set = named_basis_set(item);
      if (!set.empty()) {
        for (const auto& name : set) functions.push_back(BasisFunction::parse(name));
      } else {
        functions.push_back(BasisFunction::parse(item));
      }
    }
  }
  if (functions.empty()) throw InputError("basis: no functions given");
  return Basis(std::move(functions));
}

Basis Basis::reflected() const {
  std::vector<BasisFunction> functions;
  for (const auto& f : functions_) functions.push_back(BasisFunction::reflected(f));
  return Basis(std::move(functions));
}

std::vector<std::string> Basis::names() const {
  std::vector<std::string> out;
  for (const auto& f : functions_) out.push_back(f.name());
  return out;
}

void Basis::check_admissible(double lo, double hi) const {
  const int samples = 4097;
  // A pole: narrowing towards it multiplies |f| by far more than smooth growth between samples
  // can (exp(40z), the steepest function a user is likely to give, grows by 1.01 per sample).
  const double kPoleFactor = 1e3;
  std::vector<double> z(samples), values(samples);
  for (int i = 0; i < samples; ++i) z[i] = lo + (hi - lo) * i / (samples - 1);
  z.back() = hi;
  // Appended piece by piece: GCC 12 warns (-Wstringop-overflow, a false positive) on the chain of
  // temporaries "[" + ... would make here.
  std::string interval = "[";
  interval.append(round_trip(lo)).append(", ").append(round_trip(hi)).append("]");
  for (const auto& f : functions_) {
    f.evaluate(z, values);
    double peak = 0;
    for (int i = 0; i < samples; ++i) {
      if (!std::isfinite(values[i]))
        throw InputError("basis function '" + f.name() +
                         "' is not finite at z = " + round_trip(z[i]) + " on " + interval +
                         " (the admissible interval, lp.lo and lp.hi)");
      peak = std::max(peak, std::abs(values[i]));
    }
    const double limit = kPoleFactor * std::max(peak, 1.0);
    auto pole = [&](double at, double value) {
      if (!std::isfinite(value) || std::abs(value) > limit)
        throw InputError("basis function '" + f.name() + "' has a pole near z = " + round_trip(at) +
                         " on " + interval + " (|f| reaches " + round_trip(std::abs(value)) +
                         "): not admissible there");
    };
    for (int i = 0; i + 1 < samples; ++i) {
      // A sign change: bisect it. A zero leaves |f| small, a pole makes it grow without bound.
      if ((values[i] < 0) != (values[i + 1] < 0) && values[i] != 0 && values[i + 1] != 0) {
        double a = z[i], b = z[i + 1], fa = values[i];
        for (int step = 0; step < 80 && b - a > 0; ++step) {
          const double m = 0.5 * (a + b), fm = f(m);
          pole(m, fm);
          if ((fm < 0) == (fa < 0))
            a = m, fa = fm;
          else
            b = m;
        }
      }
      // A local peak of |f| (an even pole keeps its sign): narrow it by ternary search.
      if (i > 0 && std::abs(values[i]) > std::abs(values[i - 1]) &&
          std::abs(values[i]) > std::abs(values[i + 1])) {
        double a = z[i - 1], b = z[i + 1];
        for (int step = 0; step < 80; ++step) {
          const double m1 = a + (b - a) / 3, m2 = b - (b - a) / 3, f1 = f(m1), f2 = f(m2);
          pole(m1, f1);
          pole(m2, f2);
          if (std::abs(f1) < std::abs(f2))
            a = m1;
          else
            b = m2;
        }
      }
    }
  }
}

void Basis::check_independent(double lo, double hi) const {
  check_admissible(lo, hi);
  // Columns 1, b_1..b_m sampled densely on [lo, hi] and scaled to unit norm; a relative
  // singular value below 1e-10 means the LP rows are numerically dependent (z^5, z^6 next to the
  // lower powers sit near 1e-6 on [0, 1] and pass).
  const int samples = 2048, m = int(functions_.size());
  std::vector<double> z(samples);
  for (int i = 0; i < samples; ++i) z[i] = lo + (hi - lo) * i / (samples - 1);
  Eigen::MatrixXd A(samples, m + 1);
  A.col(0).setOnes();
  std::vector<double> values(samples);
  for (int j = 0; j < m; ++j) {
    functions_[j].evaluate(z, values);
    for (int i = 0; i < samples; ++i) {
      if (!std::isfinite(values[i]))
        throw InputError("basis function '" + functions_[j].name() +
                         "' is not finite at z = " + round_trip(z[i]));
      A(i, j + 1) = values[i];
    }
  }
  auto smallest_relative_singular_value = [](Eigen::MatrixXd M) {
    for (int c = 0; c < M.cols(); ++c) {
      double norm = M.col(c).norm();
      if (norm > 0) M.col(c) /= norm;
    }
    Eigen::JacobiSVD<Eigen::MatrixXd> svd(M);
    const auto& s = svd.singularValues();
    return s(s.size() - 1) / s(0);
  };
  const double kTolerance = 1e-10;
  if (smallest_relative_singular_value(A) >= kTolerance) return;
  // Name the culprit: the function whose removal makes the rest independent.
  std::string culprits;
  for (int j = 0; j < m; ++j) {
    Eigen::MatrixXd rest(samples, m);
    rest << A.leftCols(j + 1), A.rightCols(m - j - 1);
    if (smallest_relative_singular_value(rest) >= kTolerance)
      culprits += (culprits.empty() ? "" : ", ") + functions_[j].name();
  }
  std::string all;
  for (const auto& f : functions_) all += (all.empty() ? "" : ", ") + f.name();
  throw InputError("basis {" + all + "} is linearly dependent together with the constant on [" +
                   round_trip(lo) + ", " + round_trip(hi) + "]" +
                   (culprits.empty() ? "" : "; remove one of: " + culprits));
}

}  // namespace mb
