#include "eval/technique.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "eval/lp_technique.h"
#include "moments/canonical.h"
#include "moments/chebyshev.h"
#include "moments/hamburger.h"
#include "moments/hausdorff.h"
#include "moments/tmsm.h"
#include "util/error.h"
#include "util/number_text.h"

namespace mb {

namespace {

class PcfTechnique : public Technique {
 public:
  PcfTechnique() : Technique("pcf", Basis(), double_storage()) {}
  double shadow(const FragmentInput& in) override { return in.pcf; }
};

// F_Z(z_f - delta_f) itself: every valid lower bound lies below it, so under the receiver-plane
// reference its error is the floor that no technique can go under (REFERENCE.md §3).
class OracleTechnique : public Technique {
 public:
  OracleTechnique() : Technique("oracle", Basis(), double_storage()) {}
  double shadow(const FragmentInput& in) override { return in.oracle; }
};

class VsmTechnique : public Technique {
 public:
  explicit VsmTechnique(double min_variance)
      : Technique("vsm", Basis::parse({"power2"}), double_storage()), min_variance_(min_variance) {}
  double shadow(const FragmentInput& in) override {
    return vsm_bound(in.moments.data(), in.zf, min_variance_);
  }

 private:
  double min_variance_;
};

class EsmTechnique : public Technique {
 public:
  explicit EsmTechnique(double c)
      : Technique("esm", Basis::parse({"exp(" + round_trip(c) + "*z)"}), double_storage()), c_(c) {}
  double shadow(const FragmentInput& in) override { return esm_bound(in.moments[0], in.zf, c_); }

 private:
  double c_;
};

// Exponential variance shadow maps (seed 000 §2): VSM on the warped depths w = exp(c+ z) and
// w = -exp(-c- z). Both warps increase with z, so P(Z < z_f) = P(w(Z) < w(z_f)), and Cantelli's
// bound on a warped variable is a lower bound of G; EVSM4 takes the larger of its two, EVSM2 has
// the positive one alone. The positive warp sharpens the bound in front of z_f, the negative one
// behind.
class EvsmTechnique : public Technique {
 public:
  EvsmTechnique(std::string name, bool four, bool in_float, double c_positive, double c_negative)
      : Technique(std::move(name), evsm_basis(four, c_positive, c_negative),
                  in_float ? float32_storage() : double_storage()),
        four_(four),
        in_float_(in_float),
        c_positive_(c_positive),
        c_negative_(c_negative) {}
  double shadow(const FragmentInput& in) override {
    const double* m = in.moments.data();
    double g = vsm_bound(m, std::exp(c_positive_ * in.zf), 0);
    if (four_) g = std::max(g, vsm_bound(m + 2, -std::exp(-c_negative_ * in.zf), 0));
    return std::clamp(g, 0.0, 1.0);
  }
  // In double a lower bound (each warped Cantelli bound is one); in float32 the variance
  // E[w^2] - E[w]^2 of moments that reach exp(2 c z) loses its digits to rounding.
  double darkening_bound() const override {
    return in_float_ ? std::numeric_limits<double>::infinity() : 0;
  }
  std::string darkening_reason() const override {
    return in_float_ ? "float32 moments of exp(2 c z): the variance cancels in rounding" : "";
  }

