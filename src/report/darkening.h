#pragma once
// How reports speak of over-darkening (docs/reference.md §3): with one bias for the reference and
// every technique, a valid lower bound satisfies G <= F_Z(z_f - delta_f) <= PCF, so exact
// techniques can only leak light. Over-darkening is shown only for techniques that can produce it
// (float, 16-bit, beta > 0), with the reason; an exact technique above its proven bound is flagged
// as a bug.
#include <string>
#include <vector>

#include "eval/error_stats.h"
#include "shadow/fragments.h"

namespace mb {

// Rounding slack on top of a technique's proven bound before an exact technique is flagged.
constexpr double kDarkeningSlack = 1e-9;

struct DarkeningRow {
  std::string technique;
  double mean_dark = 0, max_dark = 0;  // ErrorStats::dark(), ErrorStats::max_dark
  double bound = 0;                    // Technique::darkening_bound
  std::string reason;                  // Technique::darkening_reason
};

bool can_over_darken(double bound);
// An exact technique (finite bound) whose largest over-darkening exceeds its bound: a bug.
bool darkening_violates(double max_dark, double bound);
// The table cell: "-" for an exact technique within its bound, the percentage otherwise ("(!)" if
// an exact technique exceeds its bound).
std::string darkening_text(double mean_dark, double max_dark, double bound);
// The paragraph that says what the error columns mean under this reference.
std::string protocol_text(Reference reference, bool area_light = false);
// One Markdown note per technique that over-darkens (why) or exceeds its bound (a bug); "" if none.
std::string darkening_notes(const std::vector<DarkeningRow>& rows);

}  // namespace mb
