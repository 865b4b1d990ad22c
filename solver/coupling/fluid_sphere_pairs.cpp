#include "coupling/fluid_sphere_pairs.hpp"

#include <cmath>
#include <stdexcept>

#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>
#endif

#include "domain/row_partition.hpp"
#include "sph/kernel.hpp"
#include "sph/pair_isa.hpp"

namespace sphdem {

namespace {

// v sized n for values the caller writes before reading: a vector outgrown is allocated
// anew with a quarter to spare, its old values not copied (a list of 1e7 entries grows by
// a few hundred between builds).
template <class T>
void fresh_size(std::vector<T>& v, std::size_t n) {
  if (n > v.capacity()) {
    std::vector<T>().swap(v);
    v.reserve(n + n / 4);
  }
  v.resize(n);
}

}  // namespace

void FluidSpherePairs::build_list(const FluidParticles& f, const CellList& dem_cells,
                                  double kernel_scale, double rc, double drag_kernel_scale) {
  list.build(dem_cells, f.x.data(), f.y.data(), f.z.data(), f.n_owned, rc, false);
  size_for_list(f, kernel_scale, drag_kernel_scale);
}

void FluidSpherePairs::build_list(const FluidParticles& f, const CellList& dem_cells,
                                  double kernel_scale, const double* rc, double drag_kernel_scale) {
  list.build_within(dem_cells, f.x.data(), f.y.data(), f.z.data(), f.n_owned, rc);
  size_for_list(f, kernel_scale, drag_kernel_scale);
}

void FluidSpherePairs::size_for_list(const FluidParticles& f, double kernel_scale,
                                     double drag_kernel_scale) {
  scale = kernel_scale;
  drag_scale = drag_kernel_scale > 0.0 ? drag_kernel_scale : kernel_scale;
  if (drag_scale > scale)
    throw std::invalid_argument("FluidSpherePairs: the drag's kernel reaches beyond the pairs'");
  const std::size_t n = list.neighbour.size();
  fresh_size(sphere, n);
  fresh_size(w, n);
  fresh_size(grad, n);
  fresh_size(w_drag, drag_apart() ? n : 0);
  count.assign(f.n_owned, 0);
  solid.resize(f.n_owned);
  solid_over_d.resize(f.n_owned);
  drag_solid.resize(drag_apart() ? f.n_owned : 0);
  drag_solid_over_d.resize(drag_apart() ? f.n_owned : 0);
}

namespace {

// A sphere's volume V and V / d per unit r^3 and r^2.
constexpr double kVolumePerR3 = 4.0 / 3.0 * M_PI, kVolumeOverDPerR2 = 2.0 / 3.0 * M_PI;

// Row a, one entry at a time: the spheres within 2 H_a kept, in order, with their values.
void evaluate_row_baseline(FluidSpherePairs& p, const FluidParticles& f, const DemParticles& s,
                           bool with_gradient, std::size_t a) {
  const double inv_h = p.inv_kernel_h(f, a), reach = kernel::kSupport / inv_h,
               reach2 = reach * reach, inv_hd = p.inv_drag_kernel_h(f, a);
  const bool apart = p.drag_apart();
  const double xa = f.x[a], ya = f.y[a], za = f.z[a];
  std::uint32_t kept = p.list.begin(a);
  double solid = 0.0, solid_over_d = 0.0, drag_solid = 0.0, drag_solid_over_d = 0.0;
  for (std::uint32_t k = p.list.begin(a); k < p.list.end(a); ++k) {
    const std::uint32_t j = p.list.neighbour[k];
    const double dx = xa - s.x[j], dy = ya - s.y[j], dz = za - s.z[j];
    const double r2 = dx * dx + dy * dy + dz * dz;
    if (r2 >= reach2) continue;
    const double q = std::sqrt(r2) * inv_h;
    if (q >= kernel::kSupport) continue;  // round-off at the edge
    const double rj = s.radius[j], v = kVolumePerR3 * rj * rj * rj,
                 v_over_d = kVolumeOverDPerR2 * rj * rj;
    p.sphere[kept] = j;
    p.w[kept] = kernel::w_q(q, inv_h);
    solid += v * p.w[kept];
    solid_over_d += v_over_d * p.w[kept];
    if (with_gradient) p.grad[kept] = kernel::grad_factor_q(q, inv_h);
    if (apart) {
      p.w_drag[kept] = kernel::w_q(std::sqrt(r2) * inv_hd, inv_hd);  // 0 beyond 2 H^drag
      drag_solid += v * p.w_drag[kept];
      drag_solid_over_d += v_over_d * p.w_drag[kept];
    }
    ++kept;
  }
  p.count[a] = kept - p.list.begin(a);
  p.solid[a] = solid;
  p.solid_over_d[a] = solid_over_d;
  if (apart) {
    p.drag_solid[a] = drag_solid;
    p.drag_solid_over_d[a] = drag_solid_over_d;
  }
}

#if defined(__x86_64__) && defined(__GNUC__)
// Row entries [0, len) with W > 0 moved forward in place, eight at a time (AVX-512
// compress: each block's kept entries packed in a register, stored under a mask; a store
// ends at or before the block it packs, which has been read). Returns how many are kept.
template <bool kGradient, bool kDragApart>
SPHDEM_TARGET_AVX512 std::uint32_t compact_row(const std::uint32_t* nb, std::uint32_t len,
                                               std::uint32_t* sphere, double* w, double* grad,
                                               double* wd) {
  std::uint32_t kept = 0;
  for (std::uint32_t k = 0; k < len; k += 8) {
    const __mmask8 live = len - k >= 8 ? 0xff : static_cast<__mmask8>((1u << (len - k)) - 1u);
    const __m512d wk = _mm512_maskz_loadu_pd(live, w + k);
    const __mmask8 inside = _mm512_mask_cmp_pd_mask(live, wk, _mm512_setzero_pd(), _CMP_GT_OQ);
    const __mmask8 out = static_cast<__mmask8>((1u << __builtin_popcount(inside)) - 1u);
    _mm256_mask_storeu_epi32(
        sphere + kept, out,
        _mm256_maskz_compress_epi32(inside, _mm256_maskz_loadu_epi32(live, nb + k)));
    _mm512_mask_storeu_pd(w + kept, out, _mm512_maskz_compress_pd(inside, wk));
    if constexpr (kGradient)
      _mm512_mask_storeu_pd(
          grad + kept, out,
          _mm512_maskz_compress_pd(inside, _mm512_maskz_loadu_pd(live, grad + k)));
    if constexpr (kDragApart)
      _mm512_mask_storeu_pd(wd + kept, out,
                            _mm512_maskz_compress_pd(inside, _mm512_maskz_loadu_pd(live, wd + k)));
    kept += __builtin_popcount(inside);
  }
  return kept;
}
#else
template <bool kGradient, bool kDragApart>
std::uint32_t compact_row(const std::uint32_t* nb, std::uint32_t len, std::uint32_t* sphere,
                          double* w, double* grad, double* wd) {
  std::uint32_t kept = 0;
  for (std::uint32_t k = 0; k < len; ++k) {  // kept <= k: nothing is overwritten before it is read
    const double wk = w[k];
    sphere[kept] = nb[k];
    w[kept] = wk;
    if constexpr (kGradient) grad[kept] = grad[k];
    if constexpr (kDragApart) wd[kept] = wd[k];
    kept += wk > 0.0;
  }
  return kept;
}
#endif

// The same row in eight lanes: every entry's values first (W = 0 beyond the support),
// then the entries with W > 0 moved forward in place, without a branch.
template <bool kGradient, bool kDragApart>
inline void evaluate_row_lanes(FluidSpherePairs& p, const FluidParticles& f, const DemParticles& s,
                               std::size_t a) {
  const double inv_h = p.inv_kernel_h(f, a), inv_hd = p.inv_drag_kernel_h(f, a);
  const double xa = f.x[a], ya = f.y[a], za = f.z[a];
  const std::uint32_t k0 = p.list.begin(a), len = p.list.end(a) - k0;
  const std::uint32_t* __restrict nb = p.list.neighbour.data() + k0;
  const double* __restrict x = s.x.data();
  const double* __restrict y = s.y.data();
  const double* __restrict z = s.z.data();
  const double* __restrict radius = s.radius.data();
  double* __restrict w = p.w.data() + k0;
  double* __restrict grad = p.grad.data() + k0;
  double* __restrict wd = kDragApart ? p.w_drag.data() + k0 : nullptr;
  double solid = 0.0, solid_over_d = 0.0, drag_solid = 0.0, drag_solid_over_d = 0.0;
#pragma omp simd reduction(+ : solid, solid_over_d, drag_solid, drag_solid_over_d)
  for (std::uint32_t k = 0; k < len; ++k) {
    const std::uint32_t j = nb[k];
    const double dx = xa - x[j], dy = ya - y[j], dz = za - z[j];
    const double r = std::sqrt(dx * dx + dy * dy + dz * dz), q = r * inv_h;
    const double rj = radius[j], v = kVolumePerR3 * rj * rj * rj,
                 v_over_d = kVolumeOverDPerR2 * rj * rj;
    const double wk = kernel::w_q(q, inv_h);  // 0 beyond the support: adds nothing
    w[k] = wk;
    solid += v * wk;
    solid_over_d += v_over_d * wk;
    if constexpr (kGradient) grad[k] = kernel::grad_factor_q(q, inv_h);
    if constexpr (kDragApart) {
      const double wdk = kernel::w_q(r * inv_hd, inv_hd);
      wd[k] = wdk;
      drag_solid += v * wdk;
      drag_solid_over_d += v_over_d * wdk;
    }
  }
  p.solid[a] = solid;
  p.solid_over_d[a] = solid_over_d;
  if constexpr (kDragApart) {
    p.drag_solid[a] = drag_solid;
    p.drag_solid_over_d[a] = drag_solid_over_d;
  }
  p.count[a] = compact_row<kGradient, kDragApart>(nb, len, p.sphere.data() + k0, w, grad, wd);
}

template <bool kDragApart>
inline void evaluate_rows_lanes(FluidSpherePairs& p, const FluidParticles& f, const DemParticles& s,
                                bool with_gradient, std::size_t lo, std::size_t hi) {
  for (std::size_t a = lo; a < hi; ++a) {
    if (with_gradient)
      evaluate_row_lanes<true, kDragApart>(p, f, s, a);
    else
      evaluate_row_lanes<false, kDragApart>(p, f, s, a);
  }
}

SPHDEM_TARGET_AVX512 void evaluate_rows_avx512(FluidSpherePairs& p, const FluidParticles& f,
                                               const DemParticles& s, bool with_gradient,
                                               std::size_t lo, std::size_t hi) {
  if (p.drag_apart())
    evaluate_rows_lanes<true>(p, f, s, with_gradient, lo, hi);
  else
    evaluate_rows_lanes<false>(p, f, s, with_gradient, lo, hi);
}

}  // namespace

void FluidSpherePairs::evaluate(const FluidParticles& f, const DemParticles& s, bool with_gradient,
                                PairIsa isa) {
  const long n = static_cast<long>(f.n_owned);
  // rows differ (a bed, clear fluid): contiguous shares of equal entries
#pragma omp parallel
  {
    const auto [lo, hi] = thread_rows(list.offset, n, kFluidRowCost);
    if (isa == PairIsa::kAvx512)
      evaluate_rows_avx512(*this, f, s, with_gradient, lo, hi);
    else
      for (std::size_t a = lo; a < hi; ++a) evaluate_row_baseline(*this, f, s, with_gradient, a);
  }
}

}  // namespace sphdem
