#pragma once
// The warm bases a fragment's LP may start from, and the order they are tried in.
#include <cstdint>
#include <limits>

#include "lp/lanes/lanes.h"
#include "lp/solution.h"

namespace mb::lp::fast {

// A previous problem's optimal basis, in terms that carry over to the next: grid columns by
// index, atom columns by the atom they came from (an AtomMap maps it to the atom of the next
// problem that stands for the same depth), z_f's column and the composite column by role.
enum class Role { Grid, Atom, Zf, Composite };
struct WarmBasis {
  double zf = 0;
  int rows = 0, grid = 0;
  Place place;  // where it was solved (WarmStart::place)
  Role role[kMaxRows];
  int index[kMaxRows];
};

// The warm bases offered to one LP (every lane's last basis, then every lane of up to two
// memories: WarmStart) with the distance of their z_f to the LP's (NaN: no basis), taken closest
// first, ties in the order offered. Taken one at a time, since most LPs need only the first:
// ranking all of them up front was a 24 x 24 comparison. Offered a block of kWarmLanes at a time
// (the lanes of one memory lie side by side), so that with AVX-512 each block is one vector and a
// take three minimums and a compare (lanes::offer_distances, lanes::closest).
struct WarmOffers {
  static constexpr int kBlocks = 3, kCount = kBlocks * kWarmLanes;
  static_assert(kWarmLanes == 8, "a block is one vector of eight doubles");
  double distance[kCount];
  const WarmBasis* first[kBlocks] = {};  // the block's bases, kWarmLanes in a row
  int usable = 0;                        // offers with a basis, not yet taken
  // Block b: bases[l] with z_f zf[l] (NaN: no basis), or none when bases is null.
  void offer(int b, const WarmBasis* bases, const double* zf, double to) {
    first[b] = bases;
    usable += lanes::offer_distances(bases ? zf : nullptr, to, distance + b * kWarmLanes);
  }
  // The closest not yet taken (the first offered on ties), or null when none is left.
  const WarmBasis* take() {
    if (usable == 0) return nullptr;
    const int best = lanes::closest(distance, kCount);
    distance[best] = std::numeric_limits<double>::quiet_NaN();
    --usable;
    return first[best / kWarmLanes] + best % kWarmLanes;
  }
};
}  // namespace mb::lp::fast
