#include "domain/neighbour_list.hpp"

#include <omp.h>

#include <algorithm>
#include <cstring>

namespace sphdem {

void NeighbourList::build(const CellList& cells, const double* x, const double* y, const double* z,
                          std::size_t n_query, double rc, bool exclude_self, bool half) {
  const double rc2 = rc * rc;
  offset.assign(n_query + 1, 0);
  const int nt = omp_get_max_threads();
  if (static_cast<int>(local_.size()) < nt) local_.resize(nt);
  auto& local = local_;
  std::vector<std::size_t> lo(nt + 1, 0);
  // One cell walk: each thread fills its own contiguous block of rows, then the
  // blocks are concatenated.
#pragma omp parallel num_threads(nt)
  {
    const int t = omp_get_thread_num(), T = omp_get_num_threads();
    const std::size_t b = n_query * t / T, e = n_query * (t + 1) / T;
    auto& buf = local[t];
    buf.clear();
    for (std::size_t i = b; i < e; ++i) {
      cells.for_each_neighbour(x[i], y[i], z[i], rc2, [&](std::uint32_t j, double, double, double, double) {
        if (half ? (j > i || j >= n_query) : !(exclude_self && j == i)) buf.push_back(j);
      });
      offset[i + 1] = static_cast<std::uint32_t>(buf.size());  // local for now
    }
    lo[t + 1] = buf.size();
#pragma omp barrier
#pragma omp single
    {
      for (int k = 0; k < T; ++k) lo[k + 1] += lo[k];
      neighbour.resize(lo[T]);
    }
    for (std::size_t i = b; i < e; ++i) offset[i + 1] += static_cast<std::uint32_t>(lo[t]);
    if (!buf.empty()) std::memcpy(neighbour.data() + lo[t], buf.data(), buf.size() * sizeof(std::uint32_t));
  }
}

}  // namespace sphdem
