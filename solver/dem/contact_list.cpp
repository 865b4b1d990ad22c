#include "dem/contact_list.hpp"

#include <algorithm>

namespace sphdem {

void ContactNeighbourList::build(const DemParticles& s, const CellList& cells, double skin_) {
  skin = skin_;
  const std::size_t n = s.n_owned;
  double rmax = 0.0;
  for (std::size_t i = 0; i < s.size(); ++i) rmax = std::max(rmax, s.radius[i]);
  const double rc_max = 2.0 * rmax + skin;
  rows_.build(n, offset, neighbour, [&](std::size_t i, std::vector<std::uint32_t>& out) {
    cells.for_each_neighbour(s.x[i], s.y[i], s.z[i], rc_max * rc_max,
                             [&](std::uint32_t j, double, double, double, double r2) {
                               if (j == i) return;
                               const double rc = s.radius[i] + s.radius[j] + skin;
                               if (r2 < rc * rc) out.push_back(j);
                             });
  });
}

}  // namespace sphdem
