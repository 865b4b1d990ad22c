#pragma once
// The drag exchange between the fluid and the spheres, semi-implicit on the fluid's side.
//
// The reaction (2.71) pulls fluid particle a toward the spheres' velocity at the rate
//   K_a = (1/rho_a) sum_j (g_j / S_j) W_aj,   g_j = c_j eps_j = d f_j / d u_f (2.68, 2.74)
// (coupling/reaction.hpp). Taken explicitly the fluid's slip overshoots once dt K_a
// passes 1; in a bed of fine grains, where the fluid is a small mass between heavy
// spheres, that is the shortest time scale of the run. Up to dt K_a = theta
// (kExplicitDragLimit) the corrector stays explicit; beyond it, backward Euler in the
// excess K'_a = K_a - theta/dt:
//   du_a = dt a_a / (1 + dt K'_a)
// which keeps the steady slip of any dt (du = 0 where a = 0: Darcy's law through a bed).
// The momentum the fluid did not take, D_a = m_a dt K'_a du_a, goes to the spheres as a
// drag impulse, in proportion to each sphere's share of K_a:
//   J_j = dt (g_j / S_j) sum_a W_aj phi_a,   phi_a = V_a du_a K'_a / K_a,  V_a = m_a / rho_a
// (rho_a as in K_a), so that sum_j J_j = sum_a D_a to round-off: the exchange keeps the
// momentum exact. In the limit of a light fluid the pair ends at one velocity, the
// sphere having given the fluid what it takes to follow.
#include <cstddef>
#include <vector>

#include "coupling/fluid_sphere_pairs.hpp"
#include "dem/dem_particles.hpp"
#include "domain/halo.hpp"
#include "sph/pair_accumulator.hpp"

namespace sphdem {

// dt K_a up to which the corrector stays explicit (the slip's explicit decay factor
// 1 - dt K_a stays >= 0.5: no overshoot for a tangent rate up to twice the secant c).
inline constexpr double kExplicitDragLimit = 0.5;

// dt K'_a of fluid particle a; > 0 where its corrector is implicit.
inline double implicit_drag_part(double dt, double drag_rate) {
  return dt * drag_rate - kExplicitDragLimit;
}

// The corrector's share of fluid particle a (volume V_a, drag rate K_a): where it is
// implicit, its acceleration divided by 1 + dt K'_a (what the fluid takes, in place) and
// phi_a = V_a du_a K'_a / K_a written, else phi_a = 0. Returns whether it was implicit.
inline bool take_drag_exchange(double dt, double drag_rate, double volume, double& ax, double& ay,
                               double& az, double* phi) {
  phi[0] = phi[1] = phi[2] = 0.0;
  const double excess = implicit_drag_part(dt, drag_rate);
  if (!(excess > 0.0)) return false;
  const double damp = 1.0 / (1.0 + excess);
  ax *= damp;
  ay *= damp;
  az *= damp;
  const double share = volume * excess / drag_rate;  // phi_a / (du_a / dt)
  phi[0] = share * ax;
  phi[1] = share * ay;
  phi[2] = share * az;
  return true;
}

// J_j into impulse (three per owned sphere) from phi (three per owned fluid particle,
// zero where explicit); halo images' sums go to their owners.
void drag_exchange_impulses(const DemParticles& s, const double* gain,
                            const FluidSpherePairs& pairs, const Halo& sphere_halo,
                            const double* phi, std::size_t n_fluid, double dt, PairAccumulator& acc,
                            std::vector<double>& impulse);

}  // namespace sphdem
