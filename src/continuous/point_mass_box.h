#pragma once
// Raw power moments whose rounding box holds a point mass (docs/reference.md §2, "Moments with a
// tolerance"). An atom's moments (a, a^2, ..) rounded to double lie outside the moment cone as
// often as not, and the box of a few ulps around them is the degenerate case of the local box
// (continuous/local_box.h): its local frame is set by the tolerances alone, z_f lies 10^7
// deviations away, and GLPK's phase 1 finds no start. Such a box is answered in closed form: an
// atom in the box bounds the box's least G from above, and Cantelli's inequality on the first two
// moments (a relaxation of the box, so a bound for it) bounds it from below.
#include <optional>
#include <span>
#include <vector>

namespace mb::lp {

struct PointMassBox {
  double G = 0;                       // an atom in the box's G: an upper end of the box's least G
  double lower = 0;                   // a proven lower end of the box's least G (Cantelli)
  double atom = 0;                    // the atom attaining G
  double range_lo = 0, range_hi = 1;  // G over the whole box lies here (proven)
};

// The box |E[z^k] - moments_k| <= tolerance_k, k = 1..n, on [lo, hi], when its variance is at or
// below what the tolerances leave undetermined and an atom lies in it; otherwise nothing.
std::optional<PointMassBox> point_mass_box(double lo, double hi, std::span<const double> moments,
                                           std::span<const double> tolerance, double zf);

}  // namespace mb::lp
