#include "report/series_identity.h"

#include <algorithm>
#include <limits>
#include <regex>
#include <set>

#include "sweep/run_identity.h"
#include "sweep/sweep_run.h"
#include "util/error.h"
#include "util/name_list.h"

namespace mb {

namespace {

std::vector<std::string> measurement_keys(const std::vector<OptionSpec>& specs) {
  std::vector<std::string> keys;
  for (const auto& s : specs)
    if (s.effect == OptionEffect::Measures) keys.push_back(s.name);
  return keys;
}

// The options two series are compared on: those their target reads (sweep_target_specs), or
// every one when their targets differ.
std::vector<OptionSpec> compared_specs(const Meta& a, const Meta& b,
                                       const std::vector<OptionSpec>& specs) {
  const std::string target = measurement_value(a, "target", specs);
  return target == measurement_value(b, "target", specs) ? sweep_target_specs(target) : specs;
}

}  // namespace

void check_series_identity(std::vector<SweepSeries>& series, const SeriesIdentity& identity) {
  const std::vector<OptionSpec>& specs = identity.specs;
  const std::vector<std::string> keys = measurement_keys(specs);
  std::set<std::string> allowed;
  std::vector<std::string> allow_different;  // each key once, in the order given
  for (const auto& key : identity.allow_different) {
    // A shadow and a transparency series measure different quantities: no report ranks them on one
    // scale (docs/sweeps.md "Identity").
    if (key == "target")
      throw InputError(
          "allow_different: 'target' cannot differ; a shadow sweep measures shadow error and a "
          "transparency sweep transmittance error, which share no scale: expected series of one "
          "target");
    if (std::find(keys.begin(), keys.end(), key) == keys.end()) {
      const std::string hint = closest_match(key, keys);
      throw InputError("allow_different: '" + key + "' is not a measurement option of sweep" +
                       (hint.empty() ? "" : " (did you mean '" + hint + "'?)") +
                       "; expected a key whose identity is 'measured' in `momentbench options "
                       "sweep`");
    }
    if (allowed.insert(key).second) allow_different.push_back(key);
  }
  std::string refused;
  std::set<std::string> refused_keys, differing;
  for (size_t i = 1; i < series.size(); ++i) {
    std::vector<OptionDifference> kept;
    for (auto& d : measurement_differences(series[i].meta, series[0].meta,
                                           compared_specs(series[i].meta, series[0].meta, specs)))
      if (allowed.count(d.key))
        differing.insert(d.key);
      else
        kept.push_back(d), refused_keys.insert(d.key);
    if (!kept.empty())
      refused += (refused.empty() ? "" : "; ") + series[i].database + " and " + series[0].database +
                 " measure errors differently: " +
                 differences_text(kept, series[i].database, series[0].database);
  }
  if (!refused.empty()) {
    refused_keys.erase("settings");  // an old database's sentence: no key to allow
    throw InputError("report: " + refused + ". Errors measured differently cannot share a report" +
                     (refused_keys.empty()
                          ? std::string()
                          : "; to combine them, each series stating its own values, give "
                            "--allow-different " +
                                joined({refused_keys.begin(), refused_keys.end()}, ",")));
  }
  for (auto& s : series) {
    std::vector<std::string> labelled;
    for (const auto& key : allow_different) {
      const std::string value = key + " " + measurement_value(s.meta, key, specs);
      s.own_values.push_back(value);
      if (differing.count(key)) labelled.push_back(value);
    }
    for (const auto& key : measurement_keys(compared_specs(s.meta, s.meta, specs)))
      if (key != "dataset" && !allowed.count(key) &&
          configured_value(s.meta, key, specs) != measurement_value({}, key, specs))
        s.off_default.push_back(key + " " + measurement_value(s.meta, key, specs));
    if (!labelled.empty()) s.label += " (" + joined(labelled, ", ") + ")";
  }
}

namespace {

// The area light of a series' views: light.angle, or (a dataset listing light_angles) the angle a
// view's name ends with, "scene/view_<angle>deg" (eval's naming, docs/user-guide.md); "" if none.
std::string area_light_angle(const SweepSeries& series, const std::vector<OptionSpec>& specs) {
  const std::string angle = measurement_value(series.meta, "light.angle", specs);
  if (!angle.empty() && std::stod(angle) > 0) return "light.angle " + angle;
  for (const auto* rows : {&series.ranked, &series.references})
    for (const auto& r : *rows) {
      static const std::regex kAngled("\"[^\"]*_([0-9.eE+-]+)deg\"\\s*:");
      std::smatch m;
      if (std::regex_search(r.view_errors, m, kAngled) && std::stod(m[1].str()) > 0)
        return "views lit by an area light of " + m[1].str() + " degrees";
      return "";  // every row of a series has the same views
    }
  return "";
}

}  // namespace

void drop_bounds_under_area_light(SweepSeries& series, const SeriesIdentity& identity) {
  if (series.target() != "shadows") return;
  const std::string light = area_light_angle(series, identity.specs);
  if (light.empty()) return;
  const std::string reason =
      light +
      ": the reference is an area light's shadow, no F_Z, which every technique may darken past "
      "(docs/soft-shadows.md §1)";
  for (auto* rows : {&series.ranked, &series.references})
    for (auto& r : *rows) {
      r.darkening_bound = std::numeric_limits<double>::infinity();
      r.darkening_reason = reason;
    }
}

}  // namespace mb
