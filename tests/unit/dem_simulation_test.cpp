// The DEM inside whole SPH-DEM steps (Simulation): a packed bed of free spheres on the
// wall, where every sphere has several contacts all the time.
#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "run/scene.hpp"
#include "run/simulation.hpp"

using namespace sphdem;

namespace {

// 20 x 20 x 3 spheres of 100 um on a simple-cubic lattice, neighbours 0.02 % of d
// apart, the bottom layer just above the wall: it lands within a few steps and then
// stays packed (~5 contacts per sphere), in a 2 mm water column.
const std::string kBed = R"(
name: bed
domain: {size: [0.002, 0.002, 0.002]}
species: [{name: glass, diameter: 1.0e-4, density: 2500}]
particles:
  - {type: lattice, species: glass, min: [0, 0, 0], max: [0.002, 0.002, 0.0003001], voidage: 0.4765}
contact: {stiffness: 100, restitution: 0.5}
startup: {relax_steps: 2}
)";

struct State {
  std::vector<double> x, y, z, vx, vy, vz;  // by sphere id
};

// A few thousand spheres per pass: an OpenMP team only adds wake-up latency on a loaded
// 2-core machine (as in contact_test), so these runs are serial.
struct SerialOpenMP {
  int saved = omp_get_max_threads();
  SerialOpenMP() { omp_set_num_threads(1); }
  ~SerialOpenMP() { omp_set_num_threads(saved); }
};

State run(const Scene& sc, int steps, int sort_interval) {
  const SerialOpenMP serial;
  Simulation sim(sc);
  sim.set_sort_interval(sort_interval);
  sim.relax();
  for (int k = 0; k < steps; ++k) sim.step();
  const DemParticles& s = sim.spheres();
  State st;
  for (auto* v : {&st.x, &st.y, &st.z, &st.vx, &st.vy, &st.vz}) v->assign(s.n_owned, 0.0);
  for (std::size_t i = 0; i < s.n_owned; ++i) {
    const auto id = static_cast<std::size_t>(s.id[i]);
    st.x[id] = s.x[i];
    st.y[id] = s.y[i];
    st.z[id] = s.z[i];
    st.vx[id] = s.vx[i];
    st.vy[id] = s.vy[i];
    st.vz[id] = s.vz[i];
  }
  return st;
}

// Largest difference in position and in velocity, by id, across the periodic faces.
std::pair<double, double> difference(const State& a, const State& b, double L) {
  double dx = 0, dv = 0;
  for (std::size_t i = 0; i < a.x.size(); ++i) {
    auto per = [&](double p, double q) { return std::abs(std::remainder(p - q, L)); };
    dx = std::max({dx, per(a.x[i], b.x[i]), per(a.y[i], b.y[i]), std::abs(a.z[i] - b.z[i])});
    dv = std::max({dv, std::abs(a.vx[i] - b.vx[i]), std::abs(a.vy[i] - b.vy[i]), std::abs(a.vz[i] - b.vz[i])});
  }
  return {dx, dv};
}

}  // namespace

// The owned particles are re-sorted into cell order every 20 steps; the contact list and
// the sphere halo must follow (they were left pointing at the old order for the DEM
// sub-steps of the first half-step after a sort, which lost contacts). Sorting every
// step, every 7 steps or never must give the same bed up to round-off (the order of the
// force sums changes): positions to 1e-9 of d.
TEST(DemInSimulation, BedDoesNotDependOnHowOftenParticlesAreSorted) {
  const Scene sc = load_scene_text(kBed, "bed.yaml");
  const int steps = 20;
  const State never = run(sc, steps, 1000000), every = run(sc, steps, 1), seventh = run(sc, steps, 7);
  const double d = sc.species[0].diameter, L = sc.box.length(0);
  double depth = 0;  // the bed has landed: the bottom layer presses into the wall
  for (double z : never.z) depth = std::max(depth, 0.5 * d - z);
  EXPECT_GT(depth, 1e-6 * d);
  for (const State* st : {&every, &seventh}) {
    const auto [dx, dv] = difference(never, *st, L);
    std::printf("sorted every %s: max |dx| = %.3g d, max |dv| = %.3g m/s\n", st == &every ? "step" : "7 steps",
                dx / d, dv);
    EXPECT_LT(dx, 1e-9 * d);
    EXPECT_LT(dv, 1e-9);
  }
}
