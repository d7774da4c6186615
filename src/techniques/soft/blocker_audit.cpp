// The blocker search audited against its sharp bounds (docs/soft-shadows.md §3): on a stride of
// the receivers, msm_soft's blocker depth beside the search region's own mean and the least and
// largest mean blocker depth any distribution with the region's moments allows (Dinkelbach's
// method on the LP, lp/blocker_bounds.h), and the penumbrae each gives.
#include <omp.h>

#include <algorithm>

#include "lp/blocker_bounds.h"
#include "techniques/soft/msm_blocker.h"
#include "util/parallel_errors.h"

namespace mb {

std::vector<BlockerAuditRow> blocker_audit(const ShadowMap& map, const Fragments& fragments,
                                           const SoftReceivers& soft, const GaussianKernel& kernel,
                                           const BiasParams& bias, const SoftParams& params,
                                           const TechniqueParams& technique, int threads) {
  std::vector<BlockerAuditRow> rows;
  if (params.audit == 0 || fragments.size() == 0) return rows;
  const MsmSoftConstants constants(technique);
  const SoftContext context = make_soft_context({map, soft, kernel, bias, params, technique});
  const auto sat = power4_table(map, params);
  lp::Discretization grid;
  grid.grid = 256;
  const lp::ProblemFactory factory(Basis::parse({"power4"}), grid);
  const size_t stride = std::max<size_t>(1, fragments.size() / size_t(params.audit));
  std::vector<size_t> picked;
  for (size_t k = stride / 2; k < fragments.size(); k += stride) picked.push_back(k);
  std::vector<BlockerAuditRow> found(picked.size());
  std::vector<char> kept(picked.size(), 0);
  ParallelErrors errors;
#pragma omp parallel num_threads(threads)
  {
    // One backend per thread, made and dropped in it (GLPK's memory is the thread's); every solve
    // starts cold, so the schedule changes no answer.
    std::unique_ptr<lp::Backend> backend;
    errors.capture([&] { backend = lp::make_backend("fast"); });
#pragma omp for schedule(dynamic, 1)
    for (size_t p = 0; p < picked.size(); ++p)
      errors.capture([&] {
        if (!backend) return;
        const Receiver r = receiver_of(fragments, soft, picked[p]);
        const MsmBlocker seed = msm_blocker(context, constants, *sat, r);
        // The search region as its texels: their depths join the grid, its moments are theirs.
        const int side = params.sat_search, x0 = r.x - side / 2, y0 = r.y - side / 2;
        std::vector<double> depths;
        double mass = 0, sum = 0;
        for (int y = y0; y < y0 + side; ++y)
          for (int x = x0; x < x0 + side; ++x) {
            const double z = map.at(x, y);
            depths.push_back(z);
            if (z < seed.zs) mass += 1, sum += z;
          }
        if (mass == 0) return;
        const std::vector<double> weights(depths.size(), 1.0 / double(depths.size()));
        const BlockerBounds bounds =
            blocker_bounds_dinkelbach(factory, depths, weights, seed.zs, *backend);
        if (!bounds.feasible) return;
        BlockerAuditRow& row = found[p];
        row.receiver = picked[p];
        row.zs = seed.zs;
        row.exact = sum / mass;
        row.seed = seed.depth;
        row.lo = bounds.lo, row.hi = bounds.hi;
        // Both sides start from the region's own mean, so lo <= exact <= hi.
        row.penumbra_lo = 2 * soft.rim_shear * std::max(r.zf - bounds.hi, 0.0);
        row.penumbra_hi = 2 * soft.rim_shear * std::max(r.zf - bounds.lo, 0.0);
        row.penumbra_exact = 2 * soft.rim_shear * std::max(r.zf - row.exact, 0.0);
        row.penumbra_seed = 2 * soft.rim_shear * std::max(r.zf - row.seed, 0.0);
        kept[p] = 1;
      });
  }
  errors.rethrow();
  for (size_t p = 0; p < picked.size(); ++p)
    if (kept[p]) rows.push_back(found[p]);
  return rows;
}

}  // namespace mb
