#include "eval/error_stats.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace mb {

void ErrorStats::add(double pcf, double g) {
  const double e = std::abs(pcf - g);
  ++count;
  weight += 1;  // exact up to 2^53 fragments: the means equal sum / count bit for bit
  sum_abs += e;
  if (pcf > g)
    sum_leak += pcf - g;
  else {
    sum_dark += g - pcf;
    max_dark = std::max(max_dark, g - pcf);
  }
  max = std::max(max, e);
  if (e > 0.1) ++over_tenth;
  ++histogram[std::min(int(e * kHistogramBins), kHistogramBins - 1)];
}

void ErrorStats::add_weighted(double pcf, double g, double w) {
  const double e = std::abs(pcf - g);
  ++count;
  weight += w;
  sum_abs += w * e;
  if (pcf > g)
    sum_leak += w * (pcf - g);
  else {
    sum_dark += w * (g - pcf);
    max_dark = std::max(max_dark, g - pcf);
  }
  max = std::max(max, e);
  if (e > 0.1) ++over_tenth;
  ++histogram[std::min(int(e * kHistogramBins), kHistogramBins - 1)];
}

void ErrorStats::add_all(std::span<const double> pcf, std::span<const double> g) {
  for (size_t i = 0; i < pcf.size(); ++i) add(pcf[i], g[i]);
}

void ErrorStats::merge(const ErrorStats& o) {
  count += o.count;
  weight += o.weight;
  over_tenth += o.over_tenth;
  failures += o.failures;
  sum_abs += o.sum_abs;
  sum_leak += o.sum_leak;
  sum_dark += o.sum_dark;
  max = std::max(max, o.max);
  max_dark = std::max(max_dark, o.max_dark);
  for (int i = 0; i < kHistogramBins; ++i) histogram[i] += o.histogram[i];
}

std::string percent_text(double fraction) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.4f", 100 * fraction);
  return buffer;
}

}  // namespace mb
