#pragma once
#include "domain/neighbour_list.hpp"
#include "sph/density_diffusion.hpp"
#include "sph/fluid_particles.hpp"
#include "sph/hydrostatic_pressure.hpp"
#include "sph/pair_accumulator.hpp"
#include "sph/pair_isa.hpp"

namespace sphdem {

// For every owned SPH particle a (fluid and wall), over its neighbours b (owned + halo),
// from a half neighbour list (each owned pair once, added to both; the self term added here):
//   Omega_a = 1 - (dh/drho) sum_b m_b dW_ab(h_a)/dh,  dh/drho = -h/(3 rho)      (2.54)
//   drho_a/dt = (1/Omega_a) sum_b m_b u_ab . grad_a W_ab(h_a)                      (2.53)
// Also stores p_term = P/(Omega rho^2) for the momentum pass (P must be current), or
// eps P/(Omega rho^2) with voidage_weighted_pressure (the variational pressure coupling,
// coupling/pressure_coupling.hpp: eps P = rho^2 de/drho of the superficial density).
// Omega is kept within [0.5, 2] (it can drift near the free surface, where the kernel
// sum is truncated); returns how many particles hit that bound.
// With a hydrostatic pressure ph, the pair term carries P - ph(z) instead of P (the
// hydrostatic split of the variational coupling; ph's own force is added analytically).
// With dd.on(), drho_a/dt also gets the density diffusion D_a of sph/density_diffusion.hpp
// (diffusion_psi, diffusion_volume and the gradient diffusion_g* must be current on owned
// and halo particles).
std::size_t compute_density_rate(FluidParticles& f, const NeighbourList& half,
                                 PairAccumulator& scratch, bool voidage_weighted_pressure = false,
                                 const HydrostaticPressure& ph = {},
                                 const DensityDiffusion& dd = {}, PairIsa isa = best_pair_isa());

}  // namespace sphdem
