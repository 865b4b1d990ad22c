#pragma once
#include "coupling/fluid_sphere_pairs.hpp"
#include "dem/dem_particles.hpp"
#include "sph/fluid_particles.hpp"

namespace sphdem {

// Voidage at every owned SPH particle a (fluid and wall) from its sphere pairs:
//   eps_a = 1 - sum_j V_j W(r_a - r_j, h_a)   (2.50),
// and the local Sauter mean diameter of the solids, sum_j V_j W / sum_j (V_j/d_j) W (2.80).
// eps is clamped to eps_floor (default 0.3): the kernel estimate can undershoot in a
// dense sediment; returns how many particles were clamped (logged per step).
std::size_t compute_fluid_voidage(FluidParticles& f, const DemParticles& s, const FluidSpherePairs& pairs,
                                  double eps_floor);

}  // namespace sphdem
