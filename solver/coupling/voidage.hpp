#pragma once
#include <cstdint>
#include <vector>

#include "coupling/fluid_sphere_pairs.hpp"
#include "dem/dem_particles.hpp"
#include "sph/fluid_particles.hpp"

namespace sphdem {

// The big spheres' part of the voidage when it is double smoothed (double_smoothing.hpp):
// their species are skipped in the sum over pairs and their re-smoothed solid fraction
// added instead (3.8-3.10).
struct BigSpheresSmoothedApart {
  const std::vector<std::uint8_t>& is_big;  // per species
  const std::vector<double>& solid;         // per owned SPH particle
  const std::vector<double>& solid_over_d;
};

// coupling.drag_voidage_upstream (gravity along -z): the voidage the drag reads at a mobile
// fluid particle a from the spheres at or below it,
//   eps_drag,a = 1 - 2 sum_{z_j <= z_a} V_j W_aj        (a sphere level with a counted half),
// the lower half of (2.50) doubled, which equals the whole kernel's in a uniform suspension;
// under a suspension's top it reads the suspension, not the clear liquid above it, so the
// top spheres, which read these particles on their own upstream side (interpolation.hpp), are
// not driven into a dense skin (validation/README.md, sessions 44-45). The whole kernel where
// a's support reaches the floor (the box's bottom wall, or the distributor plate and its
// periodic images: no sphere lies below them), where a is among the spheres no more than a
// lone sphere is (eps >= kLoneSphereVoidage), and with the big spheres smoothed apart.
// Opt-in (a suspension settling onto the floor): the lower face of a falling block or cloud
// reads the clear liquid under it through the same half.
struct VoidageUpstream {
  bool on = false;
  double floor_z = 0.0;   // the floor's height (the box's bottom face)
  double period = 0.0;    // a column periodic in z: its length (the plate's images); else 0
  bool has_floor = true;  // false: periodic in z without a plate
  // a's height above the nearest floor (infinite without one)
  double above_floor(double z) const;
};

// Voidage at every owned SPH particle a (fluid and wall) from its sphere pairs:
//   eps_a = 1 - sum_j V_j W(r_a - r_j, h_a)   (2.50),
// and the local Sauter mean diameter of the solids, sum_j V_j W / sum_j (V_j/d_j) W (2.80).
// eps is clamped to eps_floor (default 0.3): the kernel estimate can undershoot in a
// dense sediment; returns how many particles were clamped (logged per step). The voidage
// the drag reads, eps_drag, is the same sum with the drag's kernel when pairs.drag_apart()
// (its clamps counted too), else eps; the Sauter mean is the drag's. The sums over all
// species come from the pairs' evaluation (FluidSpherePairs::solid); with big spheres
// smoothed apart the pairs are summed here without them. With upstream.on, eps_drag as
// VoidageUpstream says.
std::size_t compute_fluid_voidage(FluidParticles& f, const DemParticles& s,
                                  const FluidSpherePairs& pairs, double eps_floor,
                                  const BigSpheresSmoothedApart* big = nullptr,
                                  const VoidageUpstream& upstream = {});

}  // namespace sphdem
