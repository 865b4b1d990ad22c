#include "coupling/double_smoothing.hpp"

#include <cmath>

#include "sph/kernel.hpp"

namespace sphdem {

void smooth_big_spheres(const FluidParticles& f, const DemParticles& s, const CellList& big_cells,
                        const std::vector<std::uint8_t>& is_big, double h_over_d,
                        BigSphereFraction& out) {
  const long n = static_cast<long>(f.n_owned);
  out.phi.assign(f.size(), 0.0);
  out.phi_over_d.assign(f.size(), 0.0);
  const double rc = big_cells.max_cutoff();
#pragma omp parallel for schedule(static)
  for (long b = 0; b < n; ++b) {
    double phi = 0.0, phi_over_d = 0.0;
    big_cells.for_each_neighbour(
        f.x[b], f.y[b], f.z[b], rc * rc, [&](std::uint32_t j, double, double, double, double r2) {
          if (!is_big[s.species[j]]) return;
          const double d = 2.0 * s.radius[j];
          const double vw = s.volume(j) * kernel::w(r2, h_over_d * d);  // (3.9)
          phi += vw;
          phi_over_d += vw / d;
        });
    out.phi[b] = phi;
    out.phi_over_d[b] = phi_over_d;
  }
}

void resmooth_with_fluid_kernel(const FluidParticles& f, const CellList& fluid_cells,
                                const BigSphereFraction& big, std::vector<double>& solid,
                                std::vector<double>& solid_over_d) {
  const long n = static_cast<long>(f.n_owned);
  solid.assign(f.n_owned, 0.0);
  solid_over_d.assign(f.n_owned, 0.0);
#pragma omp parallel for schedule(static)
  for (long a = 0; a < n; ++a) {
    const double inv_h = f.inv_h[a], rc = kernel::kSupport * f.h[a];
    double num = 0.0, num_over_d = 0.0, shepard = 0.0;
    fluid_cells.for_each_neighbour(
        f.x[a], f.y[a], f.z[a], rc * rc, [&](std::uint32_t b, double, double, double, double r2) {
          const double vw = f.mass[b] / f.rho[b] * kernel::w_q(std::sqrt(r2) * inv_h, inv_h);
          num += vw * big.phi[b];  // (3.10)
          num_over_d += vw * big.phi_over_d[b];
          shepard += vw;
        });
    solid[a] = shepard > 0.0 ? num / shepard : 0.0;
    solid_over_d[a] = shepard > 0.0 ? num_over_d / shepard : 0.0;
  }
}

}  // namespace sphdem
