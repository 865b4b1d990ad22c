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

// Voidage at every owned SPH particle a (fluid and wall) from its sphere pairs:
//   eps_a = 1 - sum_j V_j W(r_a - r_j, h_a)   (2.50),
// and the local Sauter mean diameter of the solids, sum_j V_j W / sum_j (V_j/d_j) W (2.80).
// eps is clamped to eps_floor (default 0.3): the kernel estimate can undershoot in a
// dense sediment; returns how many particles were clamped (logged per step). The voidage
// the drag reads, eps_drag, is the same sum with the drag's kernel when pairs.drag_apart()
// (its clamps counted too), else eps; the Sauter mean is the drag's. The sums over all
// species come from the pairs' evaluation (FluidSpherePairs::solid); with big spheres
// smoothed apart the pairs are summed here without them.
std::size_t compute_fluid_voidage(FluidParticles& f, const DemParticles& s,
                                  const FluidSpherePairs& pairs, double eps_floor,
                                  const BigSpheresSmoothedApart* big = nullptr);

}  // namespace sphdem
