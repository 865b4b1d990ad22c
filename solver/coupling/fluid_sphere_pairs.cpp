#include "coupling/fluid_sphere_pairs.hpp"

#include <cmath>
#include <stdexcept>

#include "domain/row_partition.hpp"
#include "sph/kernel.hpp"
#include "sph/pair_isa.hpp"

namespace sphdem {

void FluidSpherePairs::build_list(const FluidParticles& f, const CellList& dem_cells,
                                  double kernel_scale, double rc, double drag_kernel_scale) {
  scale = kernel_scale;
  drag_scale = drag_kernel_scale > 0.0 ? drag_kernel_scale : kernel_scale;
  if (drag_scale > scale)
    throw std::invalid_argument("FluidSpherePairs: the drag's kernel reaches beyond the pairs'");
  list.build(dem_cells, f.x.data(), f.y.data(), f.z.data(), f.n_owned, rc, false);
  sphere.resize(list.neighbour.size());
  w.resize(list.neighbour.size());
  grad.resize(list.neighbour.size());
  w_drag.resize(drag_apart() ? list.neighbour.size() : 0);
  count.assign(f.n_owned, 0);
}

namespace {

// Row a, one entry at a time: the spheres within 2 H_a kept, in order, with their values.
void evaluate_row_baseline(FluidSpherePairs& p, const FluidParticles& f, const DemParticles& s,
                           bool with_gradient, std::size_t a) {
  const double inv_h = p.inv_kernel_h(f, a), reach = kernel::kSupport / inv_h,
               reach2 = reach * reach, inv_hd = p.inv_drag_kernel_h(f, a);
  const bool apart = p.drag_apart();
  const double xa = f.x[a], ya = f.y[a], za = f.z[a];
  std::uint32_t kept = p.list.begin(a);
  for (std::uint32_t k = p.list.begin(a); k < p.list.end(a); ++k) {
    const std::uint32_t j = p.list.neighbour[k];
    const double dx = xa - s.x[j], dy = ya - s.y[j], dz = za - s.z[j];
    const double r2 = dx * dx + dy * dy + dz * dz;
    if (r2 >= reach2) continue;
    const double q = std::sqrt(r2) * inv_h;
    if (q >= kernel::kSupport) continue;  // round-off at the edge
    p.sphere[kept] = j;
    p.w[kept] = kernel::w_q(q, inv_h);
    if (with_gradient) p.grad[kept] = kernel::grad_factor_q(q, inv_h);
    if (apart) p.w_drag[kept] = kernel::w_q(std::sqrt(r2) * inv_hd, inv_hd);  // 0 beyond 2 H^drag
    ++kept;
  }
  p.count[a] = kept - p.list.begin(a);
}

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
  double* __restrict w = p.w.data() + k0;
  double* __restrict grad = p.grad.data() + k0;
  double* __restrict wd = kDragApart ? p.w_drag.data() + k0 : nullptr;
#pragma omp simd
  for (std::uint32_t k = 0; k < len; ++k) {
    const std::uint32_t j = nb[k];
    const double dx = xa - x[j], dy = ya - y[j], dz = za - z[j];
    const double r = std::sqrt(dx * dx + dy * dy + dz * dz), q = r * inv_h;
    w[k] = kernel::w_q(q, inv_h);
    if constexpr (kGradient) grad[k] = kernel::grad_factor_q(q, inv_h);
    if constexpr (kDragApart) wd[k] = kernel::w_q(r * inv_hd, inv_hd);
  }
  std::uint32_t* __restrict sphere = p.sphere.data() + k0;
  std::uint32_t kept = 0;
  for (std::uint32_t k = 0; k < len; ++k) {  // kept <= k: nothing is overwritten before it is read
    const double wk = w[k];
    sphere[kept] = nb[k];
    w[kept] = wk;
    if constexpr (kGradient) grad[kept] = grad[k];
    if constexpr (kDragApart) wd[kept] = wd[k];
    kept += wk > 0.0;
  }
  p.count[a] = kept;
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
