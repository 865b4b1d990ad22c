#pragma once
// The fluid-sphere pairs: for each owned SPH particle a, the spheres j (owned or halo)
// within its kernel support, with W(r_aj, H_a) and its gradient factor. A Verlet list
// (cut-off = support + skin) is built only when the particles have moved too far
// (Simulation::update_neighbours); every step evaluate() keeps, row by row, the entries within the
// support with their kernel values. Those are shared by the voidage (2.50), the
// interpolation at the spheres (2.69, 2.72: the same W, since W_ja(h_a) is the fluid
// particle's kernel), the reaction (2.71) and the variational pressure coupling, so each
// pair costs one distance and one kernel evaluation per step instead of four.
// The drag's kernel (coupling.drag_kernel_scale, at most sphere_kernel_scale) may be
// narrower: then each entry also carries W(r_aj, H^drag_a), and the fields the drag
// reads (voidage, fluid velocity at the spheres) and the reaction use it.
#include <array>
#include <cstdint>
#include <vector>

#include "dem/dem_particles.hpp"
#include "domain/cell_list.hpp"
#include "domain/neighbour_list.hpp"
#include "sph/fluid_particles.hpp"
#include "sph/pair_isa.hpp"

namespace sphdem {

// The cost of a fluid row in a pass over these pairs, in entries (domain/row_partition.hpp;
// where the two threads' samples in these passes even out, bench/RESULTS.md).
constexpr double kFluidRowCost = 32.0;

struct FluidSpherePairs {
  NeighbourList list;  // Verlet list: rows owned SPH particles, entries sphere indices
  std::vector<std::uint32_t> count;   // per row: entries within the support (stored first)
  std::vector<std::uint32_t> sphere;  // per entry: the sphere's index, row by row as list
  std::vector<double> w;              // W(r_aj, H_a) per entry within the support
  std::vector<double> grad;           // grad_a W_aj = grad * (x_a - x_j) (evaluate with_gradient)
  std::vector<double> w_drag;         // W(r_aj, H^drag_a) per entry, only when drag_apart()
  // Per row, with the kernel values: sum_j V_j W_aj and sum_j (V_j / d_j) W_aj, the solid
  // fraction (2.50) and the Sauter mean's denominator (2.80), all species; with the drag's
  // kernel apart, the same with it (else empty).
  std::vector<double> solid, solid_over_d, drag_solid, drag_solid_over_d;
  double scale = 1.0;  // H_a / h_a of the mobile fluid (scene key coupling.sphere_kernel_scale)
  double drag_scale = 1.0;  // H^drag_a / h_a (coupling.drag_kernel_scale), <= scale
  // The drag's weights kept apart even at the spheres' kernel width (a bed on the
  // distributor rewrites them: coupling/distributor_mirror.hpp); set before build_list.
  bool keep_drag_weights = false;
  // The side of a sphere the drag's fields are read from (coupling.drag_upstream: gravity's
  // unit vector; zero: the whole kernel; coupling/interpolation.hpp).
  std::array<double, 3> upstream{};

  bool drag_apart() const { return drag_scale != scale || keep_drag_weights; }
  // The kernel values the drag's fields and the reaction use.
  const std::vector<double>& drag_w() const { return drag_apart() ? w_drag : w; }

  // Entries [begin(a), end(a)) of row a are the spheres within 2 H_a.
  std::uint32_t begin(std::size_t a) const { return list.offset[a]; }
  std::uint32_t end(std::size_t a) const { return list.offset[a] + count[a]; }

  // 1 / H_a: scale h_a for the mobile fluid, h_a for wall particles. A wall particle
  // does not move: its superficial density follows only the fluid within its own 2 h_a,
  // so a voidage reaching further (spheres 2 h_a-2 H_a away) would raise its intrinsic
  // density with nothing to relieve it, and it would hold a sediment up by pressure
  // (reduced sand column at 1.5 h: no sphere on the wall, wall load 0 instead of eq. 15).
  double inv_kernel_h(const FluidParticles& f, std::size_t a) const {
    return f.kind[a] == kWall ? f.inv_h[a] : f.inv_h[a] / scale;
  }
  double inv_drag_kernel_h(const FluidParticles& f, std::size_t a) const {
    return f.kind[a] == kWall ? f.inv_h[a] : f.inv_h[a] / drag_scale;
  }

  // The Verlet list: spheres binned in dem_cells (owned + halo) within rc of each owned
  // SPH particle; rc >= 2 scale max h, up to dem_cells.max_cutoff(). drag_kernel_scale
  // <= kernel_scale (0: the same).
  void build_list(const FluidParticles& f, const CellList& dem_cells, double kernel_scale,
                  double rc, double drag_kernel_scale = 0.0);
  // The same with each particle's own cut-off rc[a] >= 2 scale h_a (the solver's: its own
  // h's support and the skin).
  void build_list(const FluidParticles& f, const CellList& dem_cells, double kernel_scale,
                  const double* rc, double drag_kernel_scale = 0.0);
  // Kernel values and row sums at the current positions (every step); the gradient
  // factors only with_gradient (the variational pressure coupling reads them).
  void evaluate(const FluidParticles& f, const DemParticles& s, bool with_gradient = true,
                PairIsa isa = best_pair_isa());
  // Both, at the cells' cut-off (tests).
  void build(const FluidParticles& f, const DemParticles& s, const CellList& dem_cells,
             double kernel_scale = 1.0, double drag_kernel_scale = 0.0) {
    build_list(f, dem_cells, kernel_scale, dem_cells.max_cutoff(), drag_kernel_scale);
    evaluate(f, s);
  }

 private:
  void size_for_list(const FluidParticles& f, double kernel_scale, double drag_kernel_scale);
};

}  // namespace sphdem
