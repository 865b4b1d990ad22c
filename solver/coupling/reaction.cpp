#include "coupling/reaction.hpp"

#include "domain/row_partition.hpp"

namespace sphdem {

void add_reaction_on_fluid(FluidParticles& f, const DemParticles& s,
                           const FluidSpherePairs& pairs) {
  const long n = static_cast<long>(f.n_owned);
  // rows differ in length: contiguous shares of equal entries (domain/row_partition.hpp)
#pragma omp parallel
  for (auto [a, end] = thread_rows(pairs.list.offset, n, kFluidRowCost); a < end; ++a) {
    if (f.kind[a] != kFluid) continue;
    double rx = 0, ry = 0, rz = 0;
    for (std::uint32_t k = pairs.begin(a); k < pairs.end(a); ++k) {
      const std::uint32_t j = pairs.sphere[k];
      if (s.shepard[j] <= 0.0) continue;
      const double w = pairs.w[k] / s.shepard[j];
      rx += s.fmx[j] * w;
      ry += s.fmy[j] * w;
      rz += s.fmz[j] * w;
    }
    const double inv_rho = 1.0 / f.rho[a];
    f.ax[a] -= rx * inv_rho;
    f.ay[a] -= ry * inv_rho;
    f.az[a] -= rz * inv_rho;
  }
}

}  // namespace sphdem
