#include "coupling/fluid_sphere_pairs.hpp"

#include <cmath>

#include "domain/row_partition.hpp"
#include "sph/kernel.hpp"

namespace sphdem {

void FluidSpherePairs::build_list(const FluidParticles& f, const CellList& dem_cells,
                                  double kernel_scale, double rc) {
  scale = kernel_scale;
  list.build(dem_cells, f.x.data(), f.y.data(), f.z.data(), f.n_owned, rc, false);
  sphere.resize(list.neighbour.size());
  w.resize(list.neighbour.size());
  grad.resize(list.neighbour.size());
  count.assign(f.n_owned, 0);
}

void FluidSpherePairs::evaluate(const FluidParticles& f, const DemParticles& s,
                                bool with_gradient) {
  const long n = static_cast<long>(f.n_owned);
  // rows differ (a bed, clear fluid): contiguous shares of equal entries
#pragma omp parallel
  for (auto [a, end] = thread_rows(list.offset, n, kFluidRowCost); a < end; ++a) {
    const double inv_h = inv_kernel_h(f, a), reach = kernel::kSupport / inv_h,
                 reach2 = reach * reach;
    const double xa = f.x[a], ya = f.y[a], za = f.z[a];
    std::uint32_t kept = list.begin(a);
    for (std::uint32_t k = list.begin(a); k < list.end(a); ++k) {
      const std::uint32_t j = list.neighbour[k];
      const double dx = xa - s.x[j], dy = ya - s.y[j], dz = za - s.z[j];
      const double r2 = dx * dx + dy * dy + dz * dz;
      if (r2 >= reach2) continue;
      const double q = std::sqrt(r2) * inv_h;
      if (q >= kernel::kSupport) continue;  // round-off at the edge
      sphere[kept] = j;
      w[kept] = kernel::w_q(q, inv_h);
      if (with_gradient) grad[kept] = kernel::grad_factor_q(q, inv_h);
      ++kept;
    }
    count[a] = kept - list.begin(a);
  }
}

}  // namespace sphdem