 private:
  static Basis evsm_basis(bool four, double c_positive, double c_negative) {
    const std::string p = round_trip(c_positive), n = round_trip(c_negative);
    std::vector<std::string> functions{"exp(" + p + "*z)",
                                       "exp(" + round_trip(2 * c_positive) + "*z)"};
    if (four) {
      functions.push_back("-exp(-" + n + "*z)");
      functions.push_back("exp(-" + round_trip(2 * c_negative) + "*z)");
    }
    return Basis::parse(functions);
  }
  bool four_, in_float_;
  double c_positive_, c_negative_;
};

// Layered VSM (seed 001 "Layered VSM"): [0, 1] split into L even layers; layer l keeps the depth
// clamped to it, w_l(z) = clamp(L z - l, 0, 1), and a fragment is judged by Cantelli on the warped
// depths of its own layer. The warp does not decrease, so w_l(Z) < w_l(z_f) implies Z < z_f and
// the bound stays a lower bound; occluders in earlier layers warp to 0, and light leaking from
// depths beyond z_f's layer is gone (seed 000 §2: Problem 1 if the layers' overlap is ignored).
class LvsmTechnique : public Technique {
 public:
  LvsmTechnique(int layers, double min_variance)
      : Technique("lvsm", lvsm_basis(layers), double_storage()),
        layers_(layers),
        min_variance_(min_variance) {}
  double shadow(const FragmentInput& in) override {
    const int layer = std::clamp(int(std::floor(layers_ * in.zf)), 0, layers_ - 1);
    const double wf = std::clamp(layers_ * in.zf - layer, 0.0, 1.0);
    return std::clamp(vsm_bound(in.moments.data() + 2 * layer, wf, min_variance_), 0.0, 1.0);
  }

 private:
  static Basis lvsm_basis(int layers) {
    std::vector<std::string> functions;
    for (int l = 0; l < layers; ++l) {
      const std::string warp =
          "min(max(" + std::to_string(layers) + "*z-" + std::to_string(l) + ",0),1)";
      functions.push_back(warp);
      functions.push_back(warp + "^2");
    }
    return Basis::parse(functions);
  }
  int layers_;
  double min_variance_;
};

// Convolution shadow maps (seed 001 "Convolution Shadow Maps", "CSM Ringing"): the shadow test
// [z < z_f] as a Fourier series in t = z_f - z of period 2, 1/2 + 2 sum_k sin(c_k t) / c_k with
// c_k = (2k - 1) pi, whose terms split into E[cos(c_k z)] and E[sin(c_k z)] (the map's 2M
// channels); term k is damped by exp(-damping (k/M)^2) against ringing, and the slides' scaling
// by 2 (G = saturate(2 S - 1) for the series' shadow S) makes a receiver at its own depth lit.
// Not a lower bound: truncation rings (darkening_bound infinite; verify measures by how much).
class CsmTechnique : public Technique {
 public:
  CsmTechnique(int terms, double damping)
      : Technique("csm", csm_basis(terms), double_storage()), terms_(terms), damping_(damping) {}
  double shadow(const FragmentInput& in) override {
    double series = 0.5;
    for (int k = 1; k <= terms_; ++k) {
      const double c = (2 * k - 1) * std::numbers::pi;
      const double weight = 2 / c * std::exp(-damping_ * double(k * k) / double(terms_ * terms_));
      const double cos_term = in.moments[2 * (k - 1)], sin_term = in.moments[2 * (k - 1) + 1];
      series += weight * (std::sin(c * in.zf) * cos_term - std::cos(c * in.zf) * sin_term);
    }
    return std::clamp(2 * series - 1, 0.0, 1.0);
  }
  double darkening_bound() const override { return std::numeric_limits<double>::infinity(); }
  std::string darkening_reason() const override {
    return "a truncated Fourier series of the shadow test rings (Gibbs)";
  }

 private:
  static Basis csm_basis(int terms) { return Basis::parse(csm_channels(terms)); }
  int terms_;
  double damping_;
};

// The power-moment solvers share the bias towards b* = (1/2, .., 1/2) (REFERENCE.md §4: the
// moments of half the mass at 0 and half at 1) and the beta blend of seed 004.
// Closed forms share what happens to an answer: a NaN (a singular Hankel or Toeplitz matrix at
// alpha = 0 with a kernel of one or two depths) is counted, reported, and shown as fully lit so it
// cannot hide inside the mean; anything else is clamped to [0, 1].
class ClosedFormTechnique : public Technique {
 public:
  size_t failures() const override { return failures_; }

