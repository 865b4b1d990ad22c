#include "coupling/voidage.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "coupling/drag_law_table.hpp"
#include "sph/kernel.hpp"

namespace sphdem {

namespace {

// Row a's sums sum_j V_j W_aj and sum_j V_j W_aj / d_j: from the pairs' evaluation, or
// without the big spheres' species when they are smoothed apart (3.8).
struct SolidSums {
  double solid = 0.0, solid_over_d = 0.0;
};

inline SolidSums solid_sums(const DemParticles& s, const FluidSpherePairs& pairs, bool drag,
                            std::size_t a, const BigSpheresSmoothedApart* big) {
  const bool apart = drag && pairs.drag_apart();
  if (!big)
    return apart ? SolidSums{pairs.drag_solid[a], pairs.drag_solid_over_d[a]}
                 : SolidSums{pairs.solid[a], pairs.solid_over_d[a]};
  const std::vector<double>& weights = apart ? pairs.w_drag : pairs.w;
  SolidSums sums;
  for (std::uint32_t k = pairs.begin(a); k < pairs.end(a); ++k) {
    const std::uint32_t j = pairs.sphere[k];
    if (big->is_big[s.species[j]]) continue;  // smoothed apart (3.8)
    const double vw = s.volume(j) * weights[k];
    sums.solid += vw;
    sums.solid_over_d += vw / (2.0 * s.radius[j]);
  }
  sums.solid += big->solid[a];  // (3.10)
  sums.solid_over_d += big->solid_over_d[a];
  return sums;
}

// 1 - the solid fraction, clamped to the floor (counted in clamped).
inline double floored_voidage(double solid, double eps_floor, std::size_t& clamped) {
  const double eps = 1.0 - solid;
  if (eps >= eps_floor) return eps;
  ++clamped;
  return eps_floor;
}

// Twice row a's solid sum over the spheres at or below it (level: half), the drag's kernel.
inline double upstream_solid(const FluidParticles& f, const DemParticles& s,
                             const FluidSpherePairs& pairs, std::size_t a) {
  const std::vector<double>& weights = pairs.drag_w();
  const double za = f.z[a];
  double lower = 0.0;
  for (std::uint32_t k = pairs.begin(a); k < pairs.end(a); ++k) {
    const std::uint32_t j = pairs.sphere[k];
    const double side = s.z[j] < za ? 2.0 : s.z[j] == za ? 1.0 : 0.0;
    lower += side * s.volume(j) * weights[k];
  }
  return lower;
}

}  // namespace

double VoidageUpstream::above_floor(double z) const {
  if (!has_floor) return std::numeric_limits<double>::infinity();
  const double d = z - floor_z;
  if (period <= 0.0) return d;
  const double m = d - period * std::floor(d / period);  // in [0, period)
  return std::min(m, period - m);
}

std::size_t compute_fluid_voidage(FluidParticles& f, const DemParticles& s,
                                  const FluidSpherePairs& pairs, double eps_floor,
                                  const BigSpheresSmoothedApart* big,
                                  const VoidageUpstream& upstream) {
  const long n = static_cast<long>(f.n_owned);
  const bool apart = pairs.drag_apart();
  std::size_t clamped = 0;
#pragma omp parallel for schedule(static) reduction(+ : clamped)
  for (long a = 0; a < n; ++a) {
    SolidSums sums = solid_sums(s, pairs, false, a, big);
    f.eps[a] = floored_voidage(sums.solid, eps_floor, clamped);
    if (apart) sums = solid_sums(s, pairs, true, a, big);  // the drag's kernel
    const bool upstream_here =
        upstream.on && !big && f.kind[a] == kFluid && sums.solid > 1.0 - kLoneSphereVoidage &&
        upstream.above_floor(f.z[a]) >= kernel::kSupport / pairs.inv_drag_kernel_h(f, a);
    if (upstream_here)
      f.eps_drag[a] = floored_voidage(upstream_solid(f, s, pairs, a), eps_floor, clamped);
    else if (apart)
      f.eps_drag[a] = floored_voidage(sums.solid, eps_floor, clamped);
    else
      f.eps_drag[a] = f.eps[a];
    // Sauter mean (sum_i x_i / d_i)^-1 with the kernel-weighted volume fractions x_i (2.80)
    f.d_sauter[a] = sums.solid_over_d > 0.0 ? sums.solid / sums.solid_over_d : 0.0;
  }
  return clamped;
}

}  // namespace sphdem
