#include "sph/momentum.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>

#include "domain/row_partition.hpp"
#include "sph/kernel.hpp"

namespace sphdem {

namespace {

// One pair's shares of theta (2.55-2.57, 2.70) with r_ab = (dx, dy, dz) and u_ab: the
// pressure factor s (grad W = F r_ab), the Morris factor and the signal speed; s and the
// Morris factor are zero beyond both supports (the kernels' clamp), the signal speed is not.
struct MomentumTerms {
  double s, visc, vsig;
};
inline MomentumTerms momentum_terms(double r2, double udotr, double ha, double hb, double inv_ha,
                                    double inv_hb, double rhoa, double rhob, double pa, double pb,
                                    double ca, double cb, double alpha, double two_mu) {
  const double r = std::sqrt(r2), inv_r = 1.0 / r;
  const double Fa = kernel::grad_factor_q(r * inv_ha, inv_ha);
  const double Fb = kernel::grad_factor_q(r * inv_hb, inv_hb);
  const double vsig = 0.5 * (ca + cb) + std::abs(udotr) * inv_r;
  // Monaghan (2.56), approaching pairs only
  const double pi_ab = udotr < 0.0 ? -alpha * vsig * udotr * inv_r / (rhoa + rhob) : 0.0;
  const double hm = 0.5 * (ha + hb);
  return {(pa + pi_ab) * Fa + (pb + pi_ab) * Fb,
          two_mu * 0.5 * (Fa + Fb) * r2 / (rhoa * rhob * (r2 + 0.01 * hm * hm)), vsig};
}

// Rows [lo, hi) of the half list, one pair at a time: theta and the signal speed of a, and
// of each owned b (the mirror pair: r_ba = -r_ab, u_ba = -u_ab); the skin's entries skipped.
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
      const double ux = vxa - f.vx[b], uy = vya - f.vy[b], uz = vza - f.vz[b];
      const MomentumTerms m =
          momentum_terms(r2, ux * dx + uy * dy + uz * dz, ha, hb, inv_ha, f.inv_h[b], rhoa,
                         f.rho[b], pa, f.p_term[b], ca, f.cs[b], p.alpha_artificial, two_mu);
      const double mb = f.mass[b];
      tx += mb * (-m.s * dx + m.visc * ux);
      ty += mb * (-m.s * dy + m.visc * uy);
      tz += mb * (-m.s * dz + m.visc * uz);
      vsig_max = std::max(vsig_max, m.vsig);
      if (b < n) {  // the mirror pair, for the owned b
        double* rb = acc.row(t, b);
        rb[0] += ma * (m.s * dx - m.visc * ux);
        rb[1] += ma * (m.s * dy - m.visc * uy);
        rb[2] += ma * (m.s * dz - m.visc * uz);
        rb[3] = std::max(rb[3], m.vsig);
      }
    }
    double* ra = acc.row(t, a);
    ra[0] += tx;
    ra[1] += ty;
    ra[2] += tz;
    ra[3] = std::max(ra[3], vsig_max);
  }
}

