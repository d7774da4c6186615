#include "screen/screening.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "eval/error_stats.h"

namespace mb {

namespace {

// splitmix64: a seeded order of units that does not depend on the standard library's shuffle.
uint64_t mix(uint64_t x) {
  x += 0x9e3779b97f4a7c15ull;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
  return x ^ (x >> 31);
}

// The variance of the estimated total sum_h (R_h / n_h) sum_i r_hi from the sampled residuals r
// (unit errors minus the pilot's, or one candidate's minus another's), over the strata not sampled
// whole (those are exact). Each of the d sampled units there stands for z_i = d (R_h / n_h) r_i,
// whose mean is the total, and the variance is that of a mean of d independent draws, s_z^2 / d
// (the Hansen-Hurwitz with-replacement estimator), times the finite population correction
// 1 - d / (their units). This ignores the strata, which can only overstate the variance, and it is
// what keeps the standard error honest here: a view has few sampled units, too few for its own
// variance, and the unit errors are heavy tailed.
template <class Residual>
double sample_variance(const ScreenSample& sample, Residual residual) {
  size_t draws = 0, units = 0;
  for (const auto& s : sample.strata)
    if (s.sampled() < s.runs) draws += s.sampled(), units += s.runs;
  if (draws < 2) return 0;
  std::vector<double> z;
  z.reserve(draws);
  size_t at = 0;
  for (const auto& s : sample.strata) {
    const size_t m = s.sampled();
    if (m < s.runs)
      for (size_t i = 0; i < m; ++i)
        z.push_back(double(draws) * double(s.runs) / double(m) * residual(at + i));
    at += m;
  }
  double mean = 0;
  for (double v : z) mean += v;
  mean /= double(draws);
  double squares = 0;
  for (double v : z) squares += (v - mean) * (v - mean);
  const double d = double(draws);
  return (1 - d / double(units)) * squares / (d * (d - 1));
}

}  // namespace

size_t ScreenSample::sampled_runs() const {
  size_t n = 0;
  for (const auto& s : strata) n += s.sampled();
  return n;
}

uint64_t ScreenSample::sampled_lps() const {
  uint64_t n = 0;
  for (const auto& s : strata) n += s.list.size();
  return n;
}

size_t ScreenSample::runs() const {
  size_t n = 0;
  for (const auto& s : strata) n += s.runs;
  return n;
}

ScreenStratum draw_screen_stratum(const ScreenUnits& units, size_t index, double fraction,
                                  uint64_t seed) {
  ScreenStratum s;
  s.runs = units.units();
  s.lps = units.lps;
  for (double p : units.pilot) s.pilot_total += p;
  const size_t want =
      fraction >= 1 ? s.runs
                    : std::min(s.runs, std::max<size_t>(std::min<size_t>(2, s.runs),
                                                        size_t(std::ceil(fraction * s.runs))));
  std::vector<std::pair<uint64_t, size_t>> keyed;
  for (size_t r = 0; r < s.runs; ++r)
    keyed.push_back({mix(mix(seed ^ (uint64_t(index) << 40)) ^ units.key[r]), r});
  std::partial_sort(keyed.begin(), keyed.begin() + long(want), keyed.end());
  std::vector<size_t> chosen;
  for (size_t i = 0; i < want; ++i) chosen.push_back(keyed[i].second);
  std::sort(chosen.begin(), chosen.end());
  for (size_t r : chosen) {
    s.pilot.push_back(units.pilot[r]);
    s.run_begin.push_back(s.list.size());
    s.list.insert(s.list.end(), units.items.begin() + long(units.begin[r]),
                  units.items.begin() + long(units.begin[r + 1]));
  }
  s.run_begin.push_back(s.list.size());
  return s;
}

ScreenSample make_screen_sample(const std::vector<ViewData>& views,
                                const std::vector<std::vector<uint32_t>>& needs_lp,
                                const std::vector<std::vector<double>>& pilot_shadow,
                                double fraction, uint64_t seed) {
  ScreenSample sample;
  sample.fraction = fraction;
  for (size_t v = 0; v < views.size(); ++v) {
    const Fragments& fragments = views[v].fragments;
    const std::vector<uint32_t>& list = needs_lp[v];
    sample.weight += double(fragments.size());
    // G = 0 for every candidate where no LP is needed: |PCF - 0| once, in fragment order.
    std::vector<bool> lp(fragments.size(), false);
    for (uint32_t f : list) lp[f] = true;
    for (size_t f = 0; f < fragments.size(); ++f)
      if (!lp[f]) sample.fixed_error += std::abs(fragments.pcf[f]);
    // The units: each texel row cut into segments of kScreenUnitColumns columns, its fragments in
    // texel order (a unit is a run of its own when screened).
    const size_t width = size_t(views[v].map.width);
    const uint64_t blocks = uint64_t(width + kScreenUnitColumns - 1) / kScreenUnitColumns;
    auto unit_of = [&](uint32_t f) {
      const size_t t = fragments.texel[f];
      return uint64_t(t / width) * blocks + (t % width) / kScreenUnitColumns;
    };
    ScreenUnits units;
    units.items = list;  // stable: texel order within a unit
    std::stable_sort(units.items.begin(), units.items.end(),
                     [&](uint32_t a, uint32_t b) { return unit_of(a) < unit_of(b); });
    const std::vector<uint32_t>& by_unit = units.items;
    for (size_t i = 0; i < by_unit.size(); ++i)
      if (i == 0 || unit_of(by_unit[i]) != unit_of(by_unit[i - 1])) {
        units.begin.push_back(i);
        units.key.push_back(unit_of(by_unit[i]));
      }
    units.begin.push_back(by_unit.size());
    units.lps = list.size();
    for (size_t r = 0; r < units.units(); ++r)
      units.pilot.push_back(unit_error(
          std::span(by_unit).subspan(units.begin[r], units.begin[r + 1] - units.begin[r]),
          fragments.pcf, &pilot_shadow[v]));
    sample.strata.push_back(draw_screen_stratum(units, v, fraction, seed));
  }
  return sample;
}

double unit_error(std::span<const uint32_t> fragments, const std::vector<double>& pcf,
                  const std::vector<double>* shadow) {
  ErrorStats unit;  // the per-fragment error of every table, summed in fragment-list order
  for (uint32_t f : fragments) unit.add(pcf[f], shadow ? (*shadow)[f] : 0.0);
  return unit.sum_abs;
}

std::vector<double> sampled_unit_errors(const ScreenSample& sample,
                                        const std::vector<ViewData>& views,
                                        const std::vector<std::vector<double>>& shadow) {
  std::vector<double> errors;
  for (size_t v = 0; v < sample.strata.size(); ++v) {
    const ScreenStratum& s = sample.strata[v];
    for (size_t r = 0; r < s.sampled(); ++r)
      errors.push_back(
          unit_error(std::span(s.list).subspan(s.run_begin[r], s.run_begin[r + 1] - s.run_begin[r]),
                     views[v].fragments.pcf, shadow.empty() ? nullptr : &shadow[v]));
  }
  return errors;
}

ScreenEstimate estimate_mean_error(const ScreenSample& sample,
                                   const std::vector<double>& run_errors) {
  double total = sample.fixed_error;
  const double* y = run_errors.data();
  std::vector<double> residual;  // run error minus the pilot's, strata in order
  for (const auto& s : sample.strata) {
    const size_t n = s.sampled();
    if (n == s.runs) {  // every run: the exact sum
      for (size_t i = 0; i < n; ++i) total += y[i];
    } else if (n > 0) {
      // The pilot's exact total plus the runs' mean difference from the pilot, scaled up.
      double difference = 0;
      for (size_t i = 0; i < n; ++i) difference += y[i] - s.pilot[i];
      total += s.pilot_total + double(s.runs) * difference / double(n);
    }
    for (size_t i = 0; i < n; ++i) residual.push_back(y[i] - (n == s.runs ? 0.0 : s.pilot[i]));
    y += n;
  }
  const double n = sample.weight > 0 ? sample.weight : 1;
  const double variance = sample_variance(sample, [&](size_t i) { return residual[i]; });
  return {total / n, std::sqrt(variance) / n};
}

double paired_standard_error(const ScreenSample& sample, const std::vector<double>& a,
                             const std::vector<double>& b) {
  const double variance = sample_variance(sample, [&](size_t i) { return a[i] - b[i]; });
  return std::sqrt(variance) / (sample.weight > 0 ? sample.weight : 1);
}

std::vector<size_t> candidates_to_confirm(const ScreenSample& sample,
                                          const std::vector<std::vector<double>>& run_errors,
                                          const ScreenRule& rule) {
  const size_t count = run_errors.size();
  std::vector<size_t> all(count);
  std::iota(all.begin(), all.end(), size_t(0));
  if (rule.top <= 0 || count <= size_t(rule.top)) return all;
  std::vector<double> mean(count);
  for (size_t c = 0; c < count; ++c) mean[c] = estimate_mean_error(sample, run_errors[c]).mean;
  std::vector<size_t> order = all;
  std::stable_sort(order.begin(), order.end(),
                   [&](size_t a, size_t b) { return mean[a] < mean[b]; });
  const size_t r = order[size_t(rule.top) - 1];
  std::vector<bool> best(count, false);
  for (int k = 0; k < rule.top; ++k) best[order[size_t(k)]] = true;
  std::vector<size_t> confirm;
  for (size_t c = 0; c < count; ++c) {
    const double se = paired_standard_error(sample, run_errors[c], run_errors[r]);
    if (best[c] || mean[c] - mean[r] - rule.sigmas * se <= rule.margin) confirm.push_back(c);
  }
  return confirm;
}

bool keeps_unit_errors(const ScreenSample& sample, const std::vector<double>& c, double mean_c,
                       const std::vector<double>& r, double mean_r, bool best,
                       const ScreenRule& rule, double keep_sigmas) {
  return best || mean_c - mean_r - keep_sigmas * paired_standard_error(sample, c, r) <= rule.margin;
}

double reach_lower_bound(const ScreenSample& sample, const std::vector<double>& c, double mean_c,
                         const std::vector<double>& r, const ScreenRule& rule) {
  return mean_c - rule.sigmas * paired_standard_error(sample, c, r);
}

bool proven_out_of_reach(const ScreenSample& sample, double reach_lower,
                         const std::vector<double>& r, const std::vector<double>& rp,
                         double mean_rp, const ScreenRule& rule) {
  // The standard errors are sums of a few thousand terms: their rounding is far below 1e-12 of
  // a mean error (a fraction of at most 1), so a proof closer than that is not taken.
  constexpr double kRounding = 1e-12;
  return reach_lower - mean_rp - rule.sigmas * paired_standard_error(sample, r, rp) >
         rule.margin + kRounding;
}

}  // namespace mb
