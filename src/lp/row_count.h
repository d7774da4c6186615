#pragma once
// Compile-time row counts for the small dense loops of Problem 1 (m + 1 <= 8 rows in practice).
#include <type_traits>

namespace mb::lp {

// The most rows a problem of the dense simplex has (docs/reference.md §2): fixed-size arrays of
// the engine and of its lanes are sized by it.
constexpr int kMaxRows = 8;

// Calls f(std::integral_constant<int, K>) with K = k for k = 1..8, so that loops over the rows
// unroll and vectorise with the count known at compile time; any other k gets K = Otherwise
// (a caller that handles only k <= 8 passes 8, one with a run-time fallback passes 0).
template <int Otherwise, class F>
decltype(auto) with_row_count(int k, F&& f) {
  switch (k) {
    case 1:
      return f(std::integral_constant<int, 1>{});
    case 2:
      return f(std::integral_constant<int, 2>{});
    case 3:
      return f(std::integral_constant<int, 3>{});
    case 4:
      return f(std::integral_constant<int, 4>{});
    case 5:
      return f(std::integral_constant<int, 5>{});
    case 6:
      return f(std::integral_constant<int, 6>{});
    case 7:
      return f(std::integral_constant<int, 7>{});
    case 8:
      return f(std::integral_constant<int, 8>{});
    default:
      return f(std::integral_constant<int, Otherwise>{});
  }
}

}  // namespace mb::lp
