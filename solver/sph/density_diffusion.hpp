#pragma once
// Density diffusion (delta-SPH: Molteni & Colagrossi 2009, with the hydrostatic correction
// of Fourtakas et al. 2019, DualSPHysics's DDT) for the superficial formulation: it diffuses
// the fluid's own density rho/eps, less that of the fluid at rest at the same height, and
// adds to the continuity equation (2.53)
//   D_a = 2 delta h_a c0 eps_a sum_b (psi_b - psi_a) (-F_ab) V_b,
//   psi = rho/eps - rho_H(z),  V_b = m_b / rho_b,  F_ab = (F(r, h_a) + F(r, h_b)) / 2,
// with grad_a W_ab = F r_ab and rho_H the Tait density (2.58) of the hydrostatic pressure
// P_h = rho0 |g| (z_s - z). Its continuum limit is eps_a delta h_a c0 lap(psi): acoustic
// noise in the density is damped at the diffusivity delta h c0, a fluid at rest (psi = 0)
// is left alone, and no shear viscosity is added (unlike Monaghan's term, 2.56). Mobile
// fluid pairs only: a wall particle has V = 0 and gets no D.
#include <cmath>

#include "sph/equation_of_state.hpp"
#include "sph/fluid_particles.hpp"

namespace sphdem {

struct DensityDiffusion {
  double delta = 0.0;  // fluid.density_diffusion (0: off)
  double c0 = 0.0;     // reference sound speed (2.63)
  TaitEquationOfState eos;
  double gz = 0.0;       // gravity along z (negative; 0: no hydrostatic reference)
  double surface = 0.0;  // free surface z_s of the fluid at rest
  bool on() const { return delta > 0.0; }
  // rho_H(z): the intrinsic density of the fluid at rest at height z.
  double hydrostatic_density(double z) const {
    return eos.density(eos.rho0 * gz * (z - surface), 1.0);
  }
};

// psi and V of the owned particles (fluid: rho/eps - rho_H and m/rho; wall: 0 and 0); the
// density pass reads the halo copies' after a halo fill.
inline void prepare_density_diffusion(FluidParticles& f, const DensityDiffusion& dd) {
  const long n = static_cast<long>(f.n_owned);
#pragma omp parallel for schedule(static)
  for (long a = 0; a < n; ++a) {
    const bool fluid = f.kind[a] == kFluid;
    f.diffusion_psi[a] = fluid ? f.rho[a] / f.eps[a] - dd.hydrostatic_density(f.z[a]) : 0.0;
    f.diffusion_volume[a] = fluid ? f.mass[a] / f.rho[a] : 0.0;
  }
}

}  // namespace sphdem
