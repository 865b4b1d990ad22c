#include "coupling/pressure_coupling.hpp"

#include <omp.h>

namespace sphdem {

double couple_pressure_variationally(FluidParticles& f, DemParticles& s, const FluidSpherePairs& pairs,
                                     const std::vector<std::uint32_t>& halo_source, PairAccumulator& acc,
                                     const HydrostaticPressure& ph) {
  const std::size_t ns = s.n_owned;
  const long nf = static_cast<long>(f.n_owned);
  acc.reset(ns, 3);
  double walls_on_spheres_z = 0.0;
#pragma omp parallel
  {
    const int t = omp_get_thread_num();
#pragma omp for schedule(static, 64) reduction(+ : walls_on_spheres_z)
    for (long a = 0; a < nf; ++a) {
      const double p_dyn = f.P[a] - ph(f.z[a]);
      const double vp = f.mass[a] / f.rho[a] * p_dyn;  // V_a P_a
      double gx = 0.0, gy = 0.0, gz = 0.0;  // sum_j V_j grad_a W_aj = -grad eps_a
      for (std::uint32_t k = pairs.begin(a); k < pairs.end(a); ++k) {
        const std::uint32_t j = pairs.sphere[k];
        const double dx = f.x[a] - s.x[j], dy = f.y[a] - s.y[j], dz = f.z[a] - s.z[j];
        const double gf = pairs.grad[k], c = s.volume(j) * gf;
        gx += c * dx;
        gy += c * dy;
        gz += c * dz;
        double* r = acc.row(t, j < ns ? j : halo_source[j - ns]);  // per unit sphere volume
        r[0] += vp * gf * dx;
        r[1] += vp * gf * dy;
        r[2] += vp * gf * dz;
      }
      if (f.kind[a] != kFluid) {  // a wall particle: what it pushes on the spheres, V_a P_a sum_j V_j dW/dz_a
        walls_on_spheres_z += vp * gz;
        continue;
      }
      const double p_over_rho = p_dyn / f.rho[a];
      f.ax[a] -= p_over_rho * gx;
      f.ay[a] -= p_over_rho * gy;
      f.az[a] -= p_over_rho * gz + ph.gradient_z() * f.eps[a] / f.rho[a];  // -grad P_h / rho_intrinsic
    }
  }
#pragma omp parallel for schedule(static)
  for (long j = 0; j < static_cast<long>(ns); ++j) {
    s.gx[j] = acc.sum(j, 0);  // sum_a V_a P_a grad_a W_aj: the pressure force / V_j
    s.gy[j] = acc.sum(j, 1);
    s.gz[j] = acc.sum(j, 2) - ph.gradient_z();  // + the buoyancy -grad P_h
  }
  return walls_on_spheres_z;
}

}  // namespace sphdem
