#include "sph/density_rate.hpp"

#include <algorithm>
#include <cmath>

#include "sph/kernel.hpp"

namespace sphdem {

std::size_t compute_density_rate(FluidParticles& f, const NeighbourList& nl) {
  const long n = static_cast<long>(f.n_owned);
  std::size_t bounded = 0;
#pragma omp parallel for schedule(static) reduction(+ : bounded)
  for (long a = 0; a < n; ++a) {
    const double inv_h = 1.0 / f.h[a];
    const double xa = f.x[a], ya = f.y[a], za = f.z[a];
    const double vxa = f.vx[a], vya = f.vy[a], vza = f.vz[a];
    double sum_dwdh = f.mass[a] * kernel::dw_dh_q(0.0, inv_h), sum_div = 0.0;
    for (std::uint32_t k = nl.begin(a); k < nl.end(a); ++k) {
      const std::uint32_t b = nl.neighbour[k];
      const double dx = xa - f.x[b], dy = ya - f.y[b], dz = za - f.z[b];
      const double q = std::sqrt(dx * dx + dy * dy + dz * dz) * inv_h;
      if (q >= kernel::kSupport) continue;
      const double mb = f.mass[b];
      sum_dwdh += mb * kernel::dw_dh_q(q, inv_h);
      sum_div += mb * kernel::grad_factor_q(q, inv_h) *
                 ((vxa - f.vx[b]) * dx + (vya - f.vy[b]) * dy + (vza - f.vz[b]) * dz);
    }
    double omega = 1.0 + f.h[a] / (3.0 * f.rho[a]) * sum_dwdh;
    if (omega < 0.5 || omega > 2.0) {
      omega = std::clamp(omega, 0.5, 2.0);
      ++bounded;
    }
    f.omega[a] = omega;
    f.drho[a] = sum_div / omega;
    f.p_term[a] = f.P[a] / (omega * f.rho[a] * f.rho[a]);
  }
  return bounded;
}

}  // namespace sphdem
