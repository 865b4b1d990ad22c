#include "coupling/drag_exchange.hpp"

#include <omp.h>

#include "domain/row_partition.hpp"

namespace sphdem {

void drag_exchange_impulses(const DemParticles& s, const double* gain,
                            const FluidSpherePairs& pairs, const Halo& sphere_halo,
                            const double* phi, std::size_t n_fluid, double dt, PairAccumulator& acc,
                            std::vector<double>& impulse) {
  constexpr int kRow = 3;
  acc.reset(s.size(), kRow);
  const long nf = static_cast<long>(n_fluid);
#pragma omp parallel
  {
    const int t = omp_get_thread_num();
    const std::uint32_t* __restrict sphere = pairs.sphere.data();
    const double* __restrict w = pairs.drag_w().data();  // as the reaction's
    const auto [lo, hi] = thread_rows(pairs.list.offset, nf, kFluidRowCost);
    for (std::size_t a = lo; a < hi; ++a) {
      const double px = phi[3 * a], py = phi[3 * a + 1], pz = phi[3 * a + 2];
      if (px == 0.0 && py == 0.0 && pz == 0.0) continue;
      for (std::uint32_t k = pairs.begin(a); k < pairs.end(a); ++k) {
        double* r = acc.row(t, sphere[k]);
        r[0] += w[k] * px;
        r[1] += w[k] * py;
        r[2] += w[k] * pz;
      }
    }
  }
  double* sums = acc.fold();
  sphere_halo.add_to_sources(sums, kRow);
  const long ns = static_cast<long>(s.n_owned);
  impulse.resize(3 * s.n_owned);
#pragma omp parallel for schedule(static)
  for (long j = 0; j < ns; ++j) {
    const double S = s.shepard[j], c = S > 0.0 ? dt * gain[j] / S : 0.0;
    for (int d = 0; d < 3; ++d) impulse[3 * j + d] = c * sums[3 * j + d];
  }
}

}  // namespace sphdem
