#include "report/darkening.h"

#include <sstream>

#include "techniques/registry.h"
#include "util/number_text.h"

namespace mb {

bool can_over_darken(double bound) {
  return !(bound <= kDarkeningSlack);
}

bool darkening_violates(double max_dark, double bound) {
  return !can_over_darken(bound) && max_dark > bound + kDarkeningSlack;
}

std::string darkening_text(double mean_dark, double max_dark, double bound) {
  if (darkening_violates(max_dark, bound)) return percent_text(mean_dark) + " (!)";
  if (!can_over_darken(bound)) return "-";
  return percent_text(mean_dark);
}

std::string protocol_text(Reference reference, bool area_light) {
  // Under an area light the reference is the light's own shadow, which no technique bounds
  // (docs/soft-shadows.md §1): the hard-shadow protocol's G <= PCF does not hold against it.
  std::string text =
      area_light
          ? std::string(
                "Views lit by an area light are measured against that light's shadow S "
                "(docs/soft-shadows.md §1), not PCF: errors there are mean |S - G|, no technique "
                "proves a bound on S, and over-darkening (G above S) is a measurement, not a "
                "fault. The hard-shadow protocol below holds for the views of a hard light and "
                "for the '") +
                role_name(TechniqueFamily::HardShadow, RowRole::Reference) + "' row. "
          : std::string();
  text +=
      "Errors are mean |PCF - G| over receiver fragments in percent. Every technique and the "
      "reference see the same "
      "per-fragment depth bias delta_f (docs/reference.md §3), so a valid lower bound satisfies G "
      "<= "
      "F_Z(z_f - delta_f) "
      "<= PCF: its whole error is light leaking (leak = the PCF > G part). Over-darkening (the G > "
      "PCF part) is shown "
      "only for techniques that can produce it; '-' marks an exact technique (the LP, VSM, ESM, "
      "and closed forms in "
      "double with beta = 0, whose bias alpha bounds it by alpha), checked fragment by fragment. "
      "Failures: fragments a "
      "technique could not answer (shown lit).";
  if (reference == Reference::Biased)
    text +=
        " Reference: biased, PCF = F_Z(z_f - delta_f), the seed paper's protocol; the error of an "
        "exact technique "
        "is the information its moments lose.";
  else
    text +=
        " Reference: receiver_plane, each tap against the fragment's own plane (the ideal filtered "
        "hard shadow); "
        "the '" +
        role_name(TechniqueFamily::HardShadow, RowRole::BiasFloor) +
        "' row, F_Z(z_f - delta_f) itself, is the floor that the bias sets for every "
        "technique.";
  return text;
}

std::string darkening_notes(const std::vector<DarkeningRow>& rows) {
  std::ostringstream out;
  for (const auto& r : rows) {
    if (darkening_violates(r.max_dark, r.bound))
      out << "**" << r.technique << " over-darkens by up to " << round_trip(r.max_dark)
          << ", above its proven bound " << round_trip(r.bound)
          << ".** An exact technique cannot do this (docs/reference.md §3): this is a bug; please "
             "report it with this "
             "run's config.\n\n";
    else if (can_over_darken(r.bound) && r.mean_dark > 0)
      out << "**" << r.technique << "** over-darkens " << percent_text(r.mean_dark)
          << " % on average (up to " << round_trip(r.max_dark)
          << " at one fragment): " << (r.reason.empty() ? "it is not a lower bound" : r.reason)
          << ".\n\n";
  }
  return out.str();
}

}  // namespace mb
