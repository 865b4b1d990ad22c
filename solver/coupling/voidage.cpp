#include "coupling/voidage.hpp"

#include "domain/row_partition.hpp"

namespace sphdem {

std::size_t compute_fluid_voidage(FluidParticles& f, const DemParticles& s,
                                  const FluidSpherePairs& pairs, double eps_floor,
                                  const BigSpheresSmoothedApart* big) {
  const long n = static_cast<long>(f.n_owned);
  std::size_t clamped = 0;
  // rows differ in length: contiguous shares of equal entries (domain/row_partition.hpp)
#pragma omp parallel reduction(+ : clamped)
  for (auto [a, end] = thread_rows(pairs.list.offset, n, kFluidRowCost); a < end; ++a) {
    double solid = 0.0, solid_over_d = 0.0;
    for (std::uint32_t k = pairs.begin(a); k < pairs.end(a); ++k) {
      const std::uint32_t j = pairs.sphere[k];
      if (big && big->is_big[s.species[j]]) continue;  // smoothed apart (3.8)
      const double vw = s.volume(j) * pairs.w[k];
      solid += vw;
      solid_over_d += vw / (2.0 * s.radius[j]);
    }
    if (big) {  // (3.10)
      solid += big->solid[a];
      solid_over_d += big->solid_over_d[a];
    }
    // Sauter mean (sum_i x_i / d_i)^-1 with the kernel-weighted volume fractions x_i (2.80)
    f.d_sauter[a] = solid_over_d > 0.0 ? solid / solid_over_d : 0.0;
    double eps = 1.0 - solid;
    if (eps < eps_floor) {
      eps = eps_floor;
      ++clamped;
    }
    f.eps[a] = eps;
  }
  return clamped;
}

}  // namespace sphdem
