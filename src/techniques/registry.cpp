#include "techniques/registry.h"

#include <algorithm>
#include <limits>

#include "basis/basis.h"
#include "techniques/lp_technique.h"
#include "util/error.h"
#include "util/number_text.h"
#include "util/option_record.h"

namespace mb {

// Factories, one per technique file.
std::unique_ptr<Technique> make_pcf(const TechniqueParams&);
std::unique_ptr<Technique> make_oracle(const TechniqueParams&);
std::unique_ptr<Technique> make_vsm(const TechniqueParams&);
std::unique_ptr<Technique> make_lvsm(const TechniqueParams&);
std::unique_ptr<Technique> make_esm(const TechniqueParams&);
std::unique_ptr<Technique> make_esm_zmax(const TechniqueParams&);
std::unique_ptr<Technique> make_esm_threshold(const TechniqueParams&);
std::unique_ptr<Technique> make_evsm(const std::string& name, const TechniqueParams&);
std::unique_ptr<Technique> make_csm(const TechniqueParams&);
std::unique_ptr<Technique> make_fom(const TechniqueParams&);
std::unique_ptr<Technique> make_hamburger4(const TechniqueParams&);
std::unique_ptr<Technique> make_hamburger4_float(const TechniqueParams&);
std::unique_ptr<Technique> make_hamburger4_16bit(const TechniqueParams&);
std::unique_ptr<Technique> make_hausdorff4(const TechniqueParams&);
std::unique_ptr<Technique> make_hamburger6(const TechniqueParams&);
std::unique_ptr<Technique> make_tmsm(const TechniqueParams&);
std::unique_ptr<Technique> make_tmsm_float(const TechniqueParams&);

namespace {

using P = TechniqueParams;
constexpr double kInf = std::numeric_limits<double>::infinity();

// Every technique option, in the order config files list them.
const TechniqueOption kHamburger4Alpha{
    {"hamburger4.alpha", OptionType::Number, "1e-10", "Moment bias of Hamburger 4MSM in double."},
    &P::hamburger4_alpha,
    true};
const TechniqueOption kHamburger4FloatAlpha{{"hamburger4_float.alpha", OptionType::Number, "5e-6",
                                             "Moment bias of Hamburger 4MSM in float32."},
                                            &P::hamburger4_float_alpha,
                                            true};
const TechniqueOption kHamburger416bitAlpha{{"hamburger4_16bit.alpha", OptionType::Number, "3e-5",
                                             "Moment bias of Hamburger 4MSM from 16-bit maps."},
                                            &P::hamburger4_16bit_alpha,
                                            true};
const TechniqueOption kHausdorff4Alpha{
    {"hausdorff4.alpha", OptionType::Number, "1e-10", "Moment bias of Hausdorff 4MSM."},
    &P::hausdorff4_alpha,
    true};
const TechniqueOption kHamburger6Alpha{
    {"hamburger6.alpha", OptionType::Number, "1e-10",
     "Moment bias of six-moment Hamburger MSM. Not a proven bound at any alpha (rounding of six "
     "moments); measured over-darkening: up to 0.23 at 1e-10, none beyond alpha at 1e-8, which "
     "costs 0.33 pp of mean error on the default dataset (FINDINGS §7d)."},
    &P::hamburger6_alpha,
    true};
const TechniqueOption kTmsmAlpha{{"tmsm.alpha", OptionType::Number, "1e-10",
                                  "Moment bias of trigonometric MSM in double (towards 0)."},
                                 &P::tmsm_alpha,
                                 true};
const TechniqueOption kTmsmFloatAlpha{
    {"tmsm_float.alpha", OptionType::Number, "5e-5",
     "Moment bias of trigonometric MSM in float32 (measured: tmsm.md §6)."},
    &P::tmsm_float_alpha,
    true};
const TechniqueOption kBeta{
    {"hamburger.beta", OptionType::Number, "0",
     "G + beta * (weight at z_f): 0 lower bound, 1 upper (seed 004).", 0, 1},
    &P::beta};
const TechniqueOption kEsmC{{"esm.c", OptionType::Number, "80", "ESM exponent c.", 1e-6, 700},
                            &P::esm_c};
const TechniqueOption kEsmZmaxOffset{
    {"esm.zmax_offset", OptionType::Number, "0.01",
     "esm_zmax: a fragment fails when the kernel's deepest texel lies beyond z_f plus this offset "
     "(seed 002 §3.3 gives no value; 0.01 of the depth range clears a receiver's own sloped "
     "plane).",
     0, 1},
    &P::esm_zmax_offset};
const TechniqueOption kEsmThreshold{
    {"esm.threshold", OptionType::Number, "0.01",
     "esm_threshold: a fragment fails when its filtered ESM value exceeds 1 + this epsilon (seed "
     "002 §3.3 gives no value).",
     0, 1e6},
    &P::esm_threshold};
const TechniqueOption kVsmMinVariance{
    {"vsm.min_variance", OptionType::Number, "0", "VSM variance clamp.", 0, 1},
    &P::vsm_min_variance};
const TechniqueOption kEvsmCPositive{
    {"evsm.c_positive", OptionType::Number, "40",
     "EVSM exponent of the positive warp exp(c z) (exp(2 c z) must fit float32 for "
     "evsm*_float: c <= 44).",
     1e-6, 300},
    &P::evsm_c_positive};
const TechniqueOption kEvsmCNegative{{"evsm.c_negative", OptionType::Number, "5",
                                      "EVSM4 exponent of the negative warp -exp(-c z).", 1e-6, 300},
                                     &P::evsm_c_negative};
const TechniqueOption kLvsmLayers{
    {"lvsm.layers", OptionType::Integer, "4",
     "LVSM depth layers: [0, 1] split evenly, a VSM per layer on the depth clamped to it.", 1, 8},
    &P::lvsm_layers};
const TechniqueOption kCsmTerms{
    {"csm.terms", OptionType::Integer, "8",
     "CSM Fourier terms M (2M channels: cos and sin of (2k - 1) pi z).", 1, 16},
    &P::csm_terms};
const TechniqueOption kCsmDamping{
    {"csm.damping", OptionType::Number, "2",
     "CSM ringing suppression: term k scaled by exp(-damping (k/M)^2).", 0, 100},
    &P::csm_damping};
const TechniqueOption kFomTerms{
    {"fom.terms", OptionType::Integer, "3",
     "Fourier opacity mapping: terms M of the absorbance's series (2M + 1 coefficients; 3 fills "
     "two "
     "RGBA targets less one channel, the storage of two 4MSM maps; Jansen & Bavoil 2010 vary it).",
     1, 16},
    &P::fom_terms};

const std::vector<const TechniqueOption*> kAllOptions{&kHamburger4Alpha,
                                                      &kHamburger4FloatAlpha,
                                                      &kHamburger416bitAlpha,
                                                      &kHausdorff4Alpha,
                                                      &kHamburger6Alpha,
                                                      &kTmsmAlpha,
                                                      &kTmsmFloatAlpha,
                                                      &kBeta,
                                                      &kEsmC,
                                                      &kEsmZmaxOffset,
                                                      &kEsmThreshold,
                                                      &kVsmMinVariance,
                                                      &kEvsmCPositive,
                                                      &kEvsmCNegative,
                                                      &kLvsmLayers,
                                                      &kCsmTerms,
                                                      &kCsmDamping,
                                                      &kFomTerms};

// A factory that ignores the row's name (every row but EVSM's and the LP's).
template <std::unique_ptr<Technique> (*make)(const TechniqueParams&)>
std::unique_ptr<Technique> by_params(const std::string&, const TechniqueParams& p) {
  return make(p);
}

const char* kProven = "0: a sharp or classic lower bound (Cantelli, Markov) in double";
const char* kAlphaBound = "alpha: the moment bias, at beta = 0 (docs/reference.md §4)";
const char* kNotProven = "not proven";

// How verify checks each technique (docs/reference.md §6). I = R is a wide interval holding the
// extremal nodes of nearly every instance; where it does not, the difference is "grid-limited" and
// shows in the worst cases (VSM: Cantelli's second point mu - sigma^2 / (z_f - mu) runs far out
// when z_f ~ mu, hence its wider interval). ESM's e^{cz} needs points far enough below 0 that
// e^{cz} ~ 0 (Markov's extremal mass sits at -infinity; at z = -4, e^{c (z - z_f)} <= e^{-40} for
// c = 10); the LP uses e^{c(z-1)}, the same span scaled by e^{-c}, whose values stay <= 1 (the LP
// recomputes the moments from the distribution, so the scale of the closed form's moment does not
// matter). EVSM's warps are scaled by their values at z = 1 likewise.
std::vector<std::string> power4(const P&) {
  return {"power4"};
}
std::vector<std::string> power6(const P&) {
  return {"power6"};
}
std::vector<std::string> trig4(const P&) {
  return {"trig4"};
}
std::vector<std::string> power2(const P&) {
  return {"power2"};
}
std::vector<std::string> esm_basis(const P& p) {
  return {"exp(" + round_trip(p.esm_c) + "*(z-1))"};
}
std::vector<std::string> evsm2_basis(const P& p) {
  return {"exp(" + round_trip(p.evsm_c_positive) + "*(z-1))",
          "exp(" + round_trip(2 * p.evsm_c_positive) + "*(z-1))"};
}
std::vector<std::string> evsm4_basis(const P& p) {
  std::vector<std::string> functions = evsm2_basis(p);
  functions.push_back("-exp(-" + round_trip(p.evsm_c_negative) + "*z)");
  functions.push_back("exp(-" + round_trip(2 * p.evsm_c_negative) + "*z)");
  return functions;
}
std::vector<std::string> csm_basis(const P& p) {
  return csm_channels(p.csm_terms);
}
const VerifyRecipe kVerifyHamburger4{.lp_basis = power4, .lo = -4, .hi = 5, .on_r = true};
const VerifyRecipe kVerifyVsm{
    .lp_basis = power2, .lo = -20, .hi = 21, .on_r = true, .cantelli_support = true};
VerifyRecipe storage_box(std::vector<std::string> (*basis)(const P&), double lo, double hi,
                         bool on_r, double P::*alpha) {
  return {.judge = VerifyRecipe::Judge::StorageBox,
          .lp_basis = basis,
          .lo = lo,
          .hi = hi,
          .on_r = on_r,
          .alpha = alpha};
}

std::vector<TechniqueEntry> make_table() {
  return {
      {"pcf",
       "the reference itself (a sanity row, error 0)",
       "depth",
       "0",
       "-",
       {},
       by_params<make_pcf>},
      {"oracle",
       "F_Z(z_f - delta_f): the floor the bias sets under receiver_plane",
       "depth",
       "0",
       "-",
       {},
       by_params<make_oracle>},
      {"vsm",
       "variance shadow maps: Cantelli",
       "double",
       kProven,
       {},
       {&kVsmMinVariance},
       by_params<make_vsm>,
       kVerifyVsm},
      {"esm",
       "exponential shadow maps: Markov on exp(c z)",
       "double",
       kProven,
       {},
       {&kEsmC},
       by_params<make_esm>,
       VerifyRecipe{.lp_basis = esm_basis, .lo = -4}},
      {"esm_zmax",
       "ESM, falling back to a 2x2 custom PCF where the kernel's z_max fails (seed 002)",
       "double + z_max",
       std::string(kNotProven) + ": the fall-back's 2x2 test",
       {},
       {&kEsmC, &kEsmZmaxOffset},
       by_params<make_esm_zmax>},
      {"esm_threshold",
       "ESM, falling back to a 2x2 custom PCF where its value exceeds 1 + eps",
       "double",
       std::string(kNotProven) + ": the fall-back's 2x2 test",
       {},
       {&kEsmC, &kEsmThreshold},
       by_params<make_esm_threshold>},
      {"evsm2",
       "exponential VSM, positive warp exp(c z)",
       "double",
       kProven,
       {},
       {&kEvsmCPositive},
       make_evsm,
       VerifyRecipe{.judge = VerifyRecipe::Judge::LowerBound, .lp_basis = evsm2_basis}},
      {"evsm4",
       "exponential VSM, both warps, the larger bound",
       "double",
       kProven,
       {},
       {&kEvsmCPositive, &kEvsmCNegative},
       make_evsm,
       VerifyRecipe{.judge = VerifyRecipe::Judge::LowerBound, .lp_basis = evsm4_basis}},
      {"evsm2_float",
       "evsm2 with float32 moments",
       "float32",
       std::string(kNotProven) + ": the variance of exp(2 c z) cancels in float32",
       {},
       {&kEvsmCPositive},
       make_evsm},
      {"evsm4_float",
       "evsm4 with float32 moments",
       "float32",
       std::string(kNotProven) + ": the variance of exp(2 c z) cancels in float32",
       {},
       {&kEvsmCPositive, &kEvsmCNegative},
       make_evsm},
      {"lvsm",
       "layered VSM: Cantelli on the depth clamped to z_f's layer",
       "double",
       kProven,
       {},
       {&kLvsmLayers, &kVsmMinVariance},
       by_params<make_lvsm>},
      {"csm",
       "convolution shadow maps: a damped Fourier series of the test",
       "double",
       std::string(kNotProven) + ": truncation rings (Gibbs)",
       {},
       {&kCsmTerms, &kCsmDamping},
       by_params<make_csm>,
       VerifyRecipe{.judge = VerifyRecipe::Judge::Exceedance, .lp_basis = csm_basis}},
      {"fom",
       "Fourier opacity mapping (Jansen & Bavoil 2010): a Fourier series of the absorbance, for "
       "translucent occluders (seed 004 §4.1)",
       "double",
       std::string(kNotProven) + ": truncation rings, and filtering averages absorbance",
       {},
       {&kFomTerms},
       by_params<make_fom>},
      {"hamburger4",
       "4MSM on R (Hamburger), double",
       "double",
       kAlphaBound,
       {},
       {&kHamburger4Alpha, &kBeta},
       by_params<make_hamburger4>,
       kVerifyHamburger4},
      {"hamburger4_float",
       "4MSM on R, float32 maps and arithmetic",
       "float32",
       std::string(kNotProven) + ": rounding of the moments",
       {},
       {&kHamburger4FloatAlpha, &kBeta},
       by_params<make_hamburger4_float>,
       storage_box(power4, -4, 5, true, &P::hamburger4_float_alpha)},
      {"hamburger4_16bit",
       "4MSM on R from 16-bit maps with the transform theta_4",
       "unorm16",
       std::string(kNotProven) + ": 16-bit rounding of the moments",
       {},
       {&kHamburger416bitAlpha, &kBeta},
       by_params<make_hamburger4_16bit>,
       storage_box(power4, -4, 5, true, &P::hamburger4_16bit_alpha)},
      {"hausdorff4",
       "4MSM on [0, 1] (Hausdorff), double",
       "double",
       kAlphaBound,
       {},
       {&kHausdorff4Alpha, &kBeta},
       by_params<make_hausdorff4>,
       VerifyRecipe{.lp_basis = power4}},
      {"hamburger6",
       "six power moments on R, double",
       "double",
       "not proven: rounding six moments to double (docs/reference.md §4; measured up to 0.23 at "
       "alpha 1e-10)",
       {},
       {&kHamburger6Alpha, &kBeta},
       by_params<make_hamburger6>,
       VerifyRecipe{.lp_basis = power6, .lo = -2, .hi = 3, .on_r = true}},
      {"tmsm",
       "trigonometric MSM (src/moments/tmsm.md), double",
       "double",
       kAlphaBound,
       {},
       {&kTmsmAlpha, &kBeta},
       by_params<make_tmsm>,
       VerifyRecipe{.lp_basis = trig4}},
      {"tmsm_float",
       "trigonometric MSM, float32",
       "float32",
       std::string(kNotProven) + ": rounding of the moments",
       {},
       {&kTmsmFloatAlpha, &kBeta},
       by_params<make_tmsm_float>,
       storage_box(trig4, 0, 1, false, &P::tmsm_float_alpha)},
      {"lp:",
       "Problem 1 as an LP for any basis, e.g. lp:power4, lp:trig4",
       "double",
       "the LP's certified tolerance (lp::kCertifiedError)",
       {},
       {},
       make_lp_technique},
  };
}

void check_moment_bias(const std::string& key, double alpha) {
  if (!(alpha >= 0 && alpha < 1))
    throw InputError(key + ": expected alpha in [0, 1), got " + round_trip(alpha));
}

}  // namespace

const std::vector<TechniqueEntry>& technique_registry() {
  static const std::vector<TechniqueEntry> table = [] {
    auto rows = make_table();
    for (auto& r : rows)
      if (r.reference.empty()) r.reference = "the view's reference (PCF)";
    return rows;
  }();
  return table;
}

const TechniqueEntry* find_technique(std::string_view name) {
  for (const auto& e : technique_registry())
    if (e.name == name || (e.name == "lp:" && name.rfind("lp:", 0) == 0)) return &e;
  return nullptr;
}

std::vector<OptionSpec> technique_option_specs() {
  std::vector<OptionSpec> specs;
  for (const TechniqueOption* o : kAllOptions) specs.push_back(o->spec);
  return specs;
}

void read_technique_options(const Config& config, TechniqueParams& params) {
  for (const TechniqueOption* o : kAllOptions) read_option(config, o->spec.name, o->field, params);
}

void set_moment_bias(TechniqueParams& params, double alpha) {
  for (const TechniqueOption* o : kAllOptions)
    if (o->moment_bias) params.*std::get<double TechniqueParams::*>(o->field) = alpha;
}

std::vector<std::string> closed_form_technique_names() {
  std::vector<std::string> names;
  for (const auto& e : technique_registry())
    if (e.name != "lp:") names.push_back(e.name);
  return names;
}

std::string technique_table_markdown() {
  std::string out =
      "| technique | what it is | storage | darkening bound | options |\n|---|---|---|---|---|\n";
  for (const auto& e : technique_registry()) {
    std::string options;
    for (const TechniqueOption* o : e.options)
      options += (options.empty() ? "`" : ", `") + o->spec.name + "`";
    out += "| `" + (e.name == "lp:" ? std::string("lp:<basis>") : e.name) + "` | " + e.summary +
           " | " + e.storage + " | " + e.bound + " | " + (options.empty() ? "-" : options) + " |\n";
  }
  return out;
}

std::unique_ptr<Technique> make_technique(const std::string& name, const TechniqueParams& p) {
  for (const TechniqueOption* o : kAllOptions)
    if (o->moment_bias)
      check_moment_bias(o->spec.name, p.*std::get<double TechniqueParams::*>(o->field));
  if (const TechniqueEntry* e = find_technique(name)) return e->make(name, p);
  std::string valid;
  for (const auto& n : closed_form_technique_names()) valid += n + ", ";
  std::string guess = closest_match(name, closed_form_technique_names());
  throw InputError("unknown technique '" + name + "'" +
                   (guess.empty() ? "" : " (did you mean '" + guess + "'?)") + "; valid: " + valid +
                   "lp:<basis> (e.g. lp:power4, lp:trig4, lp:z;exp(-z);sin(pi z);z^3)");
}

}  // namespace mb
