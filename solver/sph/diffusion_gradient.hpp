#pragma once
// The renormalised gradient of the density diffusion's psi (sph/density_diffusion.hpp,
// form `renormalised`; Randles & Libersky 1996, as Antuono et al. 2010 use it):
//   G_a = L_a sum_b V_b (psi_b - psi_a) grad_a W_ab,
//   L_a = (sum_b V_b (r_b - r_a) (x) grad_a W_ab)^-1,
// over the mobile fluid (V = m/rho; a wall particle has V = 0), with the pair's symmetric
// F_ab = (F(r, h_a) + F(r, h_b)) / 2 as the diffusion's. L makes G exact for a psi linear
// in space wherever the neighbours span the three directions, at a wall (one-sided) too.
// Where they do not (det(L^-1) under kMinMomentDeterminant: a particle nearly alone, the
// edge of a splash) G = 0 and the diffusion there is the `hydrostatic` form's. Owned fluid
// rows are set (walls get 0); psi and V must be current on owned and halo particles, and
// the density pass reads G's halo copies after a halo fill.
#include "domain/neighbour_list.hpp"
#include "sph/fluid_particles.hpp"
#include "sph/pair_accumulator.hpp"
#include "sph/pair_isa.hpp"

namespace sphdem {

// det of the moment matrix, which is the identity for a full kernel on a lattice and
// about 1/8 with half of it (a free surface, a wall)
inline constexpr double kMinMomentDeterminant = 0.02;

void compute_diffusion_gradient(FluidParticles& f, const NeighbourList& half,
                                PairAccumulator& scratch, PairIsa isa = best_pair_isa());

}  // namespace sphdem
