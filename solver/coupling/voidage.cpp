#include "coupling/voidage.hpp"

#include <cmath>

#include "domain/row_partition.hpp"

namespace sphdem {

namespace {

// Row a's sums sum_j V_j W_aj and sum_j V_j W_aj / d_j, without the big spheres' species
// when they are smoothed apart (3.8); in lanes (AVX-512 gathers) when there is no such
// species, else one sphere at a time.
struct SolidSums {
  double solid = 0.0, solid_over_d = 0.0;
};

template <bool kLanes>
inline SolidSums solid_sums(const DemParticles& s, const FluidSpherePairs& pairs,
                            const std::vector<double>& weights, std::size_t a,
                            const BigSpheresSmoothedApart* big) {
  double solid = 0.0, solid_over_d = 0.0;
  if constexpr (kLanes) {
    const std::uint32_t* __restrict sphere = pairs.sphere.data();
    const double* __restrict w = weights.data();
    const double* __restrict radius = s.radius.data();
#pragma omp simd reduction(+ : solid, solid_over_d)
    for (std::uint32_t k = pairs.begin(a); k < pairs.end(a); ++k) {
      const double r = radius[sphere[k]];
      const double vw = 4.0 / 3.0 * M_PI * r * r * r * w[k];  // V_j W_aj
      solid += vw;
      solid_over_d += vw / (2.0 * r);
    }
  } else {
    for (std::uint32_t k = pairs.begin(a); k < pairs.end(a); ++k) {
      const std::uint32_t j = pairs.sphere[k];
      if (big && big->is_big[s.species[j]]) continue;  // smoothed apart (3.8)
      const double vw = s.volume(j) * weights[k];
      solid += vw;
      solid_over_d += vw / (2.0 * s.radius[j]);
    }
  }
  return {solid, solid_over_d};
}

// 1 - the solid fraction, clamped to the floor (counted in clamped).
inline double floored_voidage(double solid, double eps_floor, std::size_t& clamped) {
  const double eps = 1.0 - solid;
  if (eps >= eps_floor) return eps;
  ++clamped;
  return eps_floor;
}

// eps_a (2.50), clamped to the floor, and the Sauter mean (2.80) for rows [lo, hi); with
// the drag's kernel apart, eps_drag_a and the Sauter mean from that kernel, else copies.
template <bool kLanes>
inline std::size_t voidage_rows(FluidParticles& f, const DemParticles& s,
                                const FluidSpherePairs& pairs, double eps_floor,
                                const BigSpheresSmoothedApart* big, std::size_t lo,
                                std::size_t hi) {
  std::size_t clamped = 0;
  const bool apart = pairs.drag_apart();
  for (std::size_t a = lo; a < hi; ++a) {
    auto [solid, solid_over_d] = solid_sums<kLanes>(s, pairs, pairs.w, a, big);
    if (big) {  // (3.10)
      solid += big->solid[a];
      solid_over_d += big->solid_over_d[a];
    }
    f.eps[a] = floored_voidage(solid, eps_floor, clamped);
    if (apart) {
      auto [drag_solid, drag_solid_over_d] = solid_sums<kLanes>(s, pairs, pairs.w_drag, a, big);
      if (big) {
        drag_solid += big->solid[a];
        drag_solid_over_d += big->solid_over_d[a];
      }
      solid = drag_solid;
      solid_over_d = drag_solid_over_d;
      f.eps_drag[a] = floored_voidage(solid, eps_floor, clamped);
    } else {
      f.eps_drag[a] = f.eps[a];
    }
    // Sauter mean (sum_i x_i / d_i)^-1 with the kernel-weighted volume fractions x_i (2.80)
    f.d_sauter[a] = solid_over_d > 0.0 ? solid / solid_over_d : 0.0;
  }
  return clamped;
}

SPHDEM_TARGET_AVX512 std::size_t voidage_rows_avx512(FluidParticles& f, const DemParticles& s,
                                                     const FluidSpherePairs& pairs,
                                                     double eps_floor, std::size_t lo,
                                                     std::size_t hi) {
  return voidage_rows<true>(f, s, pairs, eps_floor, nullptr, lo, hi);
}

}  // namespace

std::size_t compute_fluid_voidage(FluidParticles& f, const DemParticles& s,
                                  const FluidSpherePairs& pairs, double eps_floor,
                                  const BigSpheresSmoothedApart* big, PairIsa isa) {
  const long n = static_cast<long>(f.n_owned);
  std::size_t clamped = 0;
  // rows differ in length: contiguous shares of equal entries (domain/row_partition.hpp)
#pragma omp parallel reduction(+ : clamped)
  {
    const auto [lo, hi] = thread_rows(pairs.list.offset, n, kFluidRowCost);
    if (isa == PairIsa::kAvx512 && !big)
      clamped += voidage_rows_avx512(f, s, pairs, eps_floor, lo, hi);
    else
      clamped += voidage_rows<false>(f, s, pairs, eps_floor, big, lo, hi);
  }
  return clamped;
}

}  // namespace sphdem
