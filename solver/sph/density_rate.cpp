#include "sph/density_rate.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>

#include "sph/kernel.hpp"

namespace sphdem {

std::size_t compute_density_rate(FluidParticles& f, const NeighbourList& half, PairAccumulator& acc,
                                 bool voidage_weighted_pressure, const HydrostaticPressure& ph) {
  const long n = static_cast<long>(f.n_owned);
  acc.reset(n, 2);  // per particle: sum_b m_b dW/dh, sum_b m_b u_ab . grad W
#pragma omp parallel
  {
    const int t = omp_get_thread_num();
#pragma omp for schedule(static)
    for (long a = 0; a < n; ++a) {
      const double inv_ha = f.inv_h[a], ma = f.mass[a], ha = f.h[a];
      const double xa = f.x[a], ya = f.y[a], za = f.z[a];
      const double vxa = f.vx[a], vya = f.vy[a], vza = f.vz[a];
      double sum_dwdh = ma * kernel::dw_dh_q(0.0, inv_ha), sum_div = 0.0;  // self term of (2.54)
      for (std::uint32_t k = half.begin(a); k < half.end(a); ++k) {
        const std::uint32_t b = half.neighbour[k];
        const double dx = xa - f.x[b], dy = ya - f.y[b], dz = za - f.z[b];
        const double r2 = dx * dx + dy * dy + dz * dz,
                     reach = kernel::kSupport * std::max(ha, f.h[b]);
        if (r2 >= reach * reach) continue;  // in the list's skin only
        const double r = std::sqrt(r2);
        const double udotr = (vxa - f.vx[b]) * dx + (vya - f.vy[b]) * dy + (vza - f.vz[b]) * dz;
        const double qa = r * inv_ha;
        if (qa < kernel::kSupport) {
          const double mb = f.mass[b];
          sum_dwdh += mb * kernel::dw_dh_q(qa, inv_ha);
          sum_div += mb * kernel::grad_factor_q(qa, inv_ha) * udotr;
        }
        if (b < static_cast<std::uint32_t>(n)) {  // the mirror pair, for the owned b
          const double inv_hb = f.inv_h[b], qb = r * inv_hb;
          if (qb < kernel::kSupport) {
            double* rb = acc.row(t, b);
            rb[0] += ma * kernel::dw_dh_q(qb, inv_hb);
            rb[1] += ma * kernel::grad_factor_q(qb, inv_hb) * udotr;  // u_ba . r_ba = u_ab . r_ab
          }
        }
      }
      double* ra = acc.row(t, a);
      ra[0] += sum_dwdh;
      ra[1] += sum_div;
    }
  }
  std::size_t bounded = 0;
#pragma omp parallel for schedule(static) reduction(+ : bounded)
  for (long a = 0; a < n; ++a) {
    double omega = 1.0 + f.h[a] / (3.0 * f.rho[a]) * acc.sum(a, 0);
    if (omega < 0.5 || omega > 2.0) {
      omega = std::clamp(omega, 0.5, 2.0);
      ++bounded;
    }
    f.omega[a] = omega;
    f.drho[a] = acc.sum(a, 1) / omega;
    f.p_term[a] = (voidage_weighted_pressure ? f.eps[a] : 1.0) * (f.P[a] - ph(f.z[a])) / (omega * f.rho[a] * f.rho[a]);
  }
  return bounded;
}

}  // namespace sphdem
