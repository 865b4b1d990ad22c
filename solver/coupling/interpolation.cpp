#include "coupling/interpolation.hpp"

#include "sph/kernel.hpp"

namespace sphdem {

void interpolate_fluid_at_spheres(DemParticles& s, const FluidParticles& f, const CellList& fluid_cells) {
  const long n = static_cast<long>(s.n_owned);
  const double rc = fluid_cells.max_cutoff();
#pragma omp parallel for schedule(static)
  for (long j = 0; j < n; ++j) {
    double S = 0, eps = 0, ux = 0, uy = 0, uz = 0, gx = 0, gy = 0, gz = 0;
    fluid_cells.for_each_neighbour(s.x[j], s.y[j], s.z[j], rc * rc,
                                   [&](std::uint32_t b, double, double, double, double r2) {
                                     if (f.kind[b] != kFluid) return;
                                     const double w = kernel::w(r2, f.h[b]);
                                     if (w == 0.0) return;
                                     const double mw = f.mass[b] * w;
                                     const double vw = mw / f.rho[b];
                                     S += vw;
                                     eps += vw * f.eps[b];
                                     ux += vw * f.vx[b];
                                     uy += vw * f.vy[b];
                                     uz += vw * f.vz[b];
                                     gx += mw * f.thx[b];
                                     gy += mw * f.thy[b];
                                     gz += mw * f.thz[b];
                                   });
    s.shepard[j] = S;
    if (S > 0.0) {
      const double inv = 1.0 / S;
      s.eps[j] = eps * inv;
      s.ufx[j] = ux * inv;
      s.ufy[j] = uy * inv;
      s.ufz[j] = uz * inv;
      s.gx[j] = gx * inv;
      s.gy[j] = gy * inv;
      s.gz[j] = gz * inv;
    } else {
      s.eps[j] = 1.0;
      s.ufx[j] = s.ufy[j] = s.ufz[j] = s.gx[j] = s.gy[j] = s.gz[j] = 0.0;
    }
  }
}

}  // namespace sphdem
