// The exact in-scattering against a hard shadow map (docs/scattering.md §2): the light's projection
// is affine, so along the view ray the raster coordinates are linear in t; between two successive
// crossings of texel lines the ray stays in one texel, whose stored depth is one constant, and the
// ray's light depth, linear in t, crosses it at most once. V is therefore piecewise constant with
// breakpoints found in closed form, and ∫ exp(-sigma_t t) over each lit piece is closed form too:
// the answer is exact up to rounding.
#include <algorithm>
#include <cmath>

#include "techniques/registry.h"
#include "techniques/scatter/scatter_technique.h"

namespace mb {

namespace {

// The parameter interval where x0 + t dx lies in [0, n], intersected with [lo, hi] (empty: lo >
// hi on return).
void clip_axis(double x0, double dx, double n, double& lo, double& hi) {
  if (dx == 0) {
    if (!(x0 >= 0 && x0 <= n)) lo = hi + 1;
    return;
  }
  double a = (0 - x0) / dx, b = (n - x0) / dx;
  if (a > b) std::swap(a, b);
  lo = std::max(lo, a), hi = std::min(hi, b);
}

// The texel lines of one axis the ray crosses inside (t_lo, t_hi), in order of t.
struct LineCrossings {
  double x0 = 0, dx = 0;
  long next = 0, last = 0;  // integer lines still to cross, from `next` towards `last`
  int step = 0;             // +1, -1, or 0 (parallel to the lines)
  LineCrossings(double origin, double slope, double t_lo, double t_hi) : x0(origin), dx(slope) {
    if (dx == 0) return;
    const double a = x0 + t_lo * dx, b = x0 + t_hi * dx;
    step = dx > 0 ? 1 : -1;
    next = dx > 0 ? long(std::floor(a)) + 1 : long(std::ceil(a)) - 1;
    last = dx > 0 ? long(std::ceil(b)) - 1 : long(std::floor(b)) + 1;
  }
  bool done() const { return step == 0 || (step > 0 ? next > last : next < last); }
  double t() const { return (double(next) - x0) / dx; }
};

class ExactScatter : public ScatterTechnique {
 public:
  explicit ExactScatter(std::string name) : ScatterTechnique(std::move(name)) {}
  double lit_length(const ScatterRay& ray) const override {
    const LightDepthMap& map = *setup_.light;
    const double sigma = setup_.extinction, s = ray.length;
    const Eigen::Vector3d r0 = map.frame->to_raster(setup_.camera);
    const Eigen::Vector3d dr = map.frame->to_raster(setup_.camera + ray.direction) - r0;
    // Outside the map every point is lit; inside, walk the texels between t_in and t_out.
    double t_in = 0, t_out = s;
    clip_axis(r0.x(), dr.x(), map.resolution, t_in, t_out);
    clip_axis(r0.y(), dr.y(), map.resolution, t_in, t_out);
    if (!(t_in < t_out)) return transmittance_integral(0, s, sigma);
    double lit = transmittance_integral(0, t_in, sigma) + transmittance_integral(t_out, s, sigma);
    LineCrossings xs(r0.x(), dr.x(), t_in, t_out), ys(r0.y(), dr.y(), t_in, t_out);
    double ta = t_in;
    while (true) {
      double tb = t_out;
      LineCrossings* next = nullptr;
      if (!xs.done() && xs.t() < tb) tb = xs.t(), next = &xs;
      if (!ys.done() && ys.t() < tb) tb = ys.t(), next = &ys;
      tb = std::clamp(tb, ta, t_out);
      lit += lit_part(map, r0, dr, ta, tb, sigma);
      if (!next) break;
      next->next += next->step;
      ta = tb;
    }
    return lit;
  }

 private:
  // The lit part of [ta, tb], a piece inside one texel (found at its midpoint).
  static double lit_part(const LightDepthMap& map, const Eigen::Vector3d& r0,
                         const Eigen::Vector3d& dr, double ta, double tb, double sigma) {
    if (!(tb > ta)) return 0;
    const double mid = 0.5 * (ta + tb);
    const double stored = map.at(r0.x() + mid * dr.x(), r0.y() + mid * dr.y());
    if (std::isinf(stored)) return transmittance_integral(ta, tb, sigma);
    // Lit where z0 + t dz <= stored.
    if (dr.z() == 0) return r0.z() <= stored ? transmittance_integral(ta, tb, sigma) : 0;
    const double cross = (stored - r0.z()) / dr.z();
    const double a = dr.z() > 0 ? ta : std::max(ta, cross);
    const double b = dr.z() > 0 ? std::min(tb, cross) : tb;
    return b > a ? transmittance_integral(a, b, sigma) : 0;
  }
};

std::vector<TechniqueRow> rows() {
  return {{.name = "exact",
           .family = TechniqueFamily::Scattering,
           .rank = 0,
           .summary = "the exact in-scattering against the light's hard shadow map: a walk over "
                      "the texels the view ray crosses, closed-form integrals of the lit pieces "
                      "(docs/scattering.md §2)",
           .storage = "shadow map (layer 0)",
           .bound = "0 (the reference itself)",
           .role = RowRole::Reference,
           .default_run = true,
           .make_scatter = [](const std::string& name,
                              const ScatterParams&) -> std::unique_ptr<ScatterTechnique> {
             return std::make_unique<ExactScatter>(name);
           }}};
}

const TechniqueRegistration kRegistered(rows);

}  // namespace

}  // namespace mb
