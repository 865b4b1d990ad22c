#include "sph/diffusion_gradient.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>

#include "domain/row_partition.hpp"
#include "sph/kernel.hpp"

namespace sphdem {

namespace {

// Per particle: the moment matrix sum_b V_b w r r (symmetric: xx, yy, zz, xy, xz, yz) and
// sum_b V_b w (psi_a - psi_b) r, with r = r_a - r_b and w = -F_ab > 0 (for a linear psi
// = g . x the second is the first times g).
constexpr int kFields = 9;

// One pair's nine terms (V_b w r r and V_b w (psi_a - psi_b) r, without V_b), w = -F_ab.
struct GradientTerms {
  double t[kFields];
};
inline GradientTerms gradient_terms(double dx, double dy, double dz, double dpsi, double inv_ha,
                                    double inv_hb) {
  const double r = std::sqrt(dx * dx + dy * dy + dz * dz);
  const double w = -0.5 * (kernel::grad_factor_q(r * inv_ha, inv_ha) +
                           kernel::grad_factor_q(r * inv_hb, inv_hb));
  const double wx = w * dx, wy = w * dy, wz = w * dz;
  return {{wx * dx, wy * dy, wz * dz, wx * dy, wx * dz, wy * dz, wx * dpsi, wy * dpsi, wz * dpsi}};
}

// Rows [lo, hi) of the half list, one pair at a time; an owned b gets its share at once (the
// mirror pair has the same r r, and (psi_b - psi_a)(r_b - r_a) alike).
void gradient_rows_baseline(const FluidParticles& f, const NeighbourList& half,
                            PairAccumulator& acc, int t, long lo, long hi) {
  const auto n = static_cast<std::uint32_t>(f.n_owned);
  for (long a = lo; a < hi; ++a) {
    const double psi_a = f.diffusion_psi[a], vol_a = f.diffusion_volume[a];
    if (vol_a == 0.0) continue;  // a wall: no G of its own, nothing for its neighbours'
    double sum[kFields] = {};
    for (std::uint32_t k = half.begin(a); k < half.end(a); ++k) {
      const std::uint32_t b = half.neighbour[k];
      const double dx = f.x[a] - f.x[b], dy = f.y[a] - f.y[b], dz = f.z[a] - f.z[b];
      // beyond both supports (the list's skin) both grad factors are zero
      const GradientTerms g =
          gradient_terms(dx, dy, dz, psi_a - f.diffusion_psi[b], f.inv_h[a], f.inv_h[b]);
      const double vol_b = f.diffusion_volume[b];
      for (int i = 0; i < kFields; ++i) sum[i] += vol_b * g.t[i];
      if (b < n) {
        double* rb = acc.row(t, b);
        for (int i = 0; i < kFields; ++i) rb[i] += vol_a * g.t[i];
      }
    }
    double* ra = acc.row(t, a);
    for (int i = 0; i < kFields; ++i) ra[i] += sum[i];
  }
}

// The same rows, each row's pairs in eight lanes (as sph/density_rate.cpp's): the terms
// are kept per entry and scattered to the owned b after the vectorised loop.
inline void gradient_rows_lanes(const FluidParticles& f, const NeighbourList& half,
                                PairAccumulator& acc, int t, long lo, long hi) {
  const auto n = static_cast<std::uint32_t>(f.n_owned);
  const double* __restrict x = f.x.data();
  const double* __restrict y = f.y.data();
  const double* __restrict z = f.z.data();
  const double* __restrict inv_h = f.inv_h.data();
  const double* __restrict psi = f.diffusion_psi.data();
  const double* __restrict vol = f.diffusion_volume.data();
  for (long a = lo; a < hi; ++a) {
    const double xa = x[a], ya = y[a], za = z[a], inv_ha = inv_h[a], psi_a = psi[a];
    const double vol_a = vol[a];
    if (vol_a == 0.0) continue;  // a wall: no G of its own, nothing for its neighbours'
    const std::uint32_t* __restrict nb = half.neighbour.data() + half.begin(a);
    const std::uint32_t len = half.end(a) - half.begin(a);
    const std::uint32_t last = len == 0 ? 0 : len - 1, padded = (len + 7) & ~7u;
    double* __restrict terms = acc.entries(t, kFields * std::size_t{padded});
    double* __restrict m0 = terms;        // field i at m0 + i padded: named, so that the compiler
    double* __restrict m1 = m0 + padded;  // sees unit-stride stores (a 32-bit i padded + k
    double* __restrict m2 = m1 + padded;  // may wrap, which made them scatters)
    double* __restrict m3 = m2 + padded;
    double* __restrict m4 = m3 + padded;
    double* __restrict m5 = m4 + padded;
    double* __restrict m6 = m5 + padded;
    double* __restrict m7 = m6 + padded;
    double* __restrict m8 = m7 + padded;
    double s0 = 0, s1 = 0, s2 = 0, s3 = 0, s4 = 0, s5 = 0, s6 = 0, s7 = 0, s8 = 0;
#pragma omp simd reduction(+ : s0, s1, s2, s3, s4, s5, s6, s7, s8)
    for (std::uint32_t k = 0; k < padded; ++k) {  // whole vectors: the tail repeats the last
      const double live = k < len ? 1.0 : 0.0;    // entry, with weight 0
      const std::uint32_t b = nb[std::min(k, last)];
      const GradientTerms g =
          gradient_terms(xa - x[b], ya - y[b], za - z[b], psi_a - psi[b], inv_ha, inv_h[b]);
      const double vb = live * vol[b];
      s0 += vb * g.t[0], s1 += vb * g.t[1], s2 += vb * g.t[2];
      s3 += vb * g.t[3], s4 += vb * g.t[4], s5 += vb * g.t[5];
      s6 += vb * g.t[6], s7 += vb * g.t[7], s8 += vb * g.t[8];
      m0[k] = vol_a * g.t[0], m1[k] = vol_a * g.t[1], m2[k] = vol_a * g.t[2];
      m3[k] = vol_a * g.t[3], m4[k] = vol_a * g.t[4], m5[k] = vol_a * g.t[5];
      m6[k] = vol_a * g.t[6], m7[k] = vol_a * g.t[7], m8[k] = vol_a * g.t[8];
    }
    for (std::uint32_t k = 0; k < len; ++k) {
      if (nb[k] >= n) continue;  // a halo b: its owner's row gets the pair from its side
      double* rb = acc.row(t, nb[k]);
      rb[0] += m0[k], rb[1] += m1[k], rb[2] += m2[k], rb[3] += m3[k], rb[4] += m4[k];
      rb[5] += m5[k], rb[6] += m6[k], rb[7] += m7[k], rb[8] += m8[k];
    }
    double* ra = acc.row(t, a);
    const double sums[kFields] = {s0, s1, s2, s3, s4, s5, s6, s7, s8};
    for (int i = 0; i < kFields; ++i) ra[i] += sums[i];
  }
}

SPHDEM_TARGET_AVX512 void gradient_rows_avx512(const FluidParticles& f, const NeighbourList& half,
                                               PairAccumulator& acc, int t, long lo, long hi) {
  gradient_rows_lanes(f, half, acc, t, lo, hi);
}

SPHDEM_TARGET_AVX2 void gradient_rows_avx2(const FluidParticles& f, const NeighbourList& half,
                                           PairAccumulator& acc, int t, long lo, long hi) {
  gradient_rows_baseline(f, half, acc, t, lo, hi);
}

}  // namespace

void compute_diffusion_gradient(FluidParticles& f, const NeighbourList& half, PairAccumulator& acc,
                                PairIsa isa) {
  const long n = static_cast<long>(f.n_owned);
  acc.reset(n, kFields);
#pragma omp parallel
  {
    const int t = omp_get_thread_num();
    const auto [lo, hi] = thread_rows(half.offset, n, kPairRowCost);
    if (isa == PairIsa::kAvx512)
      gradient_rows_avx512(f, half, acc, t, lo, hi);
    else if (isa == PairIsa::kAvx2)
      gradient_rows_avx2(f, half, acc, t, lo, hi);
    else
      gradient_rows_baseline(f, half, acc, t, lo, hi);
  }
  const double* m = acc.fold();
#pragma omp parallel for schedule(static)
  for (long a = 0; a < n; ++a) {
    const double* s = m + a * kFields;
    const double xx = s[0], yy = s[1], zz = s[2], xy = s[3], xz = s[4], yz = s[5];
    // the cofactors of the symmetric moment matrix: its inverse is cof / det
    const double cxx = yy * zz - yz * yz, cyy = xx * zz - xz * xz, czz = xx * yy - xy * xy;
    const double cxy = xz * yz - xy * zz, cxz = xy * yz - xz * yy, cyz = xy * xz - xx * yz;
    const double det = xx * cxx + xy * cxy + xz * cxz;
    double gx = 0.0, gy = 0.0, gz = 0.0;
    if (f.kind[a] == kFluid && det >= kMinMomentDeterminant) {
      const double inv = 1.0 / det, bx = s[6], by = s[7], bz = s[8];
      gx = (cxx * bx + cxy * by + cxz * bz) * inv;
      gy = (cxy * bx + cyy * by + cyz * bz) * inv;
      gz = (cxz * bx + cyz * by + czz * bz) * inv;
    }
    f.diffusion_gx[a] = gx;
    f.diffusion_gy[a] = gy;
    f.diffusion_gz[a] = gz;
  }
}

}  // namespace sphdem
