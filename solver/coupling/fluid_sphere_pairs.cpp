#include "coupling/fluid_sphere_pairs.hpp"

#include <cmath>

#include "sph/kernel.hpp"

namespace sphdem {

void FluidSpherePairs::build(const FluidParticles& f, const DemParticles& s, const CellList& dem_cells,
                             double kernel_scale) {
  scale = kernel_scale;
  list.build(dem_cells, f.x.data(), f.y.data(), f.z.data(), f.n_owned, dem_cells.max_cutoff(), false);
  w.resize(list.neighbour.size());
  const long n = static_cast<long>(f.n_owned);
#pragma omp parallel for schedule(static)
  for (long a = 0; a < n; ++a) {
    const double inv_h = inv_kernel_h(f, a);
    for (std::uint32_t k = list.begin(a); k < list.end(a); ++k) {
      const std::uint32_t j = list.neighbour[k];
      const double dx = f.x[a] - s.x[j], dy = f.y[a] - s.y[j], dz = f.z[a] - s.z[j];
      w[k] = kernel::w_q(std::sqrt(dx * dx + dy * dy + dz * dz) * inv_h, inv_h);
    }
  }
}

}  // namespace sphdem
