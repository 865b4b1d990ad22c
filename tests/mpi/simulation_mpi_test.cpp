// The fluid on ranks against one rank (issue 36's agreement row, the fluid column): a
// stirred water column, every rank placing the same lattice and keeping its share, the
// curve recut every 5 steps by the counted pair work and the particles migrated at each
// rebuild; rank 0 runs the same scene on one rank (MPI_COMM_SELF, the run without MPI)
// beside it. Gathered by global id every 25 steps: each particle on exactly one rank, the
// masses identical, positions within 1e-10 of the box and the centre of mass within 1e-6
// relative; the largest difference is printed at each gather (its growth over time).
//
//   mpirun -np R simulation_mpi_test R     (the test fails unless it got R ranks)
#include <gtest/gtest.h>
#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "mpi_gtest_main.hpp"
#include "propagator/simulation.hpp"
#include "scene/scene.hpp"

namespace sphdem {
namespace {

int g_expected_ranks = 0;

const char* kColumn = R"(
name: column_on_ranks
domain: {size: [0.0024, 0.0024, 0.004]}
fluid: {density: 1000, viscosity: 8.9e-4, spacing: 2.0e-4}
startup: {relax_steps: 0}
time: {end: 0.01}
)";

// A smooth velocity field of 20 cm/s, the same function of position on every rank, so that
// particles cross the cuts and the periodic faces within the test's 100 steps.
void stir(Simulation& sim) {
  FluidParticles& f = sim.fluid();
  const Box& box = sim.params().box;
  constexpr double kTwoPi = 6.283185307179586, A = 0.2;
  for (std::size_t a = 0; a < f.n_owned; ++a) {
    if (f.kind[a] != kFluid) continue;
    f.vx[a] = A * std::sin(kTwoPi * f.z[a] / box.length(2));
    f.vy[a] = A * std::sin(kTwoPi * f.x[a] / box.length(0));
    f.vz[a] = 0.2 * A * std::sin(kTwoPi * f.y[a] / box.length(1));
  }
}

// Every particle's position, mass and rank, by global id, summed over the ranks (one
// non-zero term each: exact).
struct ById {
  std::vector<double> x, y, z, mass, rank, seen;
};
ById gather(const Simulation& sim, std::size_t n) {
  ById g{std::vector<double>(n, 0.0), std::vector<double>(n, 0.0), std::vector<double>(n, 0.0),
         std::vector<double>(n, 0.0), std::vector<double>(n, 0.0), std::vector<double>(n, 0.0)};
  const FluidParticles& f = sim.fluid();
  for (std::size_t a = 0; a < f.n_owned; ++a) {
    const auto i = static_cast<std::size_t>(f.id[a]);
    g.x[i] = f.x[a];
    g.y[i] = f.y[a];
    g.z[i] = f.z[a];
    g.mass[i] = f.mass[a];
    g.rank[i] = sim.comm().rank();
    g.seen[i] += 1.0;
  }
  for (auto* v : {&g.x, &g.y, &g.z, &g.mass, &g.rank, &g.seen})
    MPI_Allreduce(MPI_IN_PLACE, v->data(), static_cast<int>(n), MPI_DOUBLE, MPI_SUM,
                  sim.comm().comm());
  return g;
}

// The separation along a periodic axis taken to its nearest image.
double periodic_gap(const Box& box, int d, double a, double b) {
  double s = a - b;
  if (box.periodic[d]) s -= box.length(d) * std::round(s / box.length(d));
  return s;
}

TEST(RanksSimulation, StirredColumnAgreesWithOneRank) {
  const RankComm comm;
  ASSERT_EQ(comm.size(), g_expected_ranks) << "the launcher started other rank counts";
  const int me = comm.rank();
  const Scene sc = load_scene_text(kColumn, "column_on_ranks.yaml");
  Simulation sim(sc, comm);
  sim.set_rebalance_interval(5);
  stir(sim);
  const std::size_t n = comm.sum(sim.fluid().n_owned);
  std::unique_ptr<Simulation> one;
  if (me == 0) {
    one = std::make_unique<Simulation>(sc, RankComm(MPI_COMM_SELF));
    stir(*one);
    ASSERT_EQ(one->fluid().n_owned, n);
  }
  const ById start = gather(sim, n);
  const Box& box = sim.params().box;
  double worst = 0.0;
  for (int block = 1; block <= 4; ++block) {
    for (int k = 0; k < 25; ++k) sim.step();
    if (one) {
      for (int k = 0; k < 25; ++k) one->step();
    }
    const ById g = gather(sim, n);
    if (me != 0) continue;
    const ById r = gather(*one, n);  // one rank: MPI_COMM_SELF's sum is itself
    double dmax = 0.0, com_r[3] = {0, 0, 0}, com_g[3] = {0, 0, 0}, m_r = 0, m_g = 0;
    std::size_t moved = 0;
    for (std::size_t i = 0; i < n; ++i) {
      ASSERT_EQ(g.seen[i], 1.0) << "particle " << i << " on " << g.seen[i] << " ranks";
      ASSERT_EQ(g.mass[i], r.mass[i]) << "particle " << i;
      const double d[3] = {periodic_gap(box, 0, g.x[i], r.x[i]),
                           periodic_gap(box, 1, g.y[i], r.y[i]), g.z[i] - r.z[i]};
      for (int a = 0; a < 3; ++a) dmax = std::max(dmax, std::abs(d[a]) / box.length(a));
      const double pr[3] = {r.x[i], r.y[i], r.z[i]};
      for (int a = 0; a < 3; ++a) {
        com_r[a] += r.mass[i] * pr[a];
        com_g[a] += g.mass[i] * (pr[a] + d[a]);  // the same image as the reference's
      }
      m_r += r.mass[i];
      m_g += g.mass[i];
      if (g.rank[i] != start.rank[i]) ++moved;
    }
    double com_rel = 0.0;
    for (int a = 0; a < 3; ++a)
      com_rel =
          std::max(com_rel, std::abs(com_g[a] / m_g - com_r[a] / m_r) / std::abs(com_r[a] / m_r));
    std::printf(
        "%d ranks, step %ld (t %.4g s, one rank %.4g s): max |x - x_1| / L %.3g, centre of mass "
        "%.3g relative, %zu of %zu particles on another rank than at the start\n",
        comm.size(), sim.step_count(), sim.time(), one->time(), dmax, com_rel, moved, n);
    worst = std::max(worst, dmax);
    EXPECT_EQ(m_g, m_r);
    EXPECT_LT(dmax, 1e-10);
    EXPECT_LT(com_rel, 1e-6);
    EXPECT_NEAR(sim.time(), one->time(), 1e-12 * one->time());
    if (comm.size() > 1 && block == 4) {
      EXPECT_GT(moved, 0u);  // the particles did migrate
    }
  }
  if (me == 0) std::printf("worst %.3g of the box\n", worst);
}

}  // namespace
}  // namespace sphdem

int main(int argc, char** argv) {
  return sphdem::run_mpi_gtests(argc, argv, sphdem::g_expected_ranks);
}
