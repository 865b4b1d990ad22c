#pragma once
// A homogeneous random suspension at a target voidage (particle group `type: random`):
// random sequential addition (RSA). Spheres are placed one at a time, largest first, at
// uniformly random centres; a centre whose sphere would overlap one already placed (or
// a sphere of an earlier group) is drawn again. Replaces the thesis' shake-and-settle
// (§4.7), which needed many SPH-DEM steps.
//
// - The number of spheres: the species are dealt by their number fractions (QuotaDealer,
//   exact to one sphere), each diameter is drawn from its species' law, and spheres are
//   taken while they bring the solid volume closer to (1 - eps) V_region; so the
//   achieved voidage is within V_max / (2 V_region) of the target (half the largest
//   sphere; for equal spheres N = round((1 - eps) V_region / V_p)).
// - Where: centres fill x and y periodically when the region spans the whole periodic
//   width (overlaps across the periodic faces count), otherwise each sphere lies inside
//   the region; in z every sphere lies inside [min_z, max_z], hence above the wall.
// - Overlap checks use a linked-cell grid, with the minimum image on periodic axes.
// - Seeded: std::mt19937_64 streams from std::seed_seq{seed, stream}, both fixed by the
//   C++ standard, one thread, so a seed gives bit-identical positions and diameters.
// - RSA saturates: for equal spheres it cannot exceed a solid fraction of 0.384
//   (Torquato, Uche & Stillinger 2006) and the acceptance rate collapses before that.
//   After kRsaAttemptsPerSphere rejected centres for one sphere it stops with a
//   SceneError naming particles.N.voidage.
// - Below voidage kRearrangeBelow (where RSA slows down and then jams) the same spheres are
//   placed by collective rearrangement instead (collective_rearrangement.hpp): all centres
//   drawn at once, the overlaps pushed apart while the radii grow. It stops with a
//   SceneError naming particles.N.voidage when overlaps remain (near random close packing).
#include <cstdint>
#include <vector>

#include "dem/dem_particles.hpp"
#include "scene/scene.hpp"

namespace sphdem {

inline constexpr std::uint64_t kRsaAttemptsPerSphere = 100000;
inline constexpr double kRsaSaturation = 0.384;  // jamming limit of RSA, equal spheres
inline constexpr double kRearrangeBelow = 0.65;  // voidage: below it, collective rearrangement

struct RandomPacking {
  // one entry per sphere, in insertion order (largest first)
  std::vector<double> x, y, z, radius;
  std::vector<std::uint16_t> species;  // index into Scene::species
  double voidage = 1.0;                // achieved: 1 - sum_j V_j / V_region
  std::uint64_t attempts = 0;          // centres drawn in all
  std::uint64_t sweeps = 0;            // of collective rearrangement (0 for RSA)
};

// Places the spheres of the random group `scene.particles[group]`, avoiding the spheres
// already in `existing` (earlier groups). Throws SceneError for a region thinner than
// the largest sphere, an empty group, or a target RSA cannot reach.
RandomPacking random_packing(const Scene& scene, std::size_t group, const DemParticles& existing);

}  // namespace sphdem