 protected:
  using Technique::Technique;
  // Moments biased by alpha towards those of a distribution on I are a mixture's; the sharp bound
  // of the mixture lies below (1 - alpha) F_Z + alpha, so G exceeds F_Z by at most alpha. Float and
  // 16-bit storage round the moments off the kernel's moment set, and beta > 0 blends towards the
  // upper bound: neither is a lower bound any more.
  double closed_form_bound(double alpha, double beta) const {
    const bool exact_storage = storage().kind == StorageKind::Double;
    return exact_storage && beta == 0 ? alpha : std::numeric_limits<double>::infinity();
  }
  std::string closed_form_reason(double beta) const {
    if (beta > 0) return "beta > 0 blends the lower bound towards the upper bound (seed 004)";
    return "moments stored in " + storage().name() +
           " are rounded off the kernel's moment set, and the bias alpha does not always pull them "
           "back";
  }
  double finish(double g) {
    if (std::isfinite(g)) return std::clamp(g, 0.0, 1.0);
    ++failures_;
    return 0;
  }

 private:
  size_t failures_ = 0;
};

enum class PowerSolver { Hamburger4, Hamburger4Float, Hausdorff4, Hamburger6 };

class PowerMomentTechnique : public ClosedFormTechnique {
 public:
  PowerMomentTechnique(std::string name, PowerSolver solver, MomentStorage storage, double alpha,
                       double beta)
      : ClosedFormTechnique(std::move(name),
                            Basis::parse({solver == PowerSolver::Hamburger6 ? "power6" : "power4"}),
                            std::move(storage)),
        solver_(solver),
        alpha_(alpha),
        beta_(beta) {}

  double shadow(const FragmentInput& in) override {
    const int m = int(in.moments.size());
    if (solver_ == PowerSolver::Hamburger4Float) {
      float b[4], star[4] = {0.5f, 0.5f, 0.5f, 0.5f};
      for (int j = 0; j < 4; ++j) b[j] = float(in.moments[j]);
      bias_moments(b, 4, float(alpha_), star);
      MsmBound<float> r = hamburger4(b, float(in.zf));
      return finish(r.lower + float(beta_) * r.at_zf);
    }
    double b[6], star[6] = {0.5, 0.5, 0.5, 0.5, 0.5, 0.5};
    std::copy(in.moments.begin(), in.moments.end(), b);
    bias_moments(b, m, alpha_, star);
    MsmBound<double> r = solver_ == PowerSolver::Hausdorff4   ? hausdorff4(b, in.zf)
                         : solver_ == PowerSolver::Hamburger6 ? hamburger6(b, in.zf)
                                                              : hamburger4(b, in.zf);
    return finish(r.lower + beta_ * r.at_zf);
  }
  double darkening_bound() const override { return closed_form_bound(alpha_, beta_); }
  std::string darkening_reason() const override { return closed_form_reason(beta_); }

 private:
  PowerSolver solver_;
  double alpha_, beta_;
};

// Trigonometric moment shadow mapping (moments/tmsm.md): bias towards the uniform distribution.
class TmsmTechnique : public ClosedFormTechnique {
 public:
  TmsmTechnique(std::string name, bool in_float, double alpha, double beta)
      : ClosedFormTechnique(std::move(name), Basis::parse({"trig4"}),
                            in_float ? float32_storage() : double_storage()),
        in_float_(in_float),
        alpha_(alpha),
        beta_(beta) {}
  double shadow(const FragmentInput& in) override {
    if (in_float_) return finish(solve<float>(in));
    return finish(solve<double>(in));
  }
  // The bias pulls towards the uniform distribution on [0, 1], whose mass below z_f is at most 1.
  double darkening_bound() const override { return closed_form_bound(alpha_, beta_); }
  std::string darkening_reason() const override { return closed_form_reason(beta_); }

