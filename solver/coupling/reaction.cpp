#include "coupling/reaction.hpp"

#include "domain/row_partition.hpp"
#include "sph/pair_isa.hpp"

namespace sphdem {

namespace {

// sum_j fm_j W_aj / S_j over row a's spheres (S_j = 0: a sphere with no fluid, no share);
// in lanes (AVX-512 gathers) or one sphere at a time.
template <bool kLanes>
inline void reaction_rows(FluidParticles& f, const DemParticles& s, const FluidSpherePairs& pairs,
                          std::size_t lo, std::size_t hi) {
  const std::uint32_t* __restrict sphere = pairs.sphere.data();
  const double* __restrict w = pairs.drag_w().data();  // as the interpolation's S_j
  const double* __restrict shepard = s.shepard.data();
  const double* __restrict fmx = s.fmx.data();
  const double* __restrict fmy = s.fmy.data();
  const double* __restrict fmz = s.fmz.data();
  for (std::size_t a = lo; a < hi; ++a) {
    if (f.kind[a] != kFluid) continue;
    double rx = 0, ry = 0, rz = 0;
    const auto add = [&](std::uint32_t k) {
      const std::uint32_t j = sphere[k];
      const double S = shepard[j];
      const double share = S > 0.0 ? w[k] / S : 0.0;
      rx += fmx[j] * share;
      ry += fmy[j] * share;
      rz += fmz[j] * share;
    };
    if constexpr (kLanes) {
#pragma omp simd reduction(+ : rx, ry, rz)
      for (std::uint32_t k = pairs.begin(a); k < pairs.end(a); ++k) add(k);
    } else {
      for (std::uint32_t k = pairs.begin(a); k < pairs.end(a); ++k) add(k);
    }
    const double inv_rho = 1.0 / f.rho[a];
    f.ax[a] -= rx * inv_rho;
    f.ay[a] -= ry * inv_rho;
    f.az[a] -= rz * inv_rho;
  }
}

SPHDEM_TARGET_AVX512 void reaction_rows_avx512(FluidParticles& f, const DemParticles& s,
                                               const FluidSpherePairs& pairs, std::size_t lo,
                                               std::size_t hi) {
  reaction_rows<true>(f, s, pairs, lo, hi);
}

}  // namespace

void add_reaction_on_fluid(FluidParticles& f, const DemParticles& s, const FluidSpherePairs& pairs,
                           PairIsa isa) {
  const long n = static_cast<long>(f.n_owned);
  // rows differ in length: contiguous shares of equal entries (domain/row_partition.hpp)
#pragma omp parallel
  {
    const auto [lo, hi] = thread_rows(pairs.list.offset, n, kFluidRowCost);
    if (isa == PairIsa::kAvx512)
      reaction_rows_avx512(f, s, pairs, lo, hi);
    else
      reaction_rows<false>(f, s, pairs, lo, hi);
  }
}

}  // namespace sphdem
