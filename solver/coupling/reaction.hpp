#pragma once
#include "coupling/fluid_sphere_pairs.hpp"
#include "dem/dem_particles.hpp"
#include "sph/fluid_particles.hpp"
#include "sph/pair_accumulator.hpp"
#include "sph/pair_isa.hpp"

namespace sphdem {

// Reaction of the spheres on the fluid (2.71), as an acceleration added to (ax,ay,az)
// of every owned mobile fluid particle a:
//   f_a / m_a = -(1/rho_a) sum_j (fm_j / S_j) W_aj(h_a)
// fm_j is the fluid force the sphere received (averaged over the SPH step) and S_j
// the Shepard sum (2.72) over the same pairs, so sum_a f_a + sum_j fm_j = 0 to
// round-off. Halo spheres must carry fm and shepard. fm_j / S_j is staged in scratch.
// With the spheres' drag gains g_j = c_j eps_j (owned and halo; none: zeros), the same
// pass writes each fluid particle's drag rate, how fast the reaction pulls its velocity
// toward the spheres' (coupling/drag_exchange.hpp):
//   K_a = (1/rho_a) sum_j (g_j / S_j) W_aj(h_a)
void add_reaction_on_fluid(FluidParticles& f, const DemParticles& s, const FluidSpherePairs& pairs,
                           PairAccumulator& scratch, const double* gain = nullptr,
                           PairIsa isa = best_pair_isa());

}  // namespace sphdem
