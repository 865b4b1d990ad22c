#include "sph/density_rate.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>

#include "domain/row_partition.hpp"
#include "sph/kernel.hpp"

namespace sphdem {

namespace {

// One pair's terms of (2.53)/(2.54): a's with h_a, b's with h_b (u_ba . r_ba = u_ab . r_ab).
// Zero beyond both supports (the list's skin).
struct DensityTerms {
  double dwdh_a, div_a, dwdh_b, div_b;
  double minus_f;  // -(F_a + F_b)/2, the diffusion's weight (density_diffusion.hpp)
};
inline DensityTerms density_terms(double r, double udotr, double inv_ha, double inv_hb, double ma,
                                  double mb) {
  const double qa = r * inv_ha, qb = r * inv_hb;
  const double fa = kernel::grad_factor_q(qa, inv_ha), fb = kernel::grad_factor_q(qb, inv_hb);
  return {mb * kernel::dw_dh_q(qa, inv_ha), mb * fa * udotr, ma * kernel::dw_dh_q(qb, inv_hb),
          ma * fb * udotr, -0.5 * (fa + fb)};
}

// The diffusion's psi_b - psi_a less its part along the pair's mean renormalised gradient,
// (G_a + G_b)/2 . (r_b - r_a) (density_diffusion.hpp; G = 0 in the `hydrostatic` form),
// given G_a + G_b and r_a - r_b.
inline double psi_difference(double psi_a, double psi_b, double gx_sum, double gy_sum,
                             double gz_sum, double dx, double dy, double dz) {
  return psi_b - psi_a + 0.5 * (gx_sum * dx + gy_sum * dy + gz_sum * dz);
}

inline double self_dwdh(const FluidParticles& f, long a) {  // the self term of (2.54)
  return f.mass[a] * kernel::dw_dh_q(0.0, f.inv_h[a]);
}

// Which diffusion term the rows add: none, the `hydrostatic` form's (G = 0, not read) or
// the `renormalised` one's.
enum class DiffusionRows { kNone, kHydrostatic, kRenormalised };

// Rows [lo, hi) of the half list, one pair at a time: the skin's entries are skipped, an
// owned b gets its share at once.
template <DiffusionRows kRows>
void density_rows_baseline(const FluidParticles& f, const NeighbourList& half, PairAccumulator& acc,
                           int t, long lo, long hi) {
  constexpr bool kDiffusion = kRows != DiffusionRows::kNone;
  constexpr bool kG = kRows == DiffusionRows::kRenormalised;
  const auto n = static_cast<std::uint32_t>(f.n_owned);
  for (long a = lo; a < hi; ++a) {
    const double ha = f.h[a], inv_ha = f.inv_h[a], ma = f.mass[a];
    const double xa = f.x[a], ya = f.y[a], za = f.z[a];
    const double vxa = f.vx[a], vya = f.vy[a], vza = f.vz[a];
    double sum_dwdh = self_dwdh(f, a), sum_div = 0.0, sum_diff = 0.0;
    const double psi_a = kDiffusion ? f.diffusion_psi[a] : 0.0;
    const double vol_a = kDiffusion ? f.diffusion_volume[a] : 0.0;
    const double gxa = kG ? f.diffusion_gx[a] : 0.0, gya = kG ? f.diffusion_gy[a] : 0.0,
                 gza = kG ? f.diffusion_gz[a] : 0.0;
    for (std::uint32_t k = half.begin(a); k < half.end(a); ++k) {
      const std::uint32_t b = half.neighbour[k];
      const double dx = xa - f.x[b], dy = ya - f.y[b], dz = za - f.z[b];
      const double r2 = dx * dx + dy * dy + dz * dz,
                   reach = kernel::kSupport * std::max(ha, f.h[b]);
      if (r2 >= reach * reach) continue;  // in the list's skin only
      const double udotr = (vxa - f.vx[b]) * dx + (vya - f.vy[b]) * dy + (vza - f.vz[b]) * dz;
      const DensityTerms d = density_terms(std::sqrt(r2), udotr, inv_ha, f.inv_h[b], ma, f.mass[b]);
      sum_dwdh += d.dwdh_a;
      sum_div += d.div_a;
      const double dpsi_f =
          kDiffusion
              ? (kG ? psi_difference(psi_a, f.diffusion_psi[b], gxa + f.diffusion_gx[b],
                                     gya + f.diffusion_gy[b], gza + f.diffusion_gz[b], dx, dy, dz)
                    : f.diffusion_psi[b] - psi_a) *
                    d.minus_f
              : 0.0;
      if constexpr (kDiffusion) sum_diff += dpsi_f * f.diffusion_volume[b];
      if (b < n) {  // the mirror pair, for the owned b
        double* rb = acc.row(t, b);
        rb[0] += d.dwdh_b;
        rb[1] += d.div_b;
        if constexpr (kDiffusion) rb[2] -= dpsi_f * vol_a;
      }
    }
    double* ra = acc.row(t, a);
    ra[0] += sum_dwdh;
    ra[1] += sum_div;
    if constexpr (kDiffusion) ra[2] += sum_diff;
  }
}

// The same rows, each row's pairs in eight lanes: b's shares are kept per entry and
// scattered after the vectorised loop to the owned b (a halo b's owner takes the pair from
// its own row, as in the scalar rows); the skin's entries are evaluated and come out zero.
template <DiffusionRows kRows>
inline void density_rows_lanes(const FluidParticles& f, const NeighbourList& half,
                               PairAccumulator& acc, int t, long lo, long hi) {
  constexpr bool kDiffusion = kRows != DiffusionRows::kNone;
  constexpr bool kG = kRows == DiffusionRows::kRenormalised;
  const auto n = static_cast<std::uint32_t>(f.n_owned);
  const double* __restrict x = f.x.data();
  const double* __restrict y = f.y.data();
  const double* __restrict z = f.z.data();
  const double* __restrict vx = f.vx.data();
  const double* __restrict vy = f.vy.data();
  const double* __restrict vz = f.vz.data();
  const double* __restrict inv_h = f.inv_h.data();
  const double* __restrict mass = f.mass.data();
  const double* __restrict psi = f.diffusion_psi.data();
  const double* __restrict vol = f.diffusion_volume.data();
  const double* __restrict gx = f.diffusion_gx.data();
  const double* __restrict gy = f.diffusion_gy.data();
  const double* __restrict gz = f.diffusion_gz.data();
  const std::size_t mirrors = kDiffusion ? 3 : 2;
  for (long a = lo; a < hi; ++a) {
    const double inv_ha = inv_h[a], ma = mass[a];
    const double xa = x[a], ya = y[a], za = z[a];
    const double vxa = vx[a], vya = vy[a], vza = vz[a];
    const double psi_a = kDiffusion ? psi[a] : 0.0, vol_a = kDiffusion ? vol[a] : 0.0;
    const double gxa = kG ? gx[a] : 0.0, gya = kG ? gy[a] : 0.0, gza = kG ? gz[a] : 0.0;
    const std::uint32_t* __restrict nb = half.neighbour.data() + half.begin(a);
    const std::uint32_t len = half.end(a) - half.begin(a);
    double sum_dwdh = self_dwdh(f, a), sum_div = 0.0, sum_diff = 0.0;
    const std::uint32_t last = len == 0 ? 0 : len - 1, padded = (len + 7) & ~7u;
    double* __restrict mirror_dwdh = acc.entries(t, mirrors * std::size_t{padded});
    double* __restrict mirror_div = mirror_dwdh + padded;
    double* __restrict mirror_diff = mirror_div + padded;
#pragma omp simd reduction(+ : sum_dwdh, sum_div, sum_diff)
    for (std::uint32_t k = 0; k < padded; ++k) {  // whole vectors: the tail repeats the last
      const double live = k < len ? 1.0 : 0.0;    // entry, with weight 0 for a
      const std::uint32_t b = nb[std::min(k, last)];
      const double dx = xa - x[b], dy = ya - y[b], dz = za - z[b];
      const double udotr = (vxa - vx[b]) * dx + (vya - vy[b]) * dy + (vza - vz[b]) * dz;
      const DensityTerms d = density_terms(std::sqrt(dx * dx + dy * dy + dz * dz), udotr, inv_ha,
                                           inv_h[b], ma, live * mass[b]);
      sum_dwdh += d.dwdh_a;
      sum_div += d.div_a;
      mirror_dwdh[k] = d.dwdh_b;
      mirror_div[k] = d.div_b;
      if constexpr (kDiffusion) {
        const double dpsi_f =
            (kG ? psi_difference(psi_a, psi[b], gxa + gx[b], gya + gy[b], gza + gz[b], dx, dy, dz)
                : psi[b] - psi_a) *
            d.minus_f;
        sum_diff += dpsi_f * live * vol[b];
        mirror_diff[k] = -dpsi_f * vol_a;
      }
    }
    for (std::uint32_t k = 0; k < len; ++k) {
      if (nb[k] >= n) continue;  // a halo b: its owner's row gets the pair from its own side
      double* rb = acc.row(t, nb[k]);
      rb[0] += mirror_dwdh[k];
      rb[1] += mirror_div[k];
      if constexpr (kDiffusion) rb[2] += mirror_diff[k];
    }
    double* ra = acc.row(t, a);
    ra[0] += sum_dwdh;
    ra[1] += sum_div;
    if constexpr (kDiffusion) ra[2] += sum_diff;
  }
}

template <DiffusionRows kRows>
SPHDEM_TARGET_AVX512 void density_rows_avx512(const FluidParticles& f, const NeighbourList& half,
                                              PairAccumulator& acc, int t, long lo, long hi) {
  density_rows_lanes<kRows>(f, half, acc, t, lo, hi);
}

// The scalar rows compiled for x86-64-v3 (fused multiply-add).
template <DiffusionRows kRows>
SPHDEM_TARGET_AVX2 void density_rows_avx2(const FluidParticles& f, const NeighbourList& half,
                                          PairAccumulator& acc, int t, long lo, long hi) {
  density_rows_baseline<kRows>(f, half, acc, t, lo, hi);
}

// The rows for the instruction set.
template <DiffusionRows kRows>
void density_rows(const FluidParticles& f, const NeighbourList& half, PairAccumulator& acc, int t,
                  long lo, long hi, PairIsa isa) {
  if (isa == PairIsa::kAvx512)
    density_rows_avx512<kRows>(f, half, acc, t, lo, hi);
  else if (isa == PairIsa::kAvx2)
    density_rows_avx2<kRows>(f, half, acc, t, lo, hi);
  else
    density_rows_baseline<kRows>(f, half, acc, t, lo, hi);
}

// The rows for the diffusion term and the instruction set.
void density_rows(const FluidParticles& f, const NeighbourList& half, PairAccumulator& acc, int t,
                  long lo, long hi, DiffusionRows rows, PairIsa isa) {
  switch (rows) {
    case DiffusionRows::kNone:
      return density_rows<DiffusionRows::kNone>(f, half, acc, t, lo, hi, isa);
    case DiffusionRows::kHydrostatic:
      return density_rows<DiffusionRows::kHydrostatic>(f, half, acc, t, lo, hi, isa);
    case DiffusionRows::kRenormalised:
      return density_rows<DiffusionRows::kRenormalised>(f, half, acc, t, lo, hi, isa);
  }
}

}  // namespace

std::size_t compute_density_rate(FluidParticles& f, const NeighbourList& half, PairAccumulator& acc,
                                 bool voidage_weighted_pressure, const HydrostaticPressure& ph,
                                 const DensityDiffusion& dd, PairIsa isa) {
  const long n = static_cast<long>(f.n_owned);
  const bool diffusion = dd.on();
  const DiffusionRows rows = !diffusion        ? DiffusionRows::kNone
                             : dd.renormalised ? DiffusionRows::kRenormalised
                                               : DiffusionRows::kHydrostatic;
  // per particle: sum_b m_b dW/dh, sum_b m_b u_ab . grad W (and the diffusion's sum)
  acc.reset(n, diffusion ? 3 : 2);
#pragma omp parallel
  {
    const int t = omp_get_thread_num();
    const auto [lo, hi] = thread_rows(half.offset, n, kPairRowCost);
    density_rows(f, half, acc, t, lo, hi, rows, isa);
  }
  const double diffusivity = 2.0 * dd.delta * dd.c0;  // D_a = diffusivity h_a eps_a sum
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
    if (diffusion && f.kind[a] == kFluid)
      f.drho[a] += diffusivity * f.h[a] * f.eps[a] * acc.sum(a, 2);
    f.p_term[a] = (voidage_weighted_pressure ? f.eps[a] : 1.0) * (f.P[a] - ph(f.z[a])) /
                  (omega * f.rho[a] * f.rho[a]);
  }
  return bounded;
}

}  // namespace sphdem
