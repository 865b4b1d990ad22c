#pragma once
#include "domain/neighbour_list.hpp"
#include "sph/fluid_particles.hpp"
#include "sph/pair_accumulator.hpp"
#include "sph/pair_isa.hpp"

namespace sphdem {

struct MomentumParams {
  double viscosity = 8.9e-4;      // mu (Pa s), Morris et al. (1997) laminar term
  double alpha_artificial = 0.0;  // Monaghan Pi_ab (2.56) on approaching pairs only
  double cfl = 0.25;              // dt_a = cfl h_a / v_sig,a (3.5)
};

// theta_a: pressure + viscous acceleration of each owned mobile fluid particle (2.55/2.70
// without gravity and coupling), and the per-particle CFL limit dt_limit.
//   theta_a = - sum_b m_b [ (P_a/(Omega_a rho_a^2) + Pi_ab) grad W(h_a)
//                         + (P_b/(Omega_b rho_b^2) + Pi_ab) grad W(h_b) ]
//             + sum_b m_b (mu_a + mu_b) r_ab . gradW_ab / (rho_a rho_b (r^2 + 0.01 h^2)) u_ab
// The physical viscosity is Morris' term, which carries mu directly (physics.md §1
// allows it); Monaghan's term with alpha_artificial acts only on approaching pairs.
// Over a half neighbour list: each owned pair is evaluated once and written to both
// particles with opposite signs, so the pair forces cancel exactly.
void compute_fluid_acceleration(FluidParticles& f, const NeighbourList& half,
                                const MomentumParams& p, PairAccumulator& scratch,
                                PairIsa isa = best_pair_isa());

}  // namespace sphdem
