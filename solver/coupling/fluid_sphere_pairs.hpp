#pragma once
// The fluid-sphere pairs of one step: for each owned SPH particle a, the spheres j
// (owned or halo) within its kernel support, with W(r_aj, h_a). Built once per step and
// shared by the voidage (2.50), the interpolation at the spheres (2.69, 2.72: the same
// W, since W_ja(h_a) is the fluid particle's kernel) and the reaction (2.71), so each
// pair costs one cell walk and one kernel evaluation instead of three.
#include <cstdint>
#include <vector>

#include "dem/dem_particles.hpp"
#include "domain/cell_list.hpp"
#include "domain/neighbour_list.hpp"
#include "sph/fluid_particles.hpp"

namespace sphdem {

struct FluidSpherePairs {
  NeighbourList list;    // rows: owned SPH particles; entries: sphere indices
  std::vector<double> w;  // W(r_aj, H_a) per entry (0 beyond 2 H_a), H_a = scale h_a
  double scale = 1.0;     // H_a / h_a (scene key coupling.sphere_kernel_scale)

  // dem_cells bins the spheres (owned + halo) with a cut-off >= 2 scale max h.
  void build(const FluidParticles& f, const DemParticles& s, const CellList& dem_cells, double kernel_scale = 1.0);
};

}  // namespace sphdem
