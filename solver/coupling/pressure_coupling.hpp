#pragma once
#include <cstdint>
#include <vector>

#include "coupling/fluid_sphere_pairs.hpp"
#include "dem/dem_particles.hpp"
#include "sph/fluid_particles.hpp"
#include "sph/pair_accumulator.hpp"

namespace sphdem {

// Variational pressure coupling (scene key coupling.pressure_coupling: variational).
// The fluid's internal energy U = sum_a m_a e(rho_a / eps_a), with the voidage of (2.50)
// eps_a = 1 - sum_j V_j W(r_aj, h_a), depends on the sphere positions; -dU/dx gives,
// for every fluid-sphere pair, a force and its exact opposite:
//   fluid a:   V_a P_a grad eps_a = -sum_j V_a P_a V_j grad_a W_aj   (V_a = m_a / rho_a)
//   sphere j:  +sum_a V_a P_a V_j grad_a W_aj                      (~ -V_j grad P)
// Together with the SPH pressure term carrying eps P (p_term, density_rate.cpp) the
// fluid obeys rho_sup Du/Dt = -eps grad P (model A) and the pair (continuity, pressure
// force) conserves energy where eps varies, which the interpolated form does not.
// Adds P_a grad eps_a / rho_a to (ax, ay, az) of the mobile fluid particles and sets
// the spheres' (gx, gy, gz) to their pressure force / V_j, so that the fluid force
// (2.68) V_j g_j + drag carries it. Wall particles push on the spheres (their pressure
// is part of U) but do not move. halo_source maps a halo sphere to its owner.
void couple_pressure_variationally(FluidParticles& f, DemParticles& s, const FluidSpherePairs& pairs,
                                   const std::vector<std::uint32_t>& halo_source, PairAccumulator& scratch);

}  // namespace sphdem
