#pragma once
// A bed on the distributor of a column periodic in z (flow.distributor): what the drag
// reads near the plate as if the bed went on below it. Across the plate lies the
// column's clear top (the plenum, seen through the periodic face); a kernel straddling
// the plate would mix it into the voidage (2.50) and the fluid velocity (2.69) the
// bottom spheres' drag reads, and lower that drag (measured in bench/TRADEOFF.md,
// session 34). So, in the drag's weights only (the
// voidage eps_drag, the interpolation at the spheres, the reaction, the drag exchange):
//   W_aj -> W(r_a - r_j) + W(r_a - r'_j),  r'_j the mirror of r_j in the plate,
// for fluid a and sphere j on the same side of it, and 0 for a pair across it. The same
// weight serves both ends of a pair, so the drag's momentum still balances. The fluid's
// own voidage (its equation of state and the pressure coupling) keeps the plain kernel:
// a voidage that jumps at the plate would kick each fluid particle crossing it.
#include "coupling/fluid_sphere_pairs.hpp"
#include "dem/dem_particles.hpp"
#include "sph/fluid_particles.hpp"

namespace sphdem {

struct DistributorPlane {
  double z = 0.0;       // the plate (the box's bottom face)
  double period = 0.0;  // the column's length Lz; 0: no distributor
  bool on() const { return period > 0.0; }
};

// Rewrites pairs.w_drag (kept apart: FluidSpherePairs::keep_drag_weights) and the rows'
// drag sums for the fluid rows within the drag's support of a plate image, after
// FluidSpherePairs::evaluate.
void continue_bed_below_distributor(FluidSpherePairs& pairs, const FluidParticles& f,
                                    const DemParticles& s, const DistributorPlane& plane);

}  // namespace sphdem
