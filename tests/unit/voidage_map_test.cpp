// The voidage map (analysis/voidage_grid.hpp: the in-situ map and the bulk density
// profile) is the solver's voidage: on a polydisperse bed whose fluid particles carry
// their own smoothing lengths (larger in the bed, as after a sediment forms), with the
// spheres' kernel at 1.5 h, and on a bidisperse bed with the double smoothing, the map's
// mean over each horizontal layer equals the mean of the fluid particles' eps over the
// same layer. The same map with one kernel width h = sigma dx for every node and sphere
// (what the map computed before) misses it several times over, so the comparison tells
// the two apart. The map covers the column, 0 <= z <= H, not the layers below the wall.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "analysis/voidage_grid.hpp"
#include "propagator/simulation.hpp"
#include "scene/scene.hpp"
#include "sph/kernel.hpp"

using namespace sphdem;

namespace {

struct LayerMeans {
  std::vector<double> map, solver;
};

// The map's and the fluid's eps averaged over each layer of the grid.
LayerMeans layer_means(const Simulation& sim, const GridSpec& g, const std::vector<double>& map) {
  const int nx = g.extent[1] + 1, ny = g.extent[3] + 1, nz = g.extent[5] + 1;
  LayerMeans m{std::vector<double>(nz, 0.0), std::vector<double>(nz, 0.0)};
  for (int l = 0; l < nz; ++l)
    for (int k = 0; k < nx * ny; ++k) m.map[l] += map[l * nx * ny + k] / (nx * ny);
  std::vector<int> count(nz, 0);
  const FluidParticles& f = sim.fluid();
  for (std::size_t a = 0; a < f.n_owned; ++a) {
    if (f.kind[a] != kFluid) continue;
    const int l = static_cast<int>(std::floor(f.z[a] / g.spacing[2]));
    if (l < 0 || l >= nz) continue;
    m.solver[l] += f.eps[a];
    ++count[l];
  }
  for (int l = 0; l < nz; ++l) m.solver[l] /= std::max(count[l], 1);
  return m;
}

double largest_difference(const LayerMeans& m) {
  double worst = 0.0;
  for (std::size_t l = 0; l < m.map.size(); ++l)
    worst = std::max(worst, std::abs(m.map[l] - m.solver[l]));
  return worst;
}

// The fluid particles' masses as if each had started in clear fluid: their smoothing
// lengths sigma (m/rho)^(1/3) then grow where the voidage is low, as in a sediment.
void clear_fluid_masses(Simulation& sim) {
  FluidParticles& f = sim.fluid();
  const double dx = sim.scene().fluid.spacing, rho0 = sim.scene().fluid.density;
  for (std::size_t a = 0; a < f.n_owned; ++a)
    if (f.kind[a] == kFluid) f.mass[a] = rho0 * dx * dx * dx;
  sim.refresh();
}

GridSpec column_grid(const Scene& sc) {
  return column_voidage_grid(sc.box.length(0), sc.box.length(1), sc.fill_height(),
                             sc.fluid.spacing);
}

const char* const kPolydisperseBed = R"(domain: {size: [0.002, 0.002, 0.003]}
fluid: {spacing: 1.0e-4}
species:
  - name: sand
    density: 2500
    size_distribution: {law: uniform, min: 6.0e-5, max: 1.0e-4}
particles:
  - {type: random, species: sand, min: [0, 0, 0], max: [0.002, 0.002, 0.0012], voidage: 0.7, seed: 7}
coupling: {sphere_kernel_scale: 1.5}
startup: {relax_steps: 0}
)";

const char* const kBidisperseBed = R"(domain: {size: [0.002, 0.002, 0.003]}
fluid: {spacing: 1.0e-4}
species:
  - {name: big, diameter: 1.6e-4, density: 2500}
  - {name: small, diameter: 6.0e-5, density: 2500}
particles:
  - {type: random, species: [big, small], fractions: [0.2, 0.8], min: [0, 0, 0], max: [0.002, 0.002, 0.0012], voidage: 0.75, seed: 3}
coupling: {voidage_smoothing: double}
startup: {relax_steps: 0}
)";

