#pragma once
#include <cstdint>
#include <vector>

#include "coupling/fluid_sphere_pairs.hpp"
#include "dem/dem_particles.hpp"
#include "domain/halo.hpp"
#include "sph/fluid_particles.hpp"
#include "sph/hydrostatic_pressure.hpp"
#include "sph/pair_accumulator.hpp"
#include "sph/pair_isa.hpp"

namespace sphdem {

// Fluid fields at every owned sphere j, from the mobile fluid particles b, Shepard-
// normalised with S_j = sum_b (m_b/rho_b) W_jb(h_b)                      (2.72),
// W the drag's kernel (FluidSpherePairs::drag_w, eps_drag; the spheres' kernel unless
// coupling.drag_kernel_scale sets it apart):
//   (-grad P + div tau)_j = sum_b m_b theta_b W_jb(h_b) / S_j          (2.69)
//   u_f,j = sum_b (m_b/rho_b) u_b W_jb / S_j,  eps_j likewise          (for 2.74)
//   and the local Sauter mean diameter (2.80) for the polydisperse drag
// With pairs.upstream (coupling.drag_upstream: gravity's direction), u_f,j and eps_j are the
// same sums over the fluid on that side of the sphere only, normalised by their own S_j:
// the half the fluid passing a settling or fluidised sphere comes from, so the clear liquid
// above a suspension does not raise the voidage its top spheres read. Only where that half
// holds at least a quarter of S_j (not at the floor) and the whole kernel's eps_j is under
// kLoneSphereVoidage (a lone sphere reads the whole kernel). S_j itself, and so the
// reaction (2.71), keeps the whole kernel.
// Scattered from the owned fluid particles' pairs: a pair with a halo sphere adds to the
// image's row, which the halo adds to its owner's (Halo::add_to_sources): the
// same sum over periodic images. A sphere with no fluid neighbour (above the free
// surface) gets S_j = 0, eps_j = 1 and no fluid force.
// With `pressure` (the variational coupling, coupling/pressure_coupling.hpp) the same pass
// over the pairs carries that coupling's pairs instead of (2.69): the spheres' g becomes
// their pressure force / V_j and the fluid gets its share; returns the walls' vertical
// push on the spheres (0 without). One pass reads each pair once for both.
double interpolate_fluid_at_spheres(DemParticles& s, FluidParticles& f,
                                    const FluidSpherePairs& pairs, const Halo& halo,
                                    PairAccumulator& scratch,
                                    const HydrostaticPressure* pressure = nullptr,
                                    PairIsa isa = best_pair_isa());

}  // namespace sphdem
