#pragma once
// Moment soft shadow mapping's blocker search (seed 004 §3.3-3.4, docs/soft-shadows.md §2): the
// search region's four power moments, biased by alpha, give the canonical three-atom distribution
// through z_s; its atoms in front of z_s are the blockers, their mean depth softened towards z_s
// by eps_z1. Shared by msm_soft's rows and the blocker audit (docs/soft-shadows.md §3).
#include <memory>

#include "techniques/registry.h"
#include "techniques/soft/soft_technique.h"

namespace mb {

extern const TechniqueOption kMsmSoftBlockerEpsilon, kMsmSoftUmbraEpsilon, kMsmSoftAlpha;

// msm_soft's own constants (seed 004 §3.3-3.4), from its option records.
struct MsmSoftConstants {
  explicit MsmSoftConstants(const TechniqueParams& p)
      : alpha(p.number(kMsmSoftAlpha)),
        blocker_epsilon(p.number(kMsmSoftBlockerEpsilon)),
        umbra_epsilon(p.number(kMsmSoftUmbraEpsilon)) {}
  double alpha, blocker_epsilon, umbra_epsilon;
};

// The summed-area table of the four power moments z, z^2, z^3, z^4.
std::unique_ptr<SummedAreaTable> power4_table(const ShadowMap& map, const SoftParams& p);

struct MsmBlocker {
  double depth = 0;   // seed 004's estimate, eps_z1 included
  double weight = 0;  // the canonical distribution's mass in front of z_s
  double zs = 0;
};

MsmBlocker msm_blocker(const SoftContext& c, const MsmSoftConstants& k, const SummedAreaTable& sat,
                       const Receiver& r);

}  // namespace mb
