#pragma once
// Basis functions b : I -> R^m (docs/reference.md §1): the 37-function catalog of §5 under stable
// names, and user-defined expressions (muparser, variable `z`). Evaluated on arrays.
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace mb {

struct AnalyticForm;  // basis/basis_derivatives.h

class BasisFunction {
 public:
  // A catalog name ("z^2", "exp(-4z)", "sin(2 pi z)"; spaces and '*' are ignored when matching)
  // or an expression in z ("z^2*exp(-z)", "sin(2*pi*z)"; `pi` is defined as std::numbers::pi).
  static BasisFunction parse(const std::string& name_or_expression);
  // v -> f(-v): the basis of Problem 1 for the reflected depth v = -z (docs/reference.md §2, "The
  // maximum": the least mass behind z_f is the least mass in front of -z_f of the reflected
  // distribution, whose moments E f(-v) are the original ones). Named "reflected(<name>)";
  // derivatives and their bounds follow by the chain rule, so a catalog function stays certified.
  // Reflecting twice gives f back.
  static BasisFunction reflected(const BasisFunction& f);
  const std::string& name() const { return name_; }
  void evaluate(std::span<const double> z, std::span<double> out) const;
  double operator()(double z) const;
  // Catalog functions have closed-form derivatives (basis/basis_derivatives.h); expressions not.
  bool has_derivatives() const { return analytic_ != nullptr; }
  // out[k] = b^(k)(z), k = 0..order, in long double (has_derivatives() only).
  void derivatives(long double z, int order, long double* out) const;
  // A proven bound of |b^(order)| on [a, b] (has_derivatives() only).
  long double derivative_bound(int order, long double a, long double b) const;

 private:
  std::string name_;
  bool reflected_ = false;  // evaluated at -z
  const AnalyticForm* analytic_ = nullptr;
  std::function<double(double)> scalar_;
  std::shared_ptr<struct ExpressionEvaluator> expression_;
};

class Basis {
 public:
  Basis() = default;
  explicit Basis(std::vector<BasisFunction> functions) : functions_(std::move(functions)) {}
  // Names/expressions, named sets (power4, trig4, power2 (VSM), power6), or a candidate as a sweep
  // prints it ("z; z^2; z^3; z^4"): each item may hold several, separated by ';'.
  static Basis parse(const std::vector<std::string>& items);
  size_t size() const { return functions_.size(); }
  const BasisFunction& operator[](size_t j) const { return functions_[j]; }
  std::vector<std::string> names() const;
  // Every function reflected (BasisFunction::reflected): the basis of the reflected depths -z.
  Basis reflected() const;
  // Rejects (InputError naming the function and a point) a function that is not finite or has a
  // pole on [lo, hi]: sampled densely, each sign change bisected and each local peak of |f|
  // narrowed; a value there far beyond every sampled one is a pole. Every command calls this
  // (through check_independent) before any work, so no solver meets such a function.
  void check_admissible(double lo, double hi) const;
  // check_admissible, then rejects (InputError naming the functions) a basis that is numerically
  // linearly dependent together with the constant on [lo, hi].
  void check_independent(double lo, double hi) const;

 private:
  std::vector<BasisFunction> functions_;
};

// The 37 catalog names of docs/reference.md §5, in catalog order (candidate ranks use this order).
const std::vector<std::string>& catalog_names();
// Convolution shadow maps' 2M channels (seed 001): cos and sin of (2k - 1) pi z, k = 1..M, as
// expressions of z.
std::vector<std::string> csm_channels(int terms);
// Named sets: "power4" -> {z, z^2, z^3, z^4}, ..., "csm3" -> CSM's channels for M = 3; empty
// when `name` is not a set.
std::vector<std::string> named_basis_set(const std::string& name);

}  // namespace mb