// The same rows, each row's pairs in eight lanes (as the density pass): every entry is
// evaluated, the skin's come out zero (their signal speed masked), b's shares are kept per
// entry and scattered after the lanes to the owned b (a halo b's owner takes the pair from
// its own row, as in the scalar rows).
inline void momentum_rows_lanes(const FluidParticles& f, const NeighbourList& half,
                                const MomentumParams& p, PairAccumulator& acc, int t,
                                std::size_t lo, std::size_t hi) {
  const auto n = static_cast<std::uint32_t>(f.n_owned);
  const double two_mu = 2.0 * p.viscosity, alpha = p.alpha_artificial;
  const double* __restrict x = f.x.data();
  const double* __restrict y = f.y.data();
  const double* __restrict z = f.z.data();
  const double* __restrict vx = f.vx.data();
  const double* __restrict vy = f.vy.data();
  const double* __restrict vz = f.vz.data();
  const double* __restrict h = f.h.data();
  const double* __restrict inv_h = f.inv_h.data();
  const double* __restrict rho = f.rho.data();
  const double* __restrict mass = f.mass.data();
  const double* __restrict p_term = f.p_term.data();
  const double* __restrict cs = f.cs.data();
  for (std::size_t a = lo; a < hi; ++a) {
    const double ha = h[a], inv_ha = inv_h[a], rhoa = rho[a], ma = mass[a];
    const double pa = p_term[a], ca = cs[a];
    const double xa = x[a], ya = y[a], za = z[a];
    const double vxa = vx[a], vya = vy[a], vza = vz[a];
    const std::uint32_t* __restrict nb = half.neighbour.data() + half.begin(a);
    const std::uint32_t len = half.end(a) - half.begin(a);
    if (len == 0) continue;
    const std::uint32_t last = len - 1, padded = (len + 7) & ~7u;
    double* __restrict mirror_x = acc.entries(t, 4 * std::size_t{padded});
    double* __restrict mirror_y = mirror_x + padded;
    double* __restrict mirror_z = mirror_y + padded;
    double* __restrict mirror_vsig = mirror_z + padded;
    double tx = 0, ty = 0, tz = 0, vsig_max = ca;
#pragma omp simd reduction(+ : tx, ty, tz) reduction(max : vsig_max)
    for (std::uint32_t k = 0; k < padded; ++k) {  // whole vectors: the tail repeats the last
      const double live = k < len ? 1.0 : 0.0;    // entry, with weight 0 for a
      const std::uint32_t b = nb[std::min(k, last)];
      const double dx = xa - x[b], dy = ya - y[b], dz = za - z[b];
      const double r2 = dx * dx + dy * dy + dz * dz;
      const double hb = h[b], reach = kernel::kSupport * std::max(ha, hb);
      const double ux = vxa - vx[b], uy = vya - vy[b], uz = vza - vz[b];
      const MomentumTerms m =
          momentum_terms(r2, ux * dx + uy * dy + uz * dz, ha, hb, inv_ha, inv_h[b], rhoa, rho[b],
                         pa, p_term[b], ca, cs[b], alpha, two_mu);
      const double vsig = r2 < reach * reach ? m.vsig : 0.0;  // the skin's: none
      const double mb = live * mass[b];
      tx += mb * (-m.s * dx + m.visc * ux);
      ty += mb * (-m.s * dy + m.visc * uy);
      tz += mb * (-m.s * dz + m.visc * uz);
      vsig_max = std::max(vsig_max, vsig);
      mirror_x[k] = ma * (m.s * dx - m.visc * ux);
      mirror_y[k] = ma * (m.s * dy - m.visc * uy);
      mirror_z[k] = ma * (m.s * dz - m.visc * uz);
      mirror_vsig[k] = vsig;
    }
    for (std::uint32_t k = 0; k < len; ++k) {
      if (nb[k] >= n) continue;  // a halo b: its owner's row gets the pair from its own side
      double* rb = acc.row(t, nb[k]);
      rb[0] += mirror_x[k];
      rb[1] += mirror_y[k];
      rb[2] += mirror_z[k];
      rb[3] = std::max(rb[3], mirror_vsig[k]);
    }
    double* ra = acc.row(t, a);
    ra[0] += tx;
    ra[1] += ty;
    ra[2] += tz;
    ra[3] = std::max(ra[3], vsig_max);
  }
}

// For x86-64-v4: eight lanes, gathers, fused multiply-add.
SPHDEM_TARGET_AVX512 void momentum_rows_avx512(const FluidParticles& f, const NeighbourList& half,
                                               const MomentumParams& p, PairAccumulator& acc, int t,
                                               std::size_t lo, std::size_t hi) {
  momentum_rows_lanes(f, half, p, acc, t, lo, hi);
}

// The scalar rows compiled for x86-64-v3 (fused multiply-add).
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
