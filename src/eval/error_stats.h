#pragma once
// The L1 error of a technique against PCF (docs/reference.md §3): mean |PCF - G| over receivers,
// split into light leaking (PCF > G) and over-darkening (G > PCF), with the maximum, the share of
// fragments off by more than 0.1, and a histogram of per-fragment errors. Transparency weighs each
// fragment's error by its opacity (docs/transparency.md §4): the means are then weighted means,
// while the maximum, the share over 0.1 and the histogram still count fragments.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace mb {

struct ErrorStats {
  static constexpr int kHistogramBins = 100;  // |PCF - G| in bins of 0.01 over [0, 1]
  uint64_t count = 0, over_tenth = 0, failures = 0;
  double sum_abs = 0, sum_leak = 0, sum_dark = 0, max = 0,
         max_dark = 0;  // max_dark: largest G - PCF
  double weight = 0;    // the means' denominator: count, or the sum of the weights
  std::vector<uint64_t> histogram = std::vector<uint64_t>(kHistogramBins, 0);

  void add(double pcf, double g);
  // A fragment whose error counts `w` times in the means (w = 1: add).
  void add_weighted(double pcf, double g, double w);
  // Adds every fragment in order (the sums are then independent of the thread count).
  void add_all(std::span<const double> pcf, std::span<const double> g);
  void merge(const ErrorStats& other);
  double mean() const { return weight > 0 ? sum_abs / weight : 0; }
  double leak() const { return weight > 0 ? sum_leak / weight : 0; }
  double dark() const { return weight > 0 ? sum_dark / weight : 0; }
  double share_over_tenth() const { return count ? double(over_tenth) / count : 0; }
};

// A fraction as a percentage with four decimals ("12.3456"), as every error table prints it.
std::string percent_text(double fraction);

}  // namespace mb
