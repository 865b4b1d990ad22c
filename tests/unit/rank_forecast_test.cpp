// `check --ranks R`'s forecast (run/rank_forecast.hpp) against what a run holds: on one
// rank its halo copies are those RankHalo builds for the same grid and reach (the images
// across the periodic faces within the reach of a cell: by another code path), and on R
// ranks every particle is owned once, the largest share of the work is at least 1/R and
// the largest rank owns at least N/R.
#include "run/rank_forecast.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include "domain/rank_halo.hpp"
#include "propagator/simulation.hpp"
#include "scene/scene.hpp"
#include "sph/kernel.hpp"

using namespace sphdem;

namespace {
const char* kColumn = R"(
name: column
domain: {size: [0.0024, 0.0024, 0.004]}
fluid: {density: 1000, viscosity: 8.9e-4, spacing: 2.0e-4}
startup: {relax_steps: 0}
time: {end: 0.01}
)";
}

TEST(RankForecast, OneRankHasTheRunsPeriodicImages) {
  Simulation sim(load_scene_text(kColumn, "column.yaml"));
  sim.step();
  const RankForecast one = forecast_ranks(sim, 1);
  FluidParticles f = sim.fluid();
  f.resize(f.n_owned);
  double hmax = 0.0;
  for (std::size_t a = 0; a < f.n_owned; ++a) hmax = std::max(hmax, f.h[a]);
  const double reach = kernel::kSupport * hmax + sim.fluid_skin();
  const Box& box = sim.params().box;
  for (std::size_t a = 0; a < f.n_owned; ++a) {
    f.x[a] = box.wrap(0, f.x[a]);
    f.y[a] = box.wrap(1, f.y[a]);
  }
  const RankComm comm(MPI_COMM_NULL);
  const SfcGrid grid(box, decomposition_cell(box, reach, 1));
  const SfcPartition part =
      partition_curve(grid, std::vector<std::uint64_t>(grid.cell_count(), 1), 1);
  RankHalo halo;
  halo.build(comm, grid, part, reach, f.x.data(), f.y.data(), f.z.data(), f.n_owned);
  EXPECT_EQ(one.owned_max, f.n_owned);
  EXPECT_EQ(one.ghosts_max, halo.n_ghost());
  EXPECT_LE(one.ghosts_max, sim.fluid_halo().n_ghost());  // the run's box test adds corners
  EXPECT_DOUBLE_EQ(one.largest_share, 1.0);
}

TEST(RankForecast, RanksShareEveryParticleAndTheWork) {
  Simulation sim(load_scene_text(kColumn, "column.yaml"));
  sim.step();
  const std::size_t n = sim.fluid().n_owned;
  for (int r : {2, 3, 4}) {
    const RankForecast f = forecast_ranks(sim, r);
    EXPECT_GE(f.owned_max * r, n) << r;
    EXPECT_LT(f.owned_max, n) << r;
    EXPECT_GE(f.largest_share * r, 1.0 - 1e-12) << r;
    EXPECT_LT(f.largest_share, 0.75) << r;  // a column cut by work: near 1/R (<= 1/R + a cell)
    EXPECT_GT(f.ghosts_per_owned, 0.0) << r;
  }
}