// The largest layer difference of the map and of the lattice-kernel map from the solver's eps.
std::pair<double, double> compare(const char* yaml, bool wider_kernels_in_the_bed) {
  const Scene sc = load_scene_text(yaml, "bed.yaml");
  Simulation sim(sc);
  if (wider_kernels_in_the_bed) {
    clear_fluid_masses(sim);
    double h_max = 0.0;
    for (std::size_t a = 0; a < sim.fluid().n_owned; ++a) h_max = std::max(h_max, sim.fluid().h[a]);
    EXPECT_GT(h_max, 1.08 * sc.fluid.lattice_h());  // the bed's fluid carries wider kernels
  }
  const GridSpec g = column_grid(sc);
  const LayerMeans m = layer_means(sim, g, voidage_on_grid(sim, g));
  EXPECT_GT(m.solver[4], 0.6);  // a bed
  EXPECT_LT(m.solver[4], 0.8);
  const double worst = largest_difference(m);
  const double lattice =
      largest_difference(layer_means(sim, g, grain_voidage_on_grid(sim, g, sc.fluid.lattice_h())));
  std::printf("bed eps %.4f; largest layer difference: map %.2e, lattice-kernel map %.2e\n",
              m.solver[4], worst, lattice);
  return {worst, lattice};
}

}  // namespace

TEST(VoidageMap, CoversTheColumnOnly) {
  const GridSpec g = column_voidage_grid(0.002, 0.002, 0.003, 1e-4);
  EXPECT_DOUBLE_EQ(g.origin[2], 0.5e-4);
  EXPECT_EQ(g.extent[5], 29);
  EXPECT_DOUBLE_EQ(g.origin[2] + g.extent[5] * g.spacing[2], 0.003 - 0.5e-4);
}

// At the start every fluid particle has h = sigma dx and the nodes stand at the fluid
// lattice's sites: the map is the solver's eps at the particles, to round-off.
TEST(VoidageMap, IsTheSolversVoidageAtTheParticles) {
  for (const char* bed : {kPolydisperseBed, kBidisperseBed}) {
    const auto [map, lattice] = compare(bed, false);
    EXPECT_LT(map, 1e-12);
    EXPECT_GT(lattice, 1e-2);
  }
}

// With each particle's own h (wider in the bed), a node takes the Shepard mean of its
// neighbours' h: a particle's own h grows as its own eps falls, which the mean at a node
// does not follow, so the layers differ by a small offset through the bed (the size of
// the correlation of h and eps from particle to particle); the lattice-kernel map misses
// by an order of magnitude more.
TEST(VoidageMap, FollowsTheParticlesSmoothingLengths) {
  for (const char* bed : {kPolydisperseBed, kBidisperseBed}) {
    const auto [map, lattice] = compare(bed, true);
    EXPECT_LT(map, 1e-3);
    EXPECT_GT(lattice, 10.0 * map);
  }
}

// On R ranks each rank publishes a slab of whole z-layers of the grid every rank holds:
// the slabs cover the layers once, in rank order, and their values are the whole grid's
// (empty slabs where there are fewer layers than ranks).
TEST(VoidageMap, RankPiecesTileTheGrid) {
  const GridSpec whole = column_voidage_grid(1e-3, 2e-3, 5e-3, 1e-3);  // 1 x 2 x 5 nodes
  std::vector<double> values(whole.count());
  for (std::size_t k = 0; k < values.size(); ++k) values[k] = static_cast<double>(k);
  for (int ranks : {1, 2, 3, 5, 7}) {
    std::vector<double> joined;
    int next_layer = 0;
    for (int r = 0; r < ranks; ++r) {
      const GridSpec piece = rank_piece(whole, r, ranks);
      EXPECT_EQ(piece.extent[4], next_layer) << ranks << " ranks, rank " << r;
      next_layer = piece.extent[5] + 1;
      const std::vector<double> v = piece_values(values, whole, piece);
      EXPECT_EQ(v.size(), piece.extent[5] >= piece.extent[4] ? piece.count() : 0u);
      joined.insert(joined.end(), v.begin(), v.end());
    }
    EXPECT_EQ(next_layer, whole.extent[5] + 1);
    EXPECT_EQ(joined, values) << ranks << " ranks";
  }
}
