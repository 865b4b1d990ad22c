#include "domain/cell_list.hpp"

#include <limits>
#include <stdexcept>

namespace sphdem {

void CellList::build(const double* x, const double* y, const double* z, std::size_t n,
                     double max_cutoff, int reach) {
  if (!(max_cutoff > 0) || reach < 1 || reach > 3)
    throw std::invalid_argument("CellList: cut-off must be > 0, reach in [1, 3]");
  const double cell_size = max_cutoff / reach;
  reach_ = reach;
  n_ = n;
  cell_ = cell_size;
  inv_ = 1.0 / cell_size;
  double hi[3];
  for (int d = 0; d < 3; ++d) {
    lo_[d] = std::numeric_limits<double>::max();
    hi[d] = std::numeric_limits<double>::lowest();
  }
  const double* p[3] = {x, y, z};
  for (std::size_t i = 0; i < n; ++i)
    for (int d = 0; d < 3; ++d) {
      lo_[d] = std::min(lo_[d], p[d][i]);
      hi[d] = std::max(hi[d], p[d][i]);
    }
  if (n == 0)
    for (int d = 0; d < 3; ++d) lo_[d] = hi[d] = 0;
  std::size_t ncell = 1;
  for (int d = 0; d < 3; ++d) {
    // Cap the grid so a blown-up particle cannot allocate an absurd number of cells.
    const double span = (hi[d] - lo_[d]) * inv_;
    nc_[d] = static_cast<int>(std::min(span, 1.0e4)) + 1;
    ncell *= static_cast<std::size_t>(nc_[d]);
  }
  if (ncell > (std::size_t(1) << 28))
    throw std::runtime_error("CellList: particles spread over too many cells (blow-up?)");
  start_.assign(ncell + 1, 0);
  cell_of_.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const int cx = clampi(static_cast<int>((x[i] - lo_[0]) * inv_), nc_[0]);
    const int cy = clampi(static_cast<int>((y[i] - lo_[1]) * inv_), nc_[1]);
    const int cz = clampi(static_cast<int>((z[i] - lo_[2]) * inv_), nc_[2]);
    const std::uint32_t c =
        static_cast<std::uint32_t>((static_cast<std::size_t>(cz) * nc_[1] + cy) * nc_[0] + cx);
    cell_of_[i] = c;
    ++start_[c + 1];
  }
  for (std::size_t c = 0; c < ncell; ++c) start_[c + 1] += start_[c];
  index_.resize(n);
  xs_.resize(n);
  ys_.resize(n);
  zs_.resize(n);
  std::vector<std::uint32_t> fill(start_.begin(), start_.end() - 1);
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint32_t k = fill[cell_of_[i]]++;
    index_[k] = static_cast<std::uint32_t>(i);
    xs_[k] = x[i];
    ys_[k] = y[i];
    zs_[k] = z[i];
  }
}

}  // namespace sphdem
