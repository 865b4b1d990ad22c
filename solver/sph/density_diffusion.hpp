#pragma once
// Density diffusion (delta-SPH: Molteni & Colagrossi 2009) for the superficial formulation:
// it diffuses the fluid's own density rho/eps, less that of the fluid at rest at the same
// height (Fourtakas et al. 2019, DualSPHysics's DDT), and adds to the continuity
// equation (2.53)
//   D_a = 2 delta h_a c0 eps_a sum_b psi_ab (-F_ab) V_b,
//   psi = rho/eps - rho_H(z),  V_b = m_b / rho_b,  F_ab = (F(r, h_a) + F(r, h_b)) / 2,
// with grad_a W_ab = F r_ab and rho_H the Tait density (2.58) of the hydrostatic pressure
// P_h = rho0 |g| (z_s - z). Form `hydrostatic`: psi_ab = psi_b - psi_a; its continuum limit
// is eps_a delta h_a c0 lap(psi). Form `renormalised` (Antuono et al. 2010, the delta-SPH
// of Marrone et al. 2011):
//   psi_ab = psi_b - psi_a - (G_a + G_b)/2 . (r_b - r_a),
// with G the renormalised gradient of psi (sph/diffusion_gradient.hpp), so a psi linear in
// space gets no D at all, one-sided at a wall too, and the term is of higher order
// (h^2 lap lap psi). Why it matters: under a suspension the fluid carries the spheres'
// weight (the pressure gradient of the mixture, not of water), so psi grows linearly with
// depth inside it and its slope jumps at the suspension's top and at the floor; there
// lap(psi) is a sheet of sources and sinks of fluid volume, delta h (1 - eps) (rho_p -
// rho_f) g / (rho c0) per area, which drives a flow down through the suspension and speeds
// its settling (validation/README.md, session 38). Both forms: acoustic noise at the
// particle scale is damped, a fluid at rest (psi = 0) is left alone, no shear viscosity is
// added (unlike Monaghan's term, 2.56). Mobile fluid pairs only: a wall particle has V = 0
// and gets no D.
#include <cmath>

#include "sph/equation_of_state.hpp"
#include "sph/fluid_particles.hpp"

namespace sphdem {

struct DensityDiffusion {
  double delta = 0.0;  // fluid.density_diffusion (0: off)
  double c0 = 0.0;     // reference sound speed (2.63)
  TaitEquationOfState eos;
  double gz = 0.0;           // gravity along z (negative; 0: no hydrostatic reference)
  double surface = 0.0;      // free surface z_s of the fluid at rest
  bool renormalised = true;  // fluid.density_diffusion_form
  bool on() const { return delta > 0.0; }
  // rho_H(z): the intrinsic density of the fluid at rest at height z.
  double hydrostatic_density(double z) const {
    return eos.density(eos.rho0 * gz * (z - surface), 1.0);
  }
};

// psi and V of the owned particles (fluid: rho/eps - rho_H and m/rho; wall: 0 and 0); the
// `renormalised` form's G comes from compute_diffusion_gradient after the halo fill of these
// two (the `hydrostatic` form reads no G); the density pass reads the halo copies' after a
// halo fill.
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