 private:
  template <class Real>
  double solve(const FragmentInput& in) const {
    Real b[4];
    for (int j = 0; j < 4; ++j) b[j] = Real(in.moments[j]);
    bias_trigonometric_moments(b, Real(alpha_));
    MsmBound<Real> r = tmsm(b, Real(in.zf), false);
    return double(r.lower + Real(beta_) * r.at_zf);
  }
  bool in_float_;
  double alpha_, beta_;
};

void check_alpha(const char* key, double alpha) {
  if (!(alpha >= 0 && alpha < 1))
    throw InputError(std::string(key) + ": expected alpha in [0, 1), got " + round_trip(alpha));
}

}  // namespace

std::vector<std::string> closed_form_technique_names() {
  return {"pcf",
          "oracle",
          "vsm",
          "esm",
          "evsm2",
          "evsm4",
          "evsm2_float",
          "evsm4_float",
          "lvsm",
          "csm",
          "hamburger4",
          "hamburger4_float",
          "hamburger4_16bit",
          "hausdorff4",
          "hamburger6",
          "tmsm",
          "tmsm_float"};
}

std::unique_ptr<Technique> make_technique(const std::string& name, const TechniqueParams& p) {
  check_alpha("hamburger4.alpha", p.hamburger4_alpha);
  check_alpha("hamburger4_float.alpha", p.hamburger4_float_alpha);
  check_alpha("hamburger4_16bit.alpha", p.hamburger4_16bit_alpha);
  check_alpha("hausdorff4.alpha", p.hausdorff4_alpha);
  check_alpha("hamburger6.alpha", p.hamburger6_alpha);
  check_alpha("tmsm.alpha", p.tmsm_alpha);
  check_alpha("tmsm_float.alpha", p.tmsm_float_alpha);
  if (name == "pcf") return std::make_unique<PcfTechnique>();
  if (name == "oracle") return std::make_unique<OracleTechnique>();
  if (name == "vsm") return std::make_unique<VsmTechnique>(p.vsm_min_variance);
  if (name == "esm") return std::make_unique<EsmTechnique>(p.esm_c);
  if (name == "lvsm") return std::make_unique<LvsmTechnique>(p.lvsm_layers, p.vsm_min_variance);
  if (name == "csm") return std::make_unique<CsmTechnique>(p.csm_terms, p.csm_damping);
  if (name.rfind("evsm", 0) == 0 &&
      (name == "evsm2" || name == "evsm4" || name == "evsm2_float" || name == "evsm4_float"))
    return std::make_unique<EvsmTechnique>(name, name[4] == '4', name.size() > 5, p.evsm_c_positive,
                                           p.evsm_c_negative);
  if (name == "hamburger4")
    return std::make_unique<PowerMomentTechnique>(name, PowerSolver::Hamburger4, double_storage(),
                                                  p.hamburger4_alpha, p.beta);
  if (name == "hamburger4_float")
    return std::make_unique<PowerMomentTechnique>(
        name, PowerSolver::Hamburger4Float, float32_storage(), p.hamburger4_float_alpha, p.beta);
  if (name == "hamburger4_16bit")
    return std::make_unique<PowerMomentTechnique>(
        name, PowerSolver::Hamburger4, unorm16_power4_storage(), p.hamburger4_16bit_alpha, p.beta);
  if (name == "hausdorff4")
    return std::make_unique<PowerMomentTechnique>(name, PowerSolver::Hausdorff4, double_storage(),
                                                  p.hausdorff4_alpha, p.beta);
  if (name == "hamburger6")
    return std::make_unique<PowerMomentTechnique>(name, PowerSolver::Hamburger6, double_storage(),
                                                  p.hamburger6_alpha, p.beta);
  if (name == "tmsm") return std::make_unique<TmsmTechnique>(name, false, p.tmsm_alpha, p.beta);
  if (name == "tmsm_float")
    return std::make_unique<TmsmTechnique>(name, true, p.tmsm_float_alpha, p.beta);
  if (name.rfind("lp:", 0) == 0) return make_lp_technique(name, p);
  std::string valid;
  for (const auto& n : closed_form_technique_names()) valid += n + ", ";
  std::string guess = closest_match(name, closed_form_technique_names());
  throw InputError("unknown technique '" + name + "'" +
                   (guess.empty() ? "" : " (did you mean '" + guess + "'?)") + "; valid: " + valid +
                   "lp:<basis> (e.g. lp:power4, lp:trig4, lp:z;exp(-z);sin(pi z);z^3)");
}

}  // namespace mb
