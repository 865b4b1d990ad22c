#include "coupling/interpolation.hpp"

#include <omp.h>

namespace sphdem {

void interpolate_fluid_at_spheres(DemParticles& s, const FluidParticles& f,
                                  const FluidSpherePairs& pairs,
                                  const std::vector<std::uint32_t>& halo_source,
                                  PairAccumulator& acc) {
  const std::size_t ns = s.n_owned;
  const long nf = static_cast<long>(f.n_owned);
  enum { kS, kEps, kUx, kUy, kUz, kGx, kGy, kGz, kDs, kDw, kFields };
  acc.reset(ns, kFields);
  const std::vector<double>& weights = pairs.drag_w();  // the drag's kernel
#pragma omp parallel
  {
    const int t = omp_get_thread_num();
    // Interleaved chunks (rows differ in length); per-thread sums stay deterministic.
#pragma omp for schedule(static, 64)
    for (long b = 0; b < nf; ++b) {
      if (f.kind[b] != kFluid) continue;
      const double mb = f.mass[b], vb = mb / f.rho[b];
      for (std::uint32_t k = pairs.begin(b); k < pairs.end(b); ++k) {
        const double w = weights[k];
        const std::uint32_t j = pairs.sphere[k];
        const std::uint32_t owner = j < ns ? j : halo_source[j - ns];
        double* r = acc.row(t, owner);
        const double vw = vb * w, mw = mb * w;
        r[kS] += vw;
        r[kEps] += vw * f.eps_drag[b];
        r[kUx] += vw * f.vx[b];
        r[kUy] += vw * f.vy[b];
        r[kUz] += vw * f.vz[b];
        r[kGx] += mw * f.thx[b];
        r[kGy] += mw * f.thy[b];
        r[kGz] += mw * f.thz[b];
        if (f.d_sauter[b] > 0.0) {  // Sauter mean where there are solids, Shepard-averaged
          r[kDs] += vw * f.d_sauter[b];
          r[kDw] += vw;
        }
      }
    }
  }
#pragma omp parallel for schedule(static)
  for (long j = 0; j < static_cast<long>(ns); ++j) {
    const double S = acc.sum(j, kS);
    s.shepard[j] = S;
    if (S > 0.0) {
      const double inv = 1.0 / S;
      s.eps[j] = acc.sum(j, kEps) * inv;
      s.ufx[j] = acc.sum(j, kUx) * inv;
      s.ufy[j] = acc.sum(j, kUy) * inv;
      s.ufz[j] = acc.sum(j, kUz) * inv;
      s.gx[j] = acc.sum(j, kGx) * inv;
      s.gy[j] = acc.sum(j, kGy) * inv;
      s.gz[j] = acc.sum(j, kGz) * inv;
      const double dw = acc.sum(j, kDw);
      s.d_sauter[j] = dw > 0.0 ? acc.sum(j, kDs) / dw : 2.0 * s.radius[j];
    } else {
      s.d_sauter[j] = 2.0 * s.radius[j];
      s.eps[j] = 1.0;
      s.ufx[j] = s.ufy[j] = s.ufz[j] = s.gx[j] = s.gy[j] = s.gz[j] = 0.0;
    }
  }
}

}  // namespace sphdem
