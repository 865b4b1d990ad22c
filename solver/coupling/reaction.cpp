#include "coupling/reaction.hpp"

#include "sph/kernel.hpp"

namespace sphdem {

void add_reaction_on_fluid(FluidParticles& f, const DemParticles& s, const CellList& dem_cells) {
  const long n = static_cast<long>(f.n_owned);
#pragma omp parallel for schedule(static)
  for (long a = 0; a < n; ++a) {
    if (f.kind[a] != kFluid) continue;
    const double ha = f.h[a], rc = kernel::kSupport * ha;
    double rx = 0, ry = 0, rz = 0;
    dem_cells.for_each_neighbour(f.x[a], f.y[a], f.z[a], rc * rc,
                                 [&](std::uint32_t j, double, double, double, double r2) {
                                   if (s.shepard[j] <= 0.0) return;
                                   const double w = kernel::w(r2, ha) / s.shepard[j];
                                   rx += s.fmx[j] * w;
                                   ry += s.fmy[j] * w;
                                   rz += s.fmz[j] * w;
                                 });
    const double inv_rho = 1.0 / f.rho[a];
    f.ax[a] -= rx * inv_rho;
    f.ay[a] -= ry * inv_rho;
    f.az[a] -= rz * inv_rho;
  }
}

}  // namespace sphdem
