#include "coupling/voidage.hpp"

namespace sphdem {

std::size_t compute_fluid_voidage(FluidParticles& f, const DemParticles& s, const FluidSpherePairs& pairs,
                                  double eps_floor) {
  const long n = static_cast<long>(f.n_owned);
  std::size_t clamped = 0;
#pragma omp parallel for schedule(static) reduction(+ : clamped)
  for (long a = 0; a < n; ++a) {
    double solid = 0.0;
    for (std::uint32_t k = pairs.list.begin(a); k < pairs.list.end(a); ++k)
      solid += s.volume(pairs.list.neighbour[k]) * pairs.w[k];
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
