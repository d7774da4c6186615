#include "moments/hausdorff.h"

#include <algorithm>

#include "moments/canonical.h"

namespace mb {

MsmBound<double> hausdorff4(const double* b, double zf) {
  MsmBound<double> r = hamburger4(b, zf);
  // The Hamburger canonical distribution is admissible when its nodes lie in [0, 1].
  if (r.nodes[1] >= 0 && r.nodes[2] <= 1) return r;
  // Otherwise the extremal distribution lives on {0, z_f, z*, 1} with
  // E[z (z - z_f)(z - z*)(z - 1)] = 0 (docs/reference.md §4).
  const double b1 = b[0], b2 = b[1], b3 = b[2], b4 = b[3];
  const double z_star = ((b3 - b2) * zf + b3 - b4) / ((b2 - b1) * zf + b2 - b3);
  MsmBound<double> h;
  h.node_count = 4;
  h.nodes[0] = zf;
  h.nodes[1] = 0;
  h.nodes[2] = z_star;
  h.nodes[3] = 1;
  const double moments[4] = {1, b1, b2, b3};
  for (int i = 0; i < 4; ++i) h.weights[i] = node_weight(moments, h.nodes, 4, i);
  double lower = (zf > 0 ? h.weights[1] : 0.0) + (z_star < zf ? h.weights[2] : 0.0);
  h.lower = std::clamp(lower, 0.0, 1.0);
  h.at_zf = std::clamp(h.weights[0], 0.0, 1.0);
  return h;
}

}  // namespace mb
