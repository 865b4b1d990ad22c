#include "sph/momentum.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>

#include "domain/row_partition.hpp"
#include "sph/kernel.hpp"

namespace sphdem {

namespace {

// Rows [lo, hi) of the half list: theta and the signal speed of a, and of each owned b
// (the mirror pair: r_ba = -r_ab, u_ba = -u_ab).
inline void momentum_rows(const FluidParticles& f, const NeighbourList& half,
                          const MomentumParams& p, PairAccumulator& acc, int t, std::size_t lo,
                          std::size_t hi) {
  const auto n = static_cast<std::uint32_t>(f.n_owned);
  const double two_mu = 2.0 * p.viscosity;
  for (std::size_t a = lo; a < hi; ++a) {
    const double ha = f.h[a], inv_ha = f.inv_h[a], rhoa = f.rho[a], ma = f.mass[a];
    const double pa = f.p_term[a], ca = f.cs[a];
    const double xa = f.x[a], ya = f.y[a], za = f.z[a];
    const double vxa = f.vx[a], vya = f.vy[a], vza = f.vz[a];
    double tx = 0, ty = 0, tz = 0, vsig_max = ca;
    for (std::uint32_t k = half.begin(a); k < half.end(a); ++k) {
      const std::uint32_t b = half.neighbour[k];
      const double dx = xa - f.x[b], dy = ya - f.y[b], dz = za - f.z[b];
      const double r2 = dx * dx + dy * dy + dz * dz;
      const double hb = f.h[b], reach = kernel::kSupport * std::max(ha, hb);
      if (r2 >= reach * reach) continue;  // in the list's skin only
      const double r = std::sqrt(r2), inv_r = 1.0 / r;
      const double inv_hb = f.inv_h[b];
      const double Fa = kernel::grad_factor_q(r * inv_ha, inv_ha);
      const double Fb = kernel::grad_factor_q(r * inv_hb, inv_hb);
      const double rhob = f.rho[b], mb = f.mass[b];
      const double ux = vxa - f.vx[b], uy = vya - f.vy[b], uz = vza - f.vz[b];
      const double udotr = ux * dx + uy * dy + uz * dz;
      const double vsig = 0.5 * (ca + f.cs[b]) + std::abs(udotr) * inv_r;
      double pi_ab = 0.0;
      if (udotr < 0.0)  // Monaghan (2.56), approaching pairs only
        pi_ab = -p.alpha_artificial * vsig * udotr * inv_r / (rhoa + rhob);
      // Symmetric in a and b: s (pressure, grad W = F r_ab) and the Morris factor.
      const double s = (pa + pi_ab) * Fa + (f.p_term[b] + pi_ab) * Fb;
      const double hm = 0.5 * (ha + hb);
      const double visc = two_mu * 0.5 * (Fa + Fb) * r2 / (rhoa * rhob * (r2 + 0.01 * hm * hm));
      tx += mb * (-s * dx + visc * ux);
      ty += mb * (-s * dy + visc * uy);
      tz += mb * (-s * dz + visc * uz);
      vsig_max = std::max(vsig_max, vsig);
      if (b < n) {  // the mirror pair, for the owned b
        double* rb = acc.row(t, b);
        rb[0] += ma * (s * dx - visc * ux);
        rb[1] += ma * (s * dy - visc * uy);
        rb[2] += ma * (s * dz - visc * uz);
        rb[3] = std::max(rb[3], vsig);
      }
    }
    double* ra = acc.row(t, a);
    ra[0] += tx;
    ra[1] += ty;
    ra[2] += tz;
    ra[3] = std::max(ra[3], vsig_max);
  }
}

// The same loop compiled for x86-64-v4 (fused multiply-add; it stays one pair at a time:
// its thirteen gathers per pair cost more in eight lanes than the lanes save).
SPHDEM_TARGET_AVX512 void momentum_rows_avx512(const FluidParticles& f, const NeighbourList& half,
                                               const MomentumParams& p, PairAccumulator& acc, int t,
                                               std::size_t lo, std::size_t hi) {
  momentum_rows(f, half, p, acc, t, lo, hi);
}

// And for x86-64-v3 (fused multiply-add).
SPHDEM_TARGET_AVX2 void momentum_rows_avx2(const FluidParticles& f, const NeighbourList& half,
                                           const MomentumParams& p, PairAccumulator& acc, int t,
                                           std::size_t lo, std::size_t hi) {
  momentum_rows(f, half, p, acc, t, lo, hi);
}

}  // namespace

void compute_fluid_acceleration(FluidParticles& f, const NeighbourList& half,
                                const MomentumParams& p, PairAccumulator& acc, PairIsa isa) {
  const long n = static_cast<long>(f.n_owned);
  acc.reset(n, 4);  // theta x, y, z and the largest signal speed
#pragma omp parallel
  {
    const int t = omp_get_thread_num();
    const auto [lo, hi] = thread_rows(half.offset, n, kPairRowCost);
    if (isa == PairIsa::kAvx512)
      momentum_rows_avx512(f, half, p, acc, t, lo, hi);
    else if (isa == PairIsa::kAvx2)
      momentum_rows_avx2(f, half, p, acc, t, lo, hi);
    else
      momentum_rows(f, half, p, acc, t, lo, hi);
  }
#pragma omp parallel for schedule(static)
  for (long a = 0; a < n; ++a) {
    if (f.kind[a] == kWall) {  // walls only lend their pressure to the pairs
      f.thx[a] = f.thy[a] = f.thz[a] = 0.0;
      f.dt_limit[a] = 1e30;
      continue;
    }
    f.thx[a] = acc.sum(a, 0);
    f.thy[a] = acc.sum(a, 1);
    f.thz[a] = acc.sum(a, 2);
    f.dt_limit[a] = p.cfl * f.h[a] / std::max(acc.max(a, 3), f.cs[a]);
  }
}

}  // namespace sphdem
