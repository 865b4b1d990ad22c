#pragma once
// The rows of a compressed-row list split into one contiguous range per thread, of equal
// estimated cost: a row costs `row_cost` plus one per entry (offset[i] = the entries
// before row i). Called inside a parallel region, it gives the calling thread its range.
//
// Why not a dynamic schedule: its shared chunk counter moves between the cores at every
// chunk, which costs more than a sub-step's work in a dilute scene (bench/RESULTS.md).
// Why not equal counts: a packed bed under a dilute suspension has several times the
// entries per row. The split depends on the list alone, so every pass over the same list
// gives each thread the same spheres, which stay in its cache; one thread gets [0, n).
// Without a list of n rows, the rows split in equal counts.
#include <omp.h>

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace sphdem {

// The range of share t of `threads`.
inline std::pair<std::size_t, std::size_t> row_range(const std::vector<std::uint32_t>& offset,
                                                     std::size_t n, double row_cost, int t,
                                                     int threads) {
  if (threads == 1) return {0, n};
  const bool listed = offset.size() == n + 1;  // else equal counts
  const auto cost = [&](std::size_t i) {
    return row_cost * static_cast<double>(i) + (listed ? offset[i] - offset[0] : 0.0);
  };
  // the first row whose cumulative cost reaches a share k / threads of the total
  const auto boundary = [&](int k) -> std::size_t {
    if (k <= 0) return 0;
    if (k >= threads) return n;
    const double target = cost(n) * k / threads;
    std::size_t lo = 0, hi = n;
    while (lo < hi) {
      const std::size_t mid = lo + (hi - lo) / 2;
      if (cost(mid) < target)
        lo = mid + 1;
      else
        hi = mid;
    }
    return lo;
  };
  return {boundary(t), boundary(t + 1)};
}

inline std::pair<std::size_t, std::size_t> thread_rows(const std::vector<std::uint32_t>& offset,
                                                       std::size_t n, double row_cost) {
  return row_range(offset, n, row_cost, omp_get_thread_num(), omp_get_num_threads());
}

}  // namespace sphdem
