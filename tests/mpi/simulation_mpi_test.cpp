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
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <string>
#include <vector>

#include "analysis/sediment_output.hpp"
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
template <class Particles>
ById gather(const Particles& p, std::size_t n, const RankComm& comm) {
  ById g;
  for (auto* v : {&g.x, &g.y, &g.z, &g.mass, &g.rank, &g.seen}) v->assign(n, 0.0);
  for (std::size_t a = 0; a < p.n_owned; ++a) {
    const auto i = static_cast<std::size_t>(p.id[a]);
    g.x[i] = p.x[a];
    g.y[i] = p.y[a];
    g.z[i] = p.z[a];
    g.mass[i] = p.mass[a];
    g.rank[i] = comm.rank();
    g.seen[i] += 1.0;
  }
  for (auto* v : {&g.x, &g.y, &g.z, &g.mass, &g.rank, &g.seen})
    MPI_Allreduce(MPI_IN_PLACE, v->data(), static_cast<int>(n), MPI_DOUBLE, MPI_SUM, comm.comm());
  return g;
}

// The separation along a periodic axis taken to its nearest image.
double periodic_gap(const Box& box, int d, double a, double b) {
  double s = a - b;
  if (box.periodic[d]) s -= box.length(d) * std::round(s / box.length(d));
  return s;
}

// One phase on ranks (g) against one rank (r): each particle on one rank, the same masses;
// returns the largest position difference over the box and the centre of mass's, relative.
struct Agreement {
  double position = 0, centre = 0, mass = 0;
  std::size_t moved = 0;  // particles on another rank than at the start
};
Agreement compare(const ById& g, const ById& r, const ById& start, const Box& box,
                  const char* phase) {
  Agreement out;
  const std::size_t n = g.x.size();
  double com_r[3] = {0, 0, 0}, com_g[3] = {0, 0, 0}, m_r = 0, m_g = 0;
  for (std::size_t i = 0; i < n; ++i) {
    EXPECT_EQ(g.seen[i], 1.0) << phase << " " << i << " on " << g.seen[i] << " ranks";
    // constant on the ranks; against one rank, the hydrostatic start's m = rho(eps) dx^3
    // (eps a sum over the spheres in neighbour order) agrees to round-off
    EXPECT_EQ(g.mass[i], start.mass[i]) << phase << " " << i;
    EXPECT_NEAR(g.mass[i], r.mass[i], 1e-14 * r.mass[i]) << phase << " " << i;
    out.mass = std::max(out.mass, std::abs(g.mass[i] / r.mass[i] - 1.0));
    const double d[3] = {periodic_gap(box, 0, g.x[i], r.x[i]), periodic_gap(box, 1, g.y[i], r.y[i]),
                         periodic_gap(box, 2, g.z[i], r.z[i])};
    for (int a = 0; a < 3; ++a)
      out.position = std::max(out.position, std::abs(d[a]) / box.length(a));
    const double pr[3] = {r.x[i], r.y[i], r.z[i]};
    for (int a = 0; a < 3; ++a) {
      com_r[a] += r.mass[i] * pr[a];
      com_g[a] += g.mass[i] * (pr[a] + d[a]);  // the same image as the reference's
    }
    m_r += r.mass[i];
    m_g += g.mass[i];
    if (g.rank[i] != start.rank[i]) ++out.moved;
  }
  EXPECT_NEAR(m_g, m_r, 1e-14 * m_r) << phase;
  for (int a = 0; a < 3; ++a)
    out.centre =
        std::max(out.centre, std::abs(com_g[a] / m_g - com_r[a] / m_r) / std::abs(com_r[a] / m_r));
  return out;
}

