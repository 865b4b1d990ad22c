#pragma once
// The voidage field on a regular grid, for analysis: at each node x,
//   eps(x) = 1 - sum_j V_j W(x - x_j, h)         (2.50, with the solver's kernel)
// from the spheres binned in `cells` (owned + halo). Not clamped, so that
// sum over nodes of (1 - eps) dV equals the solid volume the grid encloses.
#include <array>
#include <cstddef>
#include <vector>

#include "dem/dem_particles.hpp"
#include "domain/cell_list.hpp"

namespace sphdem {

class Simulation;

struct GridSpec {
  std::array<double, 3> origin{0, 0, 0};            // position of node (0,0,0)
  std::array<double, 3> spacing{1e-4, 1e-4, 1e-4};  // node spacing per axis
  std::array<int, 6> extent{0, 0, 0, 0, 0, 0};      // node index range [i0,i1] x [j0,j1] x [k0,k1]
  std::size_t count() const {
    return static_cast<std::size_t>(extent[1] - extent[0] + 1) * (extent[3] - extent[2] + 1) *
           (extent[5] - extent[4] + 1);
  }
};

// Grid covering [0, Lx) x [0, Ly) with nodes at cell centres, and z from -2h to
// top + 2h so that the kernel of every sphere in the column lies inside it.
GridSpec column_voidage_grid(double lx, double ly, double top, double spacing, double h);

// Values in VTK order (x fastest), for the nodes of spec.extent.
std::vector<double> compute_voidage_grid(const DemParticles& s, const CellList& cells,
                                         const GridSpec& spec, double h);

// The same from a run's spheres, binned afresh (they have moved since the step's list
// build); throws if the kernel's support exceeds the sphere halo.
std::vector<double> voidage_on_grid(const Simulation& sim, const GridSpec& spec, double h);

}  // namespace sphdem
