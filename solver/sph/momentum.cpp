#include "sph/momentum.hpp"

#include <algorithm>
#include <cmath>

#include "sph/kernel.hpp"

namespace sphdem {

void compute_fluid_acceleration(FluidParticles& f, const NeighbourList& nl, const MomentumParams& p) {
  const long n = static_cast<long>(f.n_owned);
  const double two_mu = 2.0 * p.viscosity;
#pragma omp parallel for schedule(static)
  for (long a = 0; a < n; ++a) {
    if (f.kind[a] == kWall) {
      f.thx[a] = f.thy[a] = f.thz[a] = 0.0;
      f.dt_limit[a] = 1e30;
      continue;
    }
    const double ha = f.h[a], inv_ha = f.inv_h[a], rhoa = f.rho[a];
    const double pa = f.p_term[a];
    const double ca = f.cs[a];
    const double xa = f.x[a], ya = f.y[a], za = f.z[a];
    const double vxa = f.vx[a], vya = f.vy[a], vza = f.vz[a];
    double tx = 0, ty = 0, tz = 0, vsig_max = ca;
    for (std::uint32_t k = nl.begin(a); k < nl.end(a); ++k) {
      const std::uint32_t b = nl.neighbour[k];
      const double dx = xa - f.x[b], dy = ya - f.y[b], dz = za - f.z[b];
      const double r2 = dx * dx + dy * dy + dz * dz;
      const double r = std::sqrt(r2), inv_r = 1.0 / r;
      const double hb = f.h[b], inv_hb = f.inv_h[b];
      const double Fa = kernel::grad_factor_q(r * inv_ha, inv_ha);
      const double Fb = kernel::grad_factor_q(r * inv_hb, inv_hb);
      if (Fa == 0.0 && Fb == 0.0) continue;
      const double rhob = f.rho[b], mb = f.mass[b];
      const double ux = vxa - f.vx[b], uy = vya - f.vy[b], uz = vza - f.vz[b];
      const double udotr = ux * dx + uy * dy + uz * dz;
      const double vsig = 0.5 * (ca + f.cs[b]) + std::abs(udotr) * inv_r;
      vsig_max = std::max(vsig_max, vsig);
      double pi_ab = 0.0;
      if (udotr < 0.0)  // Monaghan (2.56), approaching pairs only
        pi_ab = -p.alpha_artificial * vsig * udotr * inv_r / (rhoa + rhob);
      const double pb = f.p_term[b];
      const double s = (pa + pi_ab) * Fa + (pb + pi_ab) * Fb;  // grad W = F r_ab
      // Morris laminar viscosity with the mean kernel gradient of the pair
      const double hm = 0.5 * (ha + hb);
      const double visc = mb * two_mu * 0.5 * (Fa + Fb) * r2 / (rhoa * rhob * (r2 + 0.01 * hm * hm));
      tx += -mb * s * dx + visc * ux;
      ty += -mb * s * dy + visc * uy;
      tz += -mb * s * dz + visc * uz;
    }
    f.thx[a] = tx;
    f.thy[a] = ty;
    f.thz[a] = tz;
    f.dt_limit[a] = p.cfl * ha / vsig_max;
  }
}

}  // namespace sphdem
