#pragma once
// The contact stiffness a scene needs (contact.stiffness: auto, the default): the softest
// linear spring whose largest overlap stays under contact.max_overlap (a fraction of the
// diameter) both
//  - at impact: a sphere of mass m reaching the wall (or the sediment) at the scene's
//    largest speed v hits with the largest overlap (2.47)
//      delta_max = v / omega0 exp(-eta/omega asin(omega/omega0)),  omega0 = sqrt(k/m),
//    so k = m (c v / (f d))^2 with c the damping's factor (1 without a restitution);
//    v is the drag law's terminal speed in clear fluid (free fall from the top without
//    fluid) or a group's initial speed, whichever is larger;
//  - at rest under the sediment: a bottom sphere carries on average the buoyant weight
//    of the solid above its d^2 of floor, p d^2 with p = sum (rho_p - rho_f) g V_solid / A,
//    but the contact forces of a random packing spread with an exponential tail (force
//    chains), so the largest is a few times the mean: k = C p d / f with C = 4 (the
//    default scene's sediment at rest: largest overlap 2.8 p d^2 / k; bench/TRADEOFF.md).
// Each species counts with its largest sphere (the largest m v^2 and p d). The DEM step
// then follows from t_c (scene/time_step.hpp). A softer spring means fewer DEM sub-steps:
// the reason this is the default.
#include <cmath>
#include <string>

#include "scene/scene.hpp"

namespace sphdem {

struct StiffnessChoice {
  double k = 0.0;               // N/m, rounded up to two significant digits
  double impact_speed = 0.0;    // m/s, the largest over the species and groups
  double impact_overlap = 0.0;  // expected largest overlap / d at impact, with k
  double static_overlap = 0.0;  // expected overlap / d under the sediment's weight, with k
  std::string reason;           // what set k, for `sphdem check`
};

// The choice for a resolved scene (fluid, drag law, species and groups set); the scene's
// own contact.normal.k is not read.
StiffnessChoice choose_contact_stiffness(const Scene& sc);

// The expected overlaps / d of a scene's own spring k (contact.normal.k > 0): the choice's,
// scaled as k^-1/2 at impact and k^-1 under the sediment's weight.
struct ExpectedOverlaps {
  double impact = 0.0, at_rest = 0.0;
  double worst() const { return impact > at_rest ? impact : at_rest; }
};
inline ExpectedOverlaps expected_overlaps(const Scene& sc) {
  const StiffnessChoice c = choose_contact_stiffness(sc);
  const double k = sc.contact.normal.k;
  return {c.impact_overlap * std::sqrt(c.k / k), c.static_overlap * c.k / k};
}

}  // namespace sphdem
