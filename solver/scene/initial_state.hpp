#pragma once
#include "dem/dem_particles.hpp"
#include "scene/scene.hpp"
#include "sph/fluid_particles.hpp"

namespace sphdem {

// Places the particles of a scene: the fluid on a simple-cubic lattice of spacing dx
// filling [0, fill_height], the wall layers below z = 0 (thesis §4.2), and the spheres
// of every particle group. Masses and densities of the fluid are set later, once the
// voidage is known (Simulation). Throws SceneError for impossible geometry.
void place_particles(const Scene& scene, FluidParticles& fluid, DemParticles& spheres);

// Lattice spacing per axis and site count of a constant-porosity block (thesis §4.5):
// a = (V_p / (1 - eps))^(1/3), adjusted to a whole number of sites on periodic axes
// the block spans, with a_z chosen to keep the target voidage.
// Simple cubic: count[k] sites at spacing[k] from origin[k]. Fcc: spacing[] is the cubic
// cell, count[0..1] cells across, count[2] (100) layers spacing[2]/2 apart, two sites a
// layer a cell (parity p of the layer: (p/2, 0) and ((1-p)/2, 1/2) of the cell).
struct BlockLattice {
  std::array<double, 3> spacing{}, origin{};
  std::array<int, 3> count{};
  bool fcc = false;
  double voidage = 0;  // actual voidage of the lattice
};
BlockLattice block_lattice(const Scene& scene, const ParticleGroupSpec& group, double diameter);
// The same for the group's own species: for a mixed lattice (bidisperse block, §4.6) the
// sites are spaced for the mean sphere volume, d = (sum_i x_i d_i^3)^(1/3) with the
// number fractions x_i, so the block has the target voidage.
BlockLattice block_lattice(const Scene& scene, const ParticleGroupSpec& group);

}  // namespace sphdem
