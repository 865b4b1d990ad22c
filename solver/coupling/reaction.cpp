#include "coupling/reaction.hpp"

#include "domain/row_partition.hpp"
#include "sph/pair_isa.hpp"

namespace sphdem {

namespace {

// sum_j W_aj (fm_j / S_j) and sum_j W_aj (g_j / S_j) over row a's spheres, with the four
// values staged per sphere side by side; in lanes (AVX-512 gathers) or one sphere at a time.
template <bool kLanes>
inline void reaction_rows(FluidParticles& f, const FluidSpherePairs& pairs, const double* share,
                          std::size_t lo, std::size_t hi) {
  const std::uint32_t* __restrict sphere = pairs.sphere.data();
  const double* __restrict w = pairs.drag_w().data();  // as the interpolation's S_j
  const double* __restrict fm_over_s = share;
  for (std::size_t a = lo; a < hi; ++a) {
    if (f.kind[a] != kFluid) {
      f.drag_rate[a] = 0.0;
      continue;
    }
    double rx = 0, ry = 0, rz = 0, k_sum = 0;
    const auto add = [&](std::uint32_t k) {
      const double* q = fm_over_s + 4 * sphere[k];
      rx += w[k] * q[0];
      ry += w[k] * q[1];
      rz += w[k] * q[2];
      k_sum += w[k] * q[3];
    };
    if constexpr (kLanes) {
#pragma omp simd reduction(+ : rx, ry, rz, k_sum)
      for (std::uint32_t k = pairs.begin(a); k < pairs.end(a); ++k) add(k);
    } else {
      for (std::uint32_t k = pairs.begin(a); k < pairs.end(a); ++k) add(k);
    }
    const double inv_rho = 1.0 / f.rho[a];
    f.ax[a] -= rx * inv_rho;
    f.ay[a] -= ry * inv_rho;
    f.az[a] -= rz * inv_rho;
    f.drag_rate[a] = k_sum * inv_rho;
  }
}

SPHDEM_TARGET_AVX512 void reaction_rows_avx512(FluidParticles& f, const FluidSpherePairs& pairs,
                                               const double* share, std::size_t lo,
                                               std::size_t hi) {
  reaction_rows<true>(f, pairs, share, lo, hi);
}

}  // namespace

void add_reaction_on_fluid(FluidParticles& f, const DemParticles& s, const FluidSpherePairs& pairs,
                           PairAccumulator& scratch, const double* gain, PairIsa isa) {
  const long n = static_cast<long>(f.n_owned), ns = static_cast<long>(s.size());
  double* share = scratch.staged(4 * s.size());
  // fm_j / S_j and g_j / S_j for every sphere, owned and halo (S_j = 0: a sphere with no
  // fluid, no share)
#pragma omp parallel for schedule(static)
  for (long j = 0; j < ns; ++j) {
    const double S = s.shepard[j], inv = S > 0.0 ? 1.0 / S : 0.0;
    share[4 * j] = s.fmx[j] * inv;
    share[4 * j + 1] = s.fmy[j] * inv;
    share[4 * j + 2] = s.fmz[j] * inv;
    share[4 * j + 3] = gain ? gain[j] * inv : 0.0;
  }
  // rows differ in length: contiguous shares of equal entries (domain/row_partition.hpp)
#pragma omp parallel
  {
    const auto [lo, hi] = thread_rows(pairs.list.offset, n, kFluidRowCost);
    if (isa == PairIsa::kAvx512)
      reaction_rows_avx512(f, pairs, share, lo, hi);
    else
      reaction_rows<false>(f, pairs, share, lo, hi);
  }
}

}  // namespace sphdem
