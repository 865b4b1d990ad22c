#pragma once
// Contiguous shares of n rows, one per thread of a parallel pass, that follow the threads'
// measured times. The first pass takes the list's estimate (row_partition.hpp); after each
// pass the boundaries move half way toward equal times, the rows of a share taken to cost
// what the pass measured for them, spread evenly. Entry counts do not tell a contact from
// a near miss, so in a bed under falling spheres the estimate leaves one thread waiting.
//
// Only for passes whose rows each thread computes to the same bits whatever its share
// (no sum across rows): where the boundaries fall then changes no result.
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "domain/row_partition.hpp"

namespace sphdem {

class MeasuredShares {
 public:
  // Before the region: the team it will run (1 below a parallel pass's size) over n rows;
  // a new n or team starts again from the estimate.
  void prepare(const std::vector<std::uint32_t>& offset, std::size_t n, double row_cost,
               int threads) {
    if (n == n_ && static_cast<int>(split_.size()) == threads + 1) return;
    n_ = n;
    split_.assign(threads + 1, 0);
    for (int t = 0; t < threads; ++t)
      split_[t + 1] = row_range(offset, n, row_cost, t, threads).second;
    seconds_.assign(threads, 0.0);
  }
  // Inside the region: the calling thread's rows (the estimate's if the team is not the
  // one prepared for).
  std::pair<std::size_t, std::size_t> rows(const std::vector<std::uint32_t>& offset,
                                           double row_cost) const {
    const int t = omp_get_thread_num(), threads = omp_get_num_threads();
    if (threads + 1 != static_cast<int>(split_.size()))
      return row_range(offset, n_, row_cost, t, threads);
    return {split_[t], split_[t + 1]};
  }
  // Inside the region, by each thread once its rows are done.
  void record(double seconds) {
    const int t = omp_get_thread_num();
    if (t < static_cast<int>(seconds_.size())) seconds_[t] = seconds;
  }
  // After the region.
  void rebalance() {
    const int threads = static_cast<int>(seconds_.size());
    double total = 0.0;
    for (const double s : seconds_) total += s;
    if (threads < 2 || !(total > 0.0)) return;
    const std::vector<std::size_t> old = split_;
    int s = 0;          // the share in which the k-th boundary's time falls
    double before = 0;  // the time of the shares before s
    for (int k = 1; k < threads; ++k) {
      const double target = total * k / threads;
      while (s < threads - 1 && before + seconds_[s] < target) before += seconds_[s++];
      const double length = static_cast<double>(old[s + 1] - old[s]);
      const double within = seconds_[s] > 0.0 ? (target - before) / seconds_[s] : 0.5;
      const double equal = static_cast<double>(old[s]) + std::clamp(within, 0.0, 1.0) * length;
      const double moved = std::round(0.5 * (static_cast<double>(old[k]) + equal));
      split_[k] = std::clamp(static_cast<std::size_t>(moved), split_[k - 1], n_);
    }
  }
  const std::vector<std::size_t>& split() const { return split_; }

 private:
  std::vector<std::size_t> split_;  // share t is [split_[t], split_[t + 1])
  std::vector<double> seconds_;     // each thread's time in the last pass
  std::size_t n_ = static_cast<std::size_t>(-1);
};

}  // namespace sphdem
