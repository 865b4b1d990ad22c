#include "coupling/distributor_mirror.hpp"

#include <cmath>

#include "domain/row_partition.hpp"
#include "sph/kernel.hpp"

namespace sphdem {

namespace {

// Row a of the drag's weights, between the plate images below and above the fluid
// particle (z_a may lie past the box between list builds; a halo sphere is an image).
void mirror_row(FluidSpherePairs& p, const FluidParticles& f, const DemParticles& s,
                const DistributorPlane& plane, std::size_t a) {
  const double inv_hd = p.inv_drag_kernel_h(f, a), reach = kernel::kSupport / inv_hd;
  const double za = f.z[a];
  const double below = plane.z + std::floor((za - plane.z) / plane.period) * plane.period,
               above = below + plane.period;
  const bool near_below = za - below < reach;
  if (!near_below && above - za >= reach) return;
  double solid = 0.0, solid_over_d = 0.0;
  for (std::uint32_t k = p.begin(a); k < p.end(a); ++k) {
    const std::uint32_t j = p.sphere[k];
    const double zj = s.z[j];
    if (zj < below || zj >= above) {  // across the plate: the plenum holds no sphere
      p.w_drag[k] = 0.0;
      continue;
    }
    if (near_below) {  // the mirror image at 2 below - z_j
      const double dx = f.x[a] - s.x[j], dy = f.y[a] - s.y[j], dz = za + zj - 2.0 * below;
      const double r = std::sqrt(dx * dx + dy * dy + dz * dz);
      p.w_drag[k] += kernel::w_q(r * inv_hd, inv_hd);
    }
    const double v = s.volume(j);
    solid += v * p.w_drag[k];
    solid_over_d += v * p.w_drag[k] / (2.0 * s.radius[j]);
  }
  p.drag_solid[a] = solid;  // (2.50) with the drag's weights
  p.drag_solid_over_d[a] = solid_over_d;
}

}  // namespace

void continue_bed_below_distributor(FluidSpherePairs& pairs, const FluidParticles& f,
                                    const DemParticles& s, const DistributorPlane& plane) {
  if (!plane.on()) return;
  const long n = static_cast<long>(f.n_owned);
#pragma omp parallel
  {
    const auto [lo, hi] = thread_rows(pairs.list.offset, n, kFluidRowCost);
    for (std::size_t a = lo; a < hi; ++a) mirror_row(pairs, f, s, plane, a);
  }
}

}  // namespace sphdem
