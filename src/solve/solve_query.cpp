#include "solve/solve_query.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>

#include "continuous/discretized.h"
#include "continuous/local_box.h"
#include "continuous/moment_box.h"
#include "continuous/moment_range.h"
#include "continuous/point_mass_box.h"
#include "lp/kkt_checker.h"
#include "lp/problem.h"
#include "lp/solution.h"
#include "techniques/registry.h"
#include "techniques/technique.h"
#include "util/error.h"
#include "util/number_text.h"
#include "util/option_record.h"

namespace mb {

namespace {

using nlohmann::json;

// The problem factory of the last LP line's basis and discretisation: a batch's lines mostly share
// them, and building one (the basis checked, the grid orthonormalised in long double: ~0.15 ms at
// 256 points, ~1.7 ms at 1024 with eight functions) costs more than solving the LP.
class FactoryCache {
 public:
  const lp::ProblemFactory& get(const std::vector<std::string>& basis_names,
                                const lp::Discretization& disc) {
    if (!factory_ || basis_names != names_ || disc != disc_) {
      factory_.reset();  // a line that fails here must not leave the previous one's factory behind
      Basis basis = Basis::parse(basis_names);
      basis.check_independent(disc.lo, disc.hi);
      factory_ = std::make_unique<lp::ProblemFactory>(basis, disc);
      names_ = basis_names;
      disc_ = disc;
    }
    return *factory_;
  }