// Runs a scene on the ranks and on one rank (rank 0) in blocks of steps, comparing both
// phases by global id after each block.
void agree_with_one_rank(const char* text, void (*prepare)(Simulation&), int blocks,
                         int steps_per_block, double position_tol, bool multirate = true) {
  const RankComm comm;
  ASSERT_EQ(comm.size(), g_expected_ranks) << "the launcher started other rank counts";
  const int me = comm.rank();
  const Scene sc = load_scene_text(text, "on_ranks.yaml");
  Simulation sim(sc, comm);
  sim.set_rebalance_interval(5);
  if (prepare) prepare(sim);
  const std::size_t nf = comm.sum(sim.fluid().n_owned), ns = comm.sum(sim.spheres().n_owned);
  std::unique_ptr<Simulation> one;
  if (me == 0) {
    one = std::make_unique<Simulation>(sc, RankComm(MPI_COMM_SELF));
    if (prepare) prepare(*one);
    ASSERT_EQ(one->fluid().n_owned, nf);
    ASSERT_EQ(one->spheres().n_owned, ns);
  }
  sim.relax();
  if (one) one->relax();
  const ById fluid_start = gather(sim.fluid(), nf, comm);
  const ById sphere_start = gather(sim.spheres(), ns, comm);
  const Box& box = sim.params().box;
  const RankComm self(MPI_COMM_SELF);
  for (int block = 1; block <= blocks; ++block) {
    for (int k = 0; k < steps_per_block; ++k) sim.step();
    if (one) {
      for (int k = 0; k < steps_per_block; ++k) one->step();
    }
    const ById gf = gather(sim.fluid(), nf, comm), gs = gather(sim.spheres(), ns, comm);
    if (me != 0) continue;
    const Agreement f = compare(gf, gather(one->fluid(), nf, self), fluid_start, box, "fluid");
    const Agreement s = compare(gs, gather(one->spheres(), ns, self), sphere_start, box, "sphere");
    std::printf(
        "%d ranks, step %ld (t %.4g s, one rank %.4g s): max |x - x_1| / L fluid %.3g, spheres "
        "%.3g; centre of mass fluid %.3g, spheres %.3g relative; on another rank than at the "
        "start: %zu of %zu fluid, %zu of %zu spheres; fluid masses within %.2g\n",
        comm.size(), sim.step_count(), sim.time(), one->time(), f.position, s.position, f.centre,
        s.centre, f.moved, nf, s.moved, ns, f.mass);
    EXPECT_LT(f.position, position_tol);
    EXPECT_LT(s.position, position_tol);
    EXPECT_LT(f.centre, 1e-6);
    EXPECT_LT(s.centre, 1e-6);
    EXPECT_NEAR(sim.time(), one->time(), 1e-12 * one->time());
    if (comm.size() > 1 && block == blocks) {
      EXPECT_GT(f.moved + s.moved, 0u);  // the particles did migrate
    }
    if (block == blocks && ns > 0 && multirate) {  // the multi-rate half step was exercised
      std::printf("multi-rate half steps: %ld of %ld on the ranks (rank 0), %ld of %ld on one\n",
                  sim.multirate_tally().multirate, sim.multirate_tally().half_steps,
                  one->multirate_tally().multirate, one->multirate_tally().half_steps);
      EXPECT_GT(one->multirate_tally().multirate, 0);
      EXPECT_EQ(sim.multirate_tally().multirate, one->multirate_tally().multirate);
    }
  }
}

TEST(RanksSimulation, StirredColumnAgreesWithOneRank) {
  agree_with_one_rank(kColumn, stir, 4, 25, 1e-10);
}

// Two densities settling at voidage 0.8 with friction (contact history across the cuts) and
// the multi-rate half step (its decisions taken alike on every rank), 10 relaxation steps
// and 40 steps: tests/mpi/suspension_on_ranks.yaml, which mpi_run_on_ranks runs too.
TEST(RanksSimulation, SettlingSuspensionAgreesWithOneRank) {
  std::ifstream in(SPHDEM_MPI_TEST_DIR "/suspension_on_ranks.yaml");
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  ASSERT_FALSE(text.empty());
  agree_with_one_rank(text.c_str(), nullptr, 2, 20, 1e-10);
}

// A rigid block (thesis §4.5) across the cuts: its members share the force summed over
// every rank's members, so it falls as one body, as on one rank.
const char* kRigidBlock = R"(
name: rigid_block_on_ranks
domain: {size: [0.0016, 0.0016, 0.003]}
fluid: {density: 1000, viscosity: 8.9e-4, spacing: 2.0e-4, smoothing_factor: 1.5}
species:
  - {name: glass, diameter: 1.0e-4, density: 2500}
particles:
  - {type: lattice, species: glass, voidage: 0.9, min: [0, 0, 0.001], max: [0.0016, 0.0016, 0.002], rigid: true}
contact: {model: linear_spring_dashpot, stiffness: 10, damping: 0}
drag: {law: di_felice}
time: {end: 0.01}
startup: {relax_steps: 10}
insitu: {enabled: false}
)";

TEST(RanksSimulation, RigidBlockAgreesWithOneRank) {
  agree_with_one_rank(kRigidBlock, nullptr, 2, 20, 1e-10, /*multirate=*/false);
}

// A bed on the distributor of a column periodic in z (issue 37), with friction, the flow
// controller ramping U up through the bed and the top plane: the controller's sums and G
// over the ranks, the spheres' share of each correction, the planes, as on one rank.
const char* kPeriodicBed = R"(
name: periodic_bed_on_ranks
domain: {size: [0.0016, 0.0016, 0.0032], periodic_z: true}
fluid: {density: 1000, viscosity: 8.9e-4, spacing: 2.0e-4, smoothing_factor: 1.5}
species:
  - {name: glass, diameter: 1.0e-4, density: 2500}
