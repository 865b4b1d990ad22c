#pragma once
#include <cstdint>
#include <vector>

#include "coupling/fluid_sphere_pairs.hpp"
#include "dem/dem_particles.hpp"
#include "domain/halo.hpp"
#include "sph/fluid_particles.hpp"
#include "sph/hydrostatic_pressure.hpp"
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
// is part of U) but do not move. A halo sphere's share goes to its owner (halo).
// With a hydrostatic pressure ph (scene key coupling.hydrostatic_split) the forces are
// those of U + sum_a m_a P_h(z_a)/rho'_a + sum_j V_j P_h(z_j) (rho' = rho/eps, intrinsic),
// which differs from U by the constant integral of P_h over the box: the pairs carry
// P - P_h, the fluid gets -grad P_h / rho'_a and the spheres rho0 |g| V_j, analytically.
// The kernel sums' errors (partition of unity, zeroth-order gradient) then multiply
// P - P_h, not the absolute pressure: in a packed bed with disordered fluid particles
// the base pressure keeps no static offset (reduced sand column: 0.013 rho g H at rest against
// 0.36). Returns the vertical force the wall particles' pairs put on the spheres (N): a load path
// to the wall that the fluid particles do not see (analysis/pore_pressure.hpp).
// The pairs are summed in the interpolation's pass (coupling/interpolation.hpp), which
// sets the spheres' other fluid fields too.
double couple_pressure_variationally(FluidParticles& f, DemParticles& s,
                                     const FluidSpherePairs& pairs, const Halo& halo,
                                     PairAccumulator& scratch, const HydrostaticPressure& ph = {});

}  // namespace sphdem