 private:
  std::vector<std::string> names_;
  lp::Discretization disc_;
  std::unique_ptr<lp::ProblemFactory> factory_;
};

// What an instance gives of its distribution: moments, or depths with their weights.
struct Instance {
  std::vector<double> moments, depths, weights;
  bool from_distribution() const { return !depths.empty(); }
};

// A distribution must be one: as many weights as depths, each >= 0, summing to 1, depths finite
// (docs/reference.md §1), and never given beside moments.
Instance checked_instance(std::vector<double> moments, std::vector<double> depths,
                          std::vector<double> weights) {
  if (depths.empty() && weights.empty()) return {std::move(moments), {}, {}};
  if (!moments.empty())
    throw InputError("moments: given beside depths and weights; expected one or the other");
  if (depths.size() != weights.size())
    throw InputError("weights: expected one per depth (" + std::to_string(depths.size()) +
                     "), got " + std::to_string(weights.size()));
  long double total = 0;
  for (double w : weights) {
    if (!(w >= 0)) throw InputError("weights: expected numbers >= 0, got " + round_trip(w));
    total += w;
  }
  if (std::abs(double(total) - 1) > 1e-12)
    throw InputError("weights: expected to sum to 1 (a distribution), got " +
                     round_trip(double(total)));
  return {{}, std::move(depths), std::move(weights)};
}

// An interval is two numbers, lo and hi (their order is the factory's to check).
void check_interval(const std::vector<double>& interval, const std::string& key) {
  if (interval.size() != 2)
    throw InputError(key + ": expected [lo, hi], got " + std::to_string(interval.size()) +
                     (interval.size() == 1 ? " number" : " numbers"));
}

// A distribution's depths must be admissible (docs/reference.md §1), as eval refuses an LP interval
// that excludes a view's depths: an answer with support outside I is no answer to Problem 1 on I.
// Extra points do not make a depth admissible: they refine the LP's discretisation of I
// (docs/reference.md §2), while Problem 1's admissible set is the interval.
void check_depths_inside(const Instance& instance, const std::vector<double>& interval,
                         const std::string& depths_key, const std::string& interval_key,
                         bool has_points) {
  if (!instance.from_distribution()) return;
  const auto [min, max] = std::minmax_element(instance.depths.begin(), instance.depths.end());
  if (interval[0] <= *min && *max <= interval[1]) return;
  const double outside = *min < interval[0] ? *min : *max;
  throw InputError(depths_key + ": depth " + round_trip(outside) + " lies outside " + interval_key +
                   " [" + round_trip(interval[0]) + ", " + round_trip(interval[1]) +
                   "]; a distribution's depths must be admissible "
                   "(docs/reference.md §1): expected every depth in the interval, or an interval "
                   "that holds [" +
                   round_trip(*min) + ", " + round_trip(*max) + "]" +
                   (has_points ? " (points do not count: they refine the LP's discretisation of "
                                 "the interval, which is Problem 1's admissible set)"
                               : ""));
}

// Extra points join I's discretisation (docs/reference.md §2): one outside the interval would make
// Problem 1's admissible set larger than the interval, and the answer no answer on I.
void check_points_inside(const std::vector<double>& points, const std::vector<double>& interval,
                         const std::string& points_key, const std::string& interval_key) {
  for (double p : points)
    if (!(interval[0] <= p && p <= interval[1]))
      throw InputError(points_key + ": point " + round_trip(p) + " lies outside " + interval_key +
                       " [" + round_trip(interval[0]) + ", " + round_trip(interval[1]) +
                       "]; expected points of the interval (they refine its discretisation), "
                       "or an interval that holds them");
}

// Raw moments stand for every vector within their rounding (docs/reference.md §2): where G moves
// across that box by more than the answer's own uncertainty (the bracket, or the certificate on a
// grid), the range says how little the moments determine (continuous/moment_range.h).
void add_moment_range(json& out, const lp::ProblemFactory& factory,
                      const std::vector<double>& moments, double zf,
                      const std::vector<double>& points, const lp::ContinuousSolution& solved,
                      lp::Backend& backend, double ulps, double uncertainty) {
  // The problem as posed (solving may have added the exchange's points to solve_one's).
  const lp::Problem centre = factory.from_moments(moments, zf, points);
  const std::vector<double> tolerance = lp::ulp_box(factory, centre, ulps);
  const lp::MomentRange r =
      lp::moment_range(factory, moments, tolerance, zf, points, centre, solved, backend);
  if (!r.ok || r.hi - r.lo <= uncertainty) return;
  out["range"] = {r.lo, r.hi};
  out["range_vertices"] = std::to_string(r.feasible) + " of " + std::to_string(r.vertices) +
                          " in the moment cone" +
                          (r.complete() ? "" : ": the maximum is a lower estimate");
}

// G lies in [0, 1]: a certificate's lower end below 0 (or an upper end above 1) says nothing about
// G, and one far below 0 has lost its digits (docs/reference.md §2, "The bracket"). The bracket is
// reported within [0, 1]; `proven` holds only where the certificate is a proof and its lower end
// needed no clamping beyond the LP's certified error, so that the bracket rests on the proof and
// not on 0 <= G. A clamped lower end is kept as "certificate_lower".
void put_bracket(json& out, double G, double lower, bool proven) {
  const double g = std::clamp(G, 0.0, 1.0);
  const double lo = std::clamp(lower, 0.0, g);
  out["G"] = g;
  out["lower"] = lo;
  out["bracket"] = g - lo;
  const bool clamped = lower < -lp::kCertifiedError || lower > 1 + lp::kCertifiedError;
  out["proven"] = proven && !clamped;
  if (clamped) out["certificate_lower"] = lower;
}

// A distribution as the answer's "support": [point, weight] pairs.
json support_json(const std::vector<double>& points, const std::vector<double>& weights) {
  json support = json::array();
  for (size_t k = 0; k < points.size(); ++k) support.push_back({points[k], weights[k]});
  return support;
}

// What a box answer's G, lower, bracket and proven are (docs/reference.md §2).
constexpr const char* kBoxBracketOf =
    "G, lower, bracket and proven: the least G over the moments' rounding box, not the rounded "
    "kernel's G";

// Raw power moments whose rounding box holds a point mass (continuous/point_mass_box.h): the local
// box's frame degenerates there, and the closed form answers it. False when the box holds none.
bool answer_point_mass(json& out, const lp::Discretization& disc,
                       const std::vector<double>& moments, const std::vector<double>& tolerance,
                       double zf) {
  const std::optional<lp::PointMassBox> atom =
      lp::point_mass_box(disc.lo, disc.hi, moments, tolerance, zf);
  if (!atom) return false;
  out["status"] = "optimal";
  out["moments_from"] = "moments, their rounding box, which holds a point mass";
  put_bracket(out, atom->G, atom->lower, true);
  out["bracket_of"] = kBoxBracketOf;
  out["range"] = {atom->range_lo, atom->range_hi};
  out["range_of"] =
      "G over the rounding box: an atom in it and Cantelli's bound on its mean and variance";
  out["support"] = support_json({atom->atom}, {1.0});
  out["backend"] = "closed_form";
  return true;
}

// Raw power moments outside the cone on the continuous interval: the box problem in the moments'
// local coordinates (continuous/local_box.h), which an LP resolves where the box in z is a few ulps
// of the columns' leading digits. False when its phase 1 finds no distribution in the box (the
// caller then reports the distance from the cone).
bool answer_box_locally(json& out, const lp::Discretization& disc,
                        const std::vector<double>& moments, const std::vector<double>& tolerance,
                        double zf) {
  const lp::LocalBoxAnswer local =
      lp::solve_power_box_locally(disc.lo, disc.hi, moments, tolerance, zf);
  if (!local.ok()) return false;
  out["status"] = "optimal";
  out["moments_from"] = "moments, their rounding box in local coordinates";
  // G, lower, bracket and proven are the box's least G (docs/reference.md §2): the kernel that was
  // rounded may lie anywhere in the box, its G anywhere in `range`.
  put_bracket(out, local.box.upper, local.box.lower, local.box.proven);
  out["bracket_of"] = kBoxBracketOf;
  const lp::LocalBoxUpper upper = lp::local_box_upper(local);
  out["range"] = {std::clamp(local.box.lower, 0.0, 1.0),
                  std::clamp(std::max(upper.upper, local.box.upper), 0.0, 1.0)};
  out["range_of"] =
      std::string("G over the rounding box: from its least G to ") +
      (upper.behind.ok()
           ? std::string("the largest mass at or in front of zf of a distribution in it, an upper "
                         "bound of G there") +
                 (upper.proven ? "" : " (sampled, not proven)")
           : "1 (the box problem of its largest mass found no start)");
  out["exchange_rounds"] = local.phase1.rounds + local.box.rounds + upper.behind.rounds;
  out["support"] = support_json(local.support, local.weights);
  out["backend"] = "glpk";
  return true;
}

json solve_one(lp::Backend& backend, FactoryCache& factories,
               const std::vector<std::string>& basis_names, const lp::Discretization& disc,
               const Instance& instance, double zf, const std::vector<double>& points, bool check,
               double tolerance_ulps) {
  const lp::ProblemFactory& factory = factories.get(basis_names, disc);
  const std::vector<double>& moments = instance.moments;
  lp::Problem problem = instance.from_distribution()
                            ? factory.from_distribution(instance.depths, instance.weights, zf)
                            : factory.from_moments(moments, zf, points);
  if (instance.from_distribution()) factory.add_points(problem, points);
  // A distribution's own depths and weights let a power basis go to its local coordinates, where
  // a narrow kernel keeps its digits (docs/reference.md §2).
  const lp::ContinuousSolution answer =
      lp::solve_discretized(factory, problem, backend, instance.depths, instance.weights);
  const lp::Solution& s = answer.finite;
  json out;
  if (instance.from_distribution())
    out["moments_from"] = lp::power_basis_degree(factory.basis()) > 0 && disc.continuous
                              ? "distribution, local coordinates"
                              : "distribution";
  if (!instance.from_distribution() && tolerance_ulps > 0 && s.call == lp::CallStatus::Ok &&
      s.status != lp::ProblemStatus::Optimal) {
    // docs/reference.md §2, moments with a tolerance: a boundary vector rounded to double may lie
    // just outside the moment cone. Problem 1 over every distribution whose moments are within the
    // box of `tolerance_ulps` ulps answers it; a vector outside the box reports its distance.
    const lp::Problem exact = factory.from_moments(moments, zf, points);
    const std::vector<double> tolerance = lp::ulp_box(factory, exact, tolerance_ulps);
    out["exact_status"] = lp::to_string(s.status);
    out["moment_box_ulps"] = tolerance_ulps;
    if (disc.continuous && lp::power_basis_degree(factory.basis()) > 0 &&
        (answer_box_locally(out, disc, moments, tolerance, zf) ||
         answer_point_mass(out, disc, moments, tolerance, zf)))
      return out;
    const lp::MomentBoxAnswer box = lp::solve_moment_box(factory, exact, tolerance);
    out["status"] = lp::to_string(box.status);
    out["backend"] = "glpk";
    if (box.status == lp::ProblemStatus::Optimal) {
      out["G"] = box.G;
      out["support"] = support_json(box.support, box.weights);
    } else if (box.status == lp::ProblemStatus::Infeasible) {
      out["relative_distance"] = box.relative_distance;
    }
    return out;
  }
  if (s.call == lp::CallStatus::Failed) {
    out["status"] = "call_failed";
    out["message"] = s.call_message;
    return out;
  }
  out["status"] = lp::to_string(s.status);
  if (s.status == lp::ProblemStatus::Optimal) {
    out["G"] = s.G;
    if (disc.continuous) {
      // docs/reference.md §2: G of all of [lo, hi] lies in [lower, G]; proven: the certificate is a
      // proof (catalog functions), not a sampling (expressions).
      put_bracket(out, s.G, answer.lower, answer.proven);
      out["exchange_rounds"] = answer.rounds;
    }
    json support = json::array();
    for (size_t k = 0; k < s.support.size(); ++k)
      support.push_back({problem.point(s.support[k]), s.weights[k]});
    out["support"] = support;
    if (!instance.from_distribution() && tolerance_ulps > 0)
      add_moment_range(out, factory, moments, zf, points, answer, backend, tolerance_ulps,
                       disc.continuous ? answer.width() : lp::kCertifiedError);
  }
  // Defined answers outside I (docs/reference.md §1): every distribution on [lo, hi] lies below a
  // z_f above hi (G = 1) and none strictly below a z_f at or under lo (G = 0).
  if (zf > disc.hi)
    out["note"] = "zf lies above the interval: every distribution on it is below zf, so G = 1";
  if (zf <= disc.lo)
    out["note"] = "zf lies at or below the interval's start: no mass is below it, so G = 0";
  out["iterations"] = s.iterations;
  out["backend"] = backend.name();
  out["engine"] = lp::to_string(s.engine);  // "glpk" when the fast backend's fallback answered
  if (check && s.status == lp::ProblemStatus::Optimal)
    out["kkt"] = lp::check_kkt(problem, s).describe();
  return out;
}

// A closed-form technique (docs/reference.md §4) on the given moments, e.g. to re-run a worst case
// of `verify`; alpha >= 0 replaces every solver's default moment bias.
json solve_closed_form(const std::string& name, double alpha, const std::vector<double>& moments,
                       double zf) {
  if (const TechniqueRow* row = find_technique(name, TechniqueFamily::HardShadow);
      row && (row->role == RowRole::Reference || row->solves_lp))
    throw InputError("technique: '" + name +
                     "' is not a closed form of the moments (use basis for an LP)");
  TechniqueParams params;
  if (alpha >= 0) set_moment_bias(params, alpha);
  auto technique = make_technique(name, params);
  if (moments.size() != technique->basis().size())
    throw InputError("moments: technique '" + name + "' reads " +
                     std::to_string(technique->basis().size()) + " moments, got " +
                     std::to_string(moments.size()));
  FragmentInput in;
  in.moments = moments;
  in.zf = zf;
  const double g = technique->shadow(in);
  json out;
  out["status"] = technique->failures() ? "numerically_unstable" : "optimal";
  if (!technique->failures()) out["G"] = g;
  out["backend"] = "closed_form";
  out["technique"] = name;
  return out;
}

// A JSON Lines query, read strictly: every key known, every value of its type (docs/reference.md §2
// names; errors name the key and what was expected).
struct Query {
  const json& q;
  bool has(const char* key) const { return q.contains(key); }
  const json& at(const char* key) const {
    if (!q.contains(key)) throw InputError(std::string("key '") + key + "': missing");
    return q.at(key);
  }
  double number(const char* key) const {
    const json& v = at(key);
    if (!v.is_number() || !std::isfinite(v.get<double>()))
      throw InputError(std::string("key '") + key + "': expected a finite number, got " + v.dump());
    return v.get<double>();
  }
  int integer(const char* key, int lo, int hi) const {
    const json& v = at(key);
    if (!v.is_number_integer() || v.get<double>() < lo || v.get<double>() > hi)
      throw InputError(std::string("key '") + key + "': expected an integer in [" +
                       std::to_string(lo) + ", " + std::to_string(hi) + "], got " + v.dump());
    return v.get<int>();
  }
  std::vector<double> numbers(const char* key) const {
    const json& v = at(key);
    if (!v.is_array())
      throw InputError(std::string("key '") + key + "': expected a list of numbers, got " +
                       v.dump());
    std::vector<double> out;
    for (const auto& item : v) {
      if (!item.is_number() || !std::isfinite(item.get<double>()))
        throw InputError(std::string("key '") + key + "': expected finite numbers, got " +
                         item.dump());
      out.push_back(item.get<double>());
    }
    return out;
  }
  std::vector<std::string> strings(const char* key) const {
    const json& v = at(key);
    if (v.is_string()) return {v.get<std::string>()};
    if (!v.is_array())
      throw InputError(std::string("key '") + key + "': expected a list of strings, got " +
                       v.dump());
    std::vector<std::string> out;
    for (const auto& item : v) {
      if (!item.is_string())
        throw InputError(std::string("key '") + key + "': expected strings, got " + item.dump());
      out.push_back(item.get<std::string>());
    }
    return out;
  }
  std::string string(const char* key) const {
    const json& v = at(key);
    if (!v.is_string())
      throw InputError(std::string("key '") + key + "': expected a string, got " + v.dump());
    return v.get<std::string>();
  }
};

const std::vector<std::string> kQueryKeys = {
    "id",      "basis",  "interval", "grid",      "discretization", "moments",         "depths",
    "weights", "points", "zf",       "technique", "alpha",          "moment_tolerance"};

json solve_line(const std::string& line, int number, const SolveSettings& o, lp::Backend& backend,
                FactoryCache& factories) {
  json q;
  try {
    q = json::parse(line);
  } catch (const json::exception& e) {
    // nlohmann's "[json.exception.parse_error.101] parse error at line 1, column 5: ..." without
    // its internal tag: the batch line is named by the caller.
    std::string what = e.what();
    const size_t tag = what.find("] ");
    throw InputError("JSON syntax: " + (tag == std::string::npos ? what : what.substr(tag + 2)));
  }
  if (!q.is_object()) throw InputError("expected a JSON object per line");
  for (const auto& item : q.items())
    if (std::find(kQueryKeys.begin(), kQueryKeys.end(), item.key()) == kQueryKeys.end()) {
      const std::string guess = closest_match(item.key(), kQueryKeys);
      throw InputError("unknown key '" + item.key() + "'" +
                       (guess.empty() ? "" : " (did you mean '" + guess + "'?)"));
    }
  Query query{q};
  json out;
  out["id"] = q.value("id", json(number));
  if (query.has("technique")) {
    out.update(solve_closed_form(query.string("technique"),
                                 query.has("alpha") ? query.number("alpha") : -1.0,
                                 query.numbers("moments"), query.number("zf")));
    return out;
  }
  std::vector<double> interval =
      query.has("interval") ? query.numbers("interval") : std::vector<double>{0, 1};
  check_interval(interval, "key 'interval'");
  lp::Discretization d{interval[0], interval[1],
                       query.has("grid") ? query.integer("grid", 2, 1 << 24) : o.grid, o.quantize};
  const std::string discretization =
      query.has("discretization") ? query.string("discretization") : o.discretization;
  if (discretization != "grid" && discretization != "continuous")
    throw InputError("key 'discretization': expected grid or continuous, got '" + discretization +
                     "'");
  d.continuous = discretization == "continuous";
  const bool distribution = query.has("depths") || query.has("weights");
  const Instance instance =
      distribution ? checked_instance(
                         query.has("moments") ? query.numbers("moments") : std::vector<double>{},
                         query.numbers("depths"), query.numbers("weights"))
                   : checked_instance(query.numbers("moments"), {}, {});
  check_depths_inside(instance, interval, "key 'depths'",
                      query.has("interval") ? "key 'interval'" : "key 'interval' (default)",
                      query.has("points"));
  if (query.has("points"))
    check_points_inside(query.numbers("points"), interval, "key 'points'",
                        query.has("interval") ? "key 'interval'" : "key 'interval' (default)");
  out.update(solve_one(
      backend, factories, query.strings("basis"), d, instance, query.number("zf"),
      query.has("points") ? query.numbers("points") : std::vector<double>{}, o.check,
      query.has("moment_tolerance") ? query.number("moment_tolerance") : o.moment_tolerance));
  return out;
}

}  // namespace

const std::vector<OptionRecord<SolveSettings>>& solve_options() {
  static const std::vector<OptionRecord<SolveSettings>> records{
      {{"basis", OptionType::StringList, "[power4]",
        "Basis functions: catalog names, expressions in z, or a set (power4, trig4)."},
       &SolveSettings::basis},
      {{"interval", OptionType::NumberList, "[0, 1]", "Admissible interval [lo, hi]."},
       &SolveSettings::interval},
      {{"grid", OptionType::Integer, "1024", "Uniform grid points on the interval.", 2, 1 << 24},
       &SolveSettings::grid},
      {{"moments", OptionType::NumberList, "[]", "Moment vector b_1..b_m of the instance."},
       &SolveSettings::moments},
      {{"depths", OptionType::NumberList, "[]",
        "A distribution instead of moments: its depths (with weights). Its moments are computed "
        "from it, for a power basis with discretization continuous in its own local coordinates, "
        "where a narrow kernel keeps the digits that rounding raw moments loses."},
       &SolveSettings::depths},
      {{"weights", OptionType::NumberList, "[]",
        "The distribution's weights, one per depth, >= 0, summing to 1."},
       &SolveSettings::weights},
      {{"points", OptionType::NumberList, "[]", "Extra points of I (e.g. the kernel's depths)."},
       &SolveSettings::points},
      {{"zf", OptionType::Number, "0.5", "Fragment depth z_f."}, &SolveSettings::zf},
      {{"backend", OptionType::String, "fast", "LP backend.", 0, 0, lp::backend_names()},
       &SolveSettings::backend},
      {{"technique", OptionType::String, "''",
        "A closed form instead of the LP (hamburger4, hausdorff4, tmsm, vsm, esm, ...); basis is "
        "then ignored."},
       &SolveSettings::technique},
      {{"alpha", OptionType::Number, "-1",
        "Moment bias for technique; below 0: the technique's own.", -1, 0.999999},
       &SolveSettings::alpha},
      {{"input", OptionType::String, "''",
        "JSON Lines file of instances (the instance options above are then refused)."},
       &SolveSettings::input},
      {measures_nothing({"output", OptionType::String, "''",
                         "JSON Lines results (written atomically); stdout if ''."}),
       &SolveSettings::output},
      {measures_nothing({"check", OptionType::Boolean, "false",
                         "Run the independent KKT checker on every optimal answer."}),
       &SolveSettings::check},
      {{"discretization",
        OptionType::String,
        "grid",
        "grid: Problem 1 on the grid and points; continuous: on all of the interval (exchange "
        "method; G, its certified lower end and their bracket; docs/reference.md §2).",
        0,
        0,
        {"grid", "continuous"}},
       &SolveSettings::discretization},
      {{"moment_tolerance", OptionType::Number, "4",
        "When the moments admit no distribution on I: Problem 1 over the box of this many ulps "
        "of each moment instead (docs/reference.md §2; a boundary vector rounded to double), or "
        "the "
        "vector's relative distance from the cone. 0: exact only.",
        0, 1e15},
       &SolveSettings::moment_tolerance},
      {{"quantize", OptionType::Boolean, "false",
        "Round extra points to the grid (docs/reference.md §2)."},
       &SolveSettings::quantize},
  };
  return records;
}

SolveSettings::SolveSettings() {
  read_defaults(solve_options(), *this);
}

std::vector<OptionSpec> solve_option_specs() {
  return option_specs(solve_options());
}

SolveSettings solve_settings_from(const Config& config) {
  SolveSettings o;
  read_options(config, solve_options(), o);
  if (!o.input.empty())  // an instance comes from options or from input, never both
    for (const auto& changed : config.non_default())
      for (const char* key : {"basis", "interval", "moments", "depths", "weights", "points", "zf",
                              "technique", "alpha"})
        if (changed.rfind(std::string(key) + ":", 0) == 0)
          throw InputError("solve: key '" + std::string(key) +
                           "' beside 'input' (a batch's lines carry their own instances)");
  return o;
}

nlohmann::json solve_instance(const SolveSettings& o) {
  if (!o.technique.empty()) return solve_closed_form(o.technique, o.alpha, o.moments, o.zf);
  auto backend = lp::make_backend(o.backend);
  check_interval(o.interval, "interval");
  lp::Discretization disc{o.interval[0], o.interval[1], o.grid, o.quantize};
  disc.continuous = o.discretization == "continuous";
  const Instance instance = checked_instance(o.moments, o.depths, o.weights);
  check_depths_inside(instance, o.interval, "depths (--depths)", "interval (--interval)",
                      !o.points.empty());
  check_points_inside(o.points, o.interval, "points (--points)", "interval (--interval)");
  FactoryCache factories;
  return solve_one(*backend, factories, o.basis, disc, instance, o.zf, o.points, o.check,
                   o.moment_tolerance);
}

SolveBatch solve_batch(const SolveSettings& o, std::istream& in, const std::string& source,
                       bool report_errors) {
  auto backend = lp::make_backend(o.backend);
  SolveBatch batch;
  std::string line;
  int number = 0;
  FactoryCache factories;
  while (std::getline(in, line)) {
    ++number;
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    json out;
    try {
      out = solve_line(line, number, o, *backend, factories);
      // Every answer that is not a number (infeasible, unstable, a failed call) counts as a
      // failure, as for a single instance.
      if (out.value("status", "") != "optimal") ++batch.failures;
    } catch (const std::exception& e) {
      // A malformed line is reported with its number and does not stop the others.
      ++batch.failures;
      out["status"] = "error";
      out["message"] = source + ":" + std::to_string(number) + ": " + e.what();
      if (report_errors)
        std::fprintf(stderr, "momentbench: %s\n", out["message"].get<std::string>().c_str());
    }
    batch.lines += out.dump() + "\n";
  }
  return batch;
}

}  // namespace mb
