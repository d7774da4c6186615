#pragma once
// The warm bases a fragment's LP may start from, and the order they are tried in.
#include <cstdint>
#include <limits>

#include "lp/fast/lanes.h"
#include "lp/solution.h"

namespace mb::lp::fast {

// The previous fragment's optimal basis, in terms that carry over to a neighbouring fragment:
// grid columns by index, kernel columns by the tap they came from (texel_tap maps it to the tap of
// the next kernel that sees the same texel), z_f's column and the composite column by role.
enum class Role { Grid, Tap, Zf, Composite };
struct WarmBasis {
  double zf = 0;
  int rows = 0, grid = 0;
  int column = -1, row = -1;  // the texel it was solved at (WarmPosition), -1: unknown
  Role role[kMaxRows];
  int index[kMaxRows];
};

// The warm bases offered to one LP (the texel to the left by layer, the texels above and above to
// the right by layer) with the distance of their z_f to the LP's (NaN: no basis), taken closest
// first, ties in the order offered. Taken one at a time, since most LPs need only the first:
// ranking all of them up front was a 24 x 24 comparison. Offered a block of kWarmLanes at a time
// (the lanes of one texel lie side by side), so that with AVX-512 each block is one vector and a
// take three minimums and a compare (offered one by one and taken in a scalar loop, they were ~3 %
// of a warm LP).
struct WarmOffers {
  static constexpr int kBlocks = 3, kCount = kBlocks * kWarmLanes;
  static_assert(kWarmLanes == 8, "a block is one vector of eight doubles");
  double distance[kCount];
  const WarmBasis* first[kBlocks] = {};  // the block's bases, kWarmLanes in a row
  int usable = 0;                        // offers with a basis, not yet taken
  // Block b: bases[l] with z_f zf[l] (NaN: no basis), or none when bases is null.
  void offer(int b, const WarmBasis* bases, const double* zf, double to) {
    first[b] = bases;
    double* d = distance + b * kWarmLanes;
#ifdef __AVX512F__
    // (The masked forms with every lane set: GCC 12's unmasked ones warn of an uninitialised
    // variable, as in smallest_lane.)
    const __m512d none = _mm512_set1_pd(std::numeric_limits<double>::quiet_NaN());
    const __m512d gap =
        bases ? _mm512_mask_abs_pd(
                    none, 0xff,
                    _mm512_mask_sub_pd(none, 0xff, _mm512_loadu_pd(zf), _mm512_set1_pd(to)))
              : none;
    _mm512_storeu_pd(d, gap);
    usable += __builtin_popcount(_mm512_mask_cmp_pd_mask(0xff, gap, gap, _CMP_ORD_Q));
    return;
#endif
    for (int l = 0; l < kWarmLanes; ++l) {
      d[l] = bases ? std::abs(zf[l] - to) : std::numeric_limits<double>::quiet_NaN();
      usable += d[l] == d[l];
    }
  }
  // The closest not yet taken (the first offered on ties), or null when none is left.
  const WarmBasis* take() {
    if (usable == 0) return nullptr;
    int best = 0;
#ifdef __AVX512F__
    {
      constexpr double kNone = std::numeric_limits<double>::infinity();
      __m512d block[kBlocks];
      const __m512d none = _mm512_set1_pd(kNone);
      for (int b = 0; b < kBlocks; ++b) {  // NaN (none, or taken) reads as no distance at all
        const __m512d d = _mm512_loadu_pd(distance + b * kWarmLanes);
        block[b] = _mm512_mask_mov_pd(none, _mm512_mask_cmp_pd_mask(0xff, d, d, _CMP_ORD_Q), d);
      }
      // (Masked forms: see offer.)
      const __m512d least = _mm512_set1_pd(smallest_lane(
          _mm512_mask_min_pd(none, 0xff, _mm512_mask_min_pd(none, 0xff, block[0], block[1]),
                             block[2]),
          kNone));
      uint32_t holding = 0;
      for (int b = 0; b < kBlocks; ++b)
        holding |= uint32_t(_mm512_mask_cmp_pd_mask(0xff, block[b], least, _CMP_EQ_OQ))
                   << (b * kWarmLanes);
      best = __builtin_ctz(holding);  // usable > 0: some lane holds a finite least
    }
#else
    double least = distance[0];
    for (int i = 1; i < kCount; ++i) {  // NaN (none, or taken) never compares less
      const bool closer = distance[i] < least || least != least;
      least = closer ? distance[i] : least;
      best = closer ? i : best;
    }
#endif
    distance[best] = std::numeric_limits<double>::quiet_NaN();
    --usable;
    return first[best / kWarmLanes] + best % kWarmLanes;
  }
};
}  // namespace mb::lp::fast
