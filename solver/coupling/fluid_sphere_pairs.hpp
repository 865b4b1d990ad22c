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
  std::vector<double> w;  // W(r_aj, H_a) per entry (0 beyond 2 H_a)
  double scale = 1.0;     // H_a / h_a of the mobile fluid (scene key coupling.sphere_kernel_scale)

  // 1 / H_a: scale h_a for the mobile fluid, h_a for wall particles. A wall particle
  // does not move: its superficial density follows only the fluid within its own 2 h_a,
  // so a voidage reaching further (spheres 2 h_a-2 H_a away) would raise its intrinsic
  // density with nothing to relieve it, and it would hold a sediment up by pressure
  // (reduced sand column at 1.5 h: no sphere on the wall, wall load 0 instead of eq. 15).
  double inv_kernel_h(const FluidParticles& f, std::size_t a) const {
    return f.kind[a] == kWall ? f.inv_h[a] : f.inv_h[a] / scale;
  }

  // dem_cells bins the spheres (owned + halo) with a cut-off >= 2 scale max h.
  void build(const FluidParticles& f, const DemParticles& s, const CellList& dem_cells, double kernel_scale = 1.0);
};

}  // namespace sphdem
