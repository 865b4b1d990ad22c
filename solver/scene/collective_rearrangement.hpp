#pragma once
// Dense random packings (particle group `type: random` below voidage kRearrangeBelow,
// random_packing.hpp): collective rearrangement (Jodrey & Tory 1985; reviewed by Bezrukov,
// Bargiel & Stoyan 2002). The centres start uniformly at random, overlapping, at the
// spheres' own radii; every overlapping pair is pushed apart along its line of centres to
// kPushGap beyond contact, half each (all of it for a sphere of an earlier group, which
// does not move), all pushes of a sweep at once, until no pair overlaps. Random sequential
// addition cannot pass a solid fraction of 0.384; this reaches 0.58-0.6 for equal spheres
// (random close packing is 0.64). Growing the radii in stages from RSA's range, the
// textbook variant, took more sweeps. Deterministic: one thread, a fixed order.
#include <array>
#include <cstdint>
#include <vector>

#include "scene/sphere_grid.hpp"

namespace sphdem {

inline constexpr double kPushGap = 1e-3;  // pairs end this share of contact apart
inline constexpr std::uint64_t kMaxSweeps = 4000;

// Where centres may lie: along a wrapped axis anywhere in [lo, lo + span) (periodic),
// otherwise in [lo + r, lo + span - r] (the sphere inside the region).
struct PlacementRegion {
  std::array<double, 3> lo{}, span{};
  std::array<bool, 3> wrap{};
};

// Spheres that do not move (earlier groups), structure of arrays.
struct FixedSpheres {
  std::vector<double> x, y, z, radius;
};

struct Rearrangement {
  std::uint64_t sweeps = 0;   // in all stages
  double overlap = 0;         // largest left, as a share of its pair's contact distance
  double solid_fraction = 0;  // the stage reached
  bool converged = false;     // no overlap at the spheres' own radii
};

// Moves the centres (x, y, z) of the spheres of radii `radius`, drawn inside `where`,
// until none overlaps another or a fixed one. `grid` covers the region with cells at
// least the largest contact distance wide.
Rearrangement rearrange(const PlacementRegion& where, const FixedSpheres& fixed, SphereGrid& grid,
                        std::vector<double>& x, std::vector<double>& y, std::vector<double>& z,
                        const std::vector<double>& radius);

}  // namespace sphdem
