#include "coupling/voidage.hpp"

#include "sph/kernel.hpp"

namespace sphdem {

std::size_t compute_fluid_voidage(FluidParticles& f, const DemParticles& s, const CellList& dem_cells,
                                  double eps_floor) {
  const long n = static_cast<long>(f.n_owned);
  std::size_t clamped = 0;
#pragma omp parallel for schedule(static) reduction(+ : clamped)
  for (long a = 0; a < n; ++a) {
    const double ha = f.h[a], rc = kernel::kSupport * ha;
    double solid = 0.0;
    dem_cells.for_each_neighbour(f.x[a], f.y[a], f.z[a], rc * rc,
                                 [&](std::uint32_t j, double, double, double, double r2) {
                                   solid += s.volume(j) * kernel::w(r2, ha);
                                 });
    double eps = 1.0 - solid;
    if (eps < eps_floor) {
      eps = eps_floor;
      ++clamped;
    }
    f.eps[a] = eps;
  }
  return clamped;
}

}  // namespace sphdem