particles:
  - {type: random, species: glass, voidage: 0.75, min: [0, 0, 0], max: [0.0016, 0.0016, 0.0016], seed: 3}
contact: {tangential: {model: linear_history, friction: 0.3}}
drag: {law: di_felice}
flow: {times: [0, 0.004], superficial_velocity: [0, 0.004], distributor: true, top_plane: 0.003}
time: {end: 0.01}
startup: {relax_steps: 10}
insitu: {enabled: false}
)";

TEST(RanksSimulation, BedInAPeriodicColumnAgreesWithOneRank) {
  agree_with_one_rank(kPeriodicBed, nullptr, 2, 20, 1e-10);
}

// The end-of-run sediment output on ranks (rank 0 writes what every rank gathered), after
// 20 steps of the suspension with the spheres sent off at 30 cm/s: every touching pair and
// wall contact of the whole set, each once, with its overlap as the
// gathered positions give it (brute force over all pairs, periodic across x and y).
TEST(RanksSimulation, ContactNetworkHoldsEveryContactOnce) {
  const RankComm comm;
  ASSERT_EQ(comm.size(), g_expected_ranks) << "the launcher started other rank counts";
  std::ifstream in(SPHDEM_MPI_TEST_DIR "/suspension_on_ranks.yaml");
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  Simulation sim(load_scene_text(text, "suspension_on_ranks.yaml"), comm);
  sim.relax();
  DemParticles& moving = sim.spheres();  // 30 cm/s in directions set by the ids: collisions
  for (std::size_t j = 0; j < moving.n_owned; ++j) {
    const double i = static_cast<double>(moving.id[j]);
    moving.vx[j] = 0.3 * std::sin(1.3 * i);
    moving.vy[j] = 0.3 * std::cos(0.7 * i);
    moving.vz[j] = 0.3 * std::sin(2.1 * i);
  }
  for (int k = 0; k < 20; ++k) sim.step();
  const std::string dir = "sediment_on_" + std::to_string(comm.size()) + "_ranks";
  if (comm.rank() == 0) std::filesystem::create_directories(dir);
  comm.barrier();
  write_sediment_output(sim, dir);
  const DemParticles& s = sim.spheres();
  const std::size_t n = comm.sum(s.n_owned);
  std::vector<double> x(n), y(n), z(n), r(n);  // by id, summed over ranks (one term each)
  for (std::size_t j = 0; j < s.n_owned; ++j) {
    const auto i = static_cast<std::size_t>(s.id[j]);
    x[i] = s.x[j], y[i] = s.y[j], z[i] = s.z[j], r[i] = s.radius[j];
  }
  for (auto* v : {&x, &y, &z, &r}) comm.sum(*v);
  if (comm.rank() != 0) return;
  const Box& box = sim.params().box;
  std::map<std::pair<long, long>, double> expected;  // (id, id or -1 for the wall) -> overlap
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = i + 1; j < n; ++j) {
      const double dx = periodic_gap(box, 0, x[i], x[j]), dy = periodic_gap(box, 1, y[i], y[j]),
                   dz = z[i] - z[j];
      const double delta = r[i] + r[j] - std::sqrt(dx * dx + dy * dy + dz * dz);
      if (delta > 0.0) expected[{static_cast<long>(i), static_cast<long>(j)}] = delta;
    }
    if (z[i] < r[i]) expected[{static_cast<long>(i), -1L}] = r[i] - z[i];
  }
  std::ifstream csv(dir + "/contact_network.csv");
  std::string line;
  std::getline(csv, line);
  std::size_t rows = 0;
  while (std::getline(csv, line)) {
    long a = 0, b = 0;
    double c[8];
    ASSERT_EQ(std::sscanf(line.c_str(), "%ld,%ld,%lf,%lf,%lf,%lf,%lf,%lf,%lf,%lf", &a, &b, &c[0],
                          &c[1], &c[2], &c[3], &c[4], &c[5], &c[6], &c[7]),
              10)
        << line;
    ++rows;
    const auto it = expected.find({a, b});
    ASSERT_NE(it, expected.end()) << "listed but not touching (or listed twice): " << line;
    EXPECT_NEAR(c[6], it->second, 1e-17) << line;  // overlap (m)
    expected.erase(it);
  }
  std::printf("%d ranks: %zu contacts in contact_network.csv, %zu missing\n", comm.size(), rows,
              expected.size());
  EXPECT_GT(rows, 0u) << "no contact: the check would not discriminate";
  EXPECT_TRUE(expected.empty()) << expected.size() << " contacts missing, the first between "
                                << expected.begin()->first.first << " and "
                                << expected.begin()->first.second;
}

}  // namespace
}  // namespace sphdem

int main(int argc, char** argv) {
  return sphdem::run_mpi_gtests(argc, argv, sphdem::g_expected_ranks);
}
