#include "domain/neighbour_list.hpp"

namespace sphdem {

void NeighbourList::build(const CellList& cells, const double* x, const double* y, const double* z,
                          std::size_t n_query, double rc, bool exclude_self, bool half) {
  const double rc2 = rc * rc;
  rows_.build(n_query, offset, neighbour, [&](std::size_t i, std::vector<std::uint32_t>& out) {
    cells.for_each_neighbour(x[i], y[i], z[i], rc2,
                             [&](std::uint32_t j, double, double, double, double) {
                               if (half ? (j > i || j >= n_query) : !(exclude_self && j == i))
                                 out.push_back(j);
                             });
  });
}

}  // namespace sphdem
