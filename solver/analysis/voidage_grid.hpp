#pragma once
// The solver's voidage on a regular grid, for analysis (the in-situ voidage map, the
// bulk density profile). At a node x it is the sum the solver takes at a mobile fluid
// particle standing there (coupling/voidage.hpp, double_smoothing.hpp):
//   h(x)   = sum_b V_b h_b W(x - x_b, h_b) / sum_b V_b W(x - x_b, h_b)  (mobile fluid b)
//   eps(x) = 1 - sum_j V_j W(x - x_j, s h(x))                            (2.50)
//            - sum_b V_b phi_b W(x - x_b, h(x)) / sum_b V_b W(x - x_b, h(x))  (3.10)
// with s = coupling.sphere_kernel_scale, the first sum over the spheres not smoothed
// apart and the second only with the double smoothing (phi_b of 3.9 at every SPH
// particle b): the kernel widths of each species and the double smoothing are the
// solver's, and h(x) is the smoothing length a fluid particle at x would have. Not
// clamped to the voidage floor; 1 where no fluid particle reaches.
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "dem/dem_particles.hpp"
#include "domain/box.hpp"
#include "domain/rank_comm.hpp"
#include "sph/fluid_particles.hpp"

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

// The column [0, Lx) x [0, Ly) x [0, height] with nodes at cell centres: a whole number
// of cells across each periodic width and up the column, each about `spacing`.
GridSpec column_voidage_grid(double lx, double ly, double height, double spacing);

// What the sums read: fluid particles and spheres, owned first and their periodic images
// after (x, y, z, h, mass, rho and kind of the fluid; x, y, z, radius and species of the
// spheres), far enough round the nodes for the widest kernel.
struct VoidageSources {
  const FluidParticles& fluid;
  const DemParticles& spheres;
  double sphere_kernel_scale = 1;
  // the double smoothing: per species, smoothed apart or not, and (3.9) at every fluid
  // particle; both null without it
  const std::vector<std::uint8_t>* is_big = nullptr;
  const std::vector<double>* phi = nullptr;
  // > 0: every node and sphere at this one width (the fluid is not read): the grains'
  // packing resolved at h, not the solver's field
  double fixed_h = 0;
};

// The owned particles and their periodic images within `width` of the faces, owned
// first (a run's own halo copies may be stale between its list builds).
FluidParticles with_periodic_images(const FluidParticles& owned, const Box& box, double width);
DemParticles with_periodic_images(const DemParticles& owned, const Box& box, double width);

// Values in VTK order (x fastest), for the nodes of spec.extent. With a communicator of
// several ranks (collective: every rank the same spec) each rank gives its owned particles
// and their images, and every rank gets the whole grid: the sums that make h(x), then the
// spheres' and (3.10)'s, are summed over the ranks. By default one rank's sources alone.
std::vector<double> voidage_at_nodes(const VoidageSources& src, const GridSpec& spec,
                                     const RankComm& comm = RankComm(MPI_COMM_NULL));

// The same from a run's particles at their present positions (with periodic images of
// the owned particles made afresh, and phi recomputed with the double smoothing; on
// ranks phi comes from the spheres' halo copies, as the run's own step reads them).
std::vector<double> voidage_on_grid(const Simulation& sim, const GridSpec& spec);

// The grains' voidage resolved with one kernel width h at every node and sphere,
// 1 - sum_j V_j W(x - x_j, h): the packing of the spheres (the bulk density profile,
// analysis/bulk_density.hpp), sharper than the solver's field where the solver's kernel
// is wider (a sediment's fluid carries larger h, the spheres' kernel may be wider still).
std::vector<double> grain_voidage_on_grid(const Simulation& sim, const GridSpec& spec, double h);

// A rank's piece of a grid whose values every rank holds: a slab of whole z-layers
// (empty where the grid has fewer layers than ranks), and its values.
GridSpec rank_piece(const GridSpec& whole, int rank, int ranks);
std::vector<double> piece_values(const std::vector<double>& values, const GridSpec& whole,
                                 const GridSpec& piece);

}  // namespace sphdem
