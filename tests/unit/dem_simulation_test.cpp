// The DEM inside whole SPH-DEM steps (Simulation): a packed bed of free spheres on the
// wall, where every sphere has several contacts all the time.
#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "propagator/simulation.hpp"
#include "scene/scene.hpp"

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

const char* const kFriction =
    "contact.tangential={model: linear_history, friction: 0.5, restitution: 0.5}";
const char* const kRolling = "contact.rolling={model: epsd, friction: 0.1}";
// the bed released sliding sideways: the wall's friction stops the bottom layer first
const char* const kSliding = "particles.0.velocity=[0.005, 0.002, 0]";

struct State {
  std::vector<double> x, y, z, vx, vy, vz, wx, wy, wz;  // by sphere id
  std::size_t records = 0;                              // contact history records
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
  for (auto* v : {&st.x, &st.y, &st.z, &st.vx, &st.vy, &st.vz, &st.wx, &st.wy, &st.wz})
    v->assign(s.n_owned, 0.0);
  for (std::size_t i = 0; i < s.n_owned; ++i) {
    const auto id = static_cast<std::size_t>(s.id[i]);
    st.x[id] = s.x[i];
    st.y[id] = s.y[i];
    st.z[id] = s.z[i];
    st.vx[id] = s.vx[i];
    st.vy[id] = s.vy[i];
    st.vz[id] = s.vz[i];
    st.wx[id] = s.wx[i];
    st.wy[id] = s.wy[i];
    st.wz[id] = s.wz[i];
  }
  const ContactHistory& h = sim.contact_history();
  for (const auto* v : {&h.pair, &h.wall})
    for (const ContactState& c : *v) st.records += c.active();
  return st;
}

// Largest difference in position and in velocity, by id, across the periodic faces.
std::array<double, 3> difference(const State& a, const State& b, double L) {
  double dx = 0, dv = 0, dw = 0;
  for (std::size_t i = 0; i < a.x.size(); ++i) {
    auto per = [&](double p, double q) { return std::abs(std::remainder(p - q, L)); };
    dx = std::max({dx, per(a.x[i], b.x[i]), per(a.y[i], b.y[i]), std::abs(a.z[i] - b.z[i])});
    dv = std::max({dv, std::abs(a.vx[i] - b.vx[i]), std::abs(a.vy[i] - b.vy[i]),
                   std::abs(a.vz[i] - b.vz[i])});
    dw = std::max({dw, std::abs(a.wx[i] - b.wx[i]), std::abs(a.wy[i] - b.wy[i]),
                   std::abs(a.wz[i] - b.wz[i])});
  }
  return {dx, dv, dw};
}

}  // namespace

// The owned particles are re-sorted into cell order every 20 steps; the contact list and
// the sphere halo must follow (they were left pointing at the old order for the DEM
// sub-steps of the first half-step after a sort, which lost contacts). Sorting every
// step, every 7 steps or never must give the same bed up to round-off (the order of the
// force sums changes): positions to 1e-9 of d (measured 2e-15 d; before the fix the
// 7-step run was off by 5e-7 d and 2e-5 m/s).
TEST(DemInSimulation, BedDoesNotDependOnHowOftenParticlesAreSorted) {
  const Scene sc = load_scene_text(kBed, "bed.yaml");
  const int steps = 20;
  const State never = run(sc, steps, 1000000), every = run(sc, steps, 1),
              seventh = run(sc, steps, 7);
  const double d = sc.species[0].diameter, L = sc.box.length(0);
  double depth = 0;  // the bed has landed: the bottom layer presses into the wall
  for (double z : never.z) depth = std::max(depth, 0.5 * d - z);
  EXPECT_GT(depth, 1e-6 * d);
  EXPECT_EQ(never.records, 0u);  // normal contacts only: no history, no spin
  for (const State* st : {&every, &seventh}) {
    const auto [dx, dv, dw] = difference(never, *st, L);
    std::printf("sorted every %s: max |dx| = %.3g d, max |dv| = %.3g m/s\n",
                st == &every ? "step" : "7 steps", dx / d, dv);
    EXPECT_LT(dx, 1e-9 * d);
    EXPECT_LT(dv, 1e-9);
    EXPECT_EQ(dw, 0.0);
  }
}

// The contact history follows the spheres through a sort: saved by id pair before the
// permutation, loaded into the rebuilt list after. Two runs of a bed released sliding
// sideways (friction and rolling resistance on) are the same bits until one of them
// sorts (the first sort, lattice order -> cell order, moves nearly every sphere); over the
// step that starts with it only the order of the force sums differs, so every contact's
// record must agree to round-off. (A frictional sliding bed amplifies round-off ~x8
// per SPH step, so longer comparisons say little; a lost or misplaced history is an
// O(1) difference.)
TEST(DemInSimulation, ContactHistoryFollowsTheSpheresThroughASort) {
  const Scene sc = load_scene_text(kBed, "bed.yaml", {kFriction, kRolling, kSliding});
  const SerialOpenMP serial;
  Simulation a(sc), b(sc);
  a.set_sort_interval(1000000);
  b.set_sort_interval(10);  // the 10th advance (2 relaxation steps + 8) starts with a sort
  a.relax();
  b.relax();
  for (int k = 0; k < 7; ++k) {
    a.step();
    b.step();
  }
  auto same_records = [](const std::vector<ContactHistory::Record>& p,
                         const std::vector<ContactHistory::Record>& q, double rel) {
    ASSERT_EQ(p.size(), q.size());
    double xi_max = 0, mr_max = 0, dxi = 0, dmr = 0;
    for (std::size_t r = 0; r < p.size(); ++r) {
      ASSERT_EQ(p[r].id, q[r].id);
      ASSERT_EQ(p[r].partner, q[r].partner);
      for (int d = 0; d < 3; ++d) {
        xi_max = std::max(xi_max, std::abs(p[r].state.xi[d]));
        mr_max = std::max(mr_max, std::abs(p[r].state.mr[d]));
        dxi = std::max(dxi, std::abs(p[r].state.xi[d] - q[r].state.xi[d]));
        dmr = std::max(dmr, std::abs(p[r].state.mr[d] - q[r].state.mr[d]));
      }
    }
    std::printf("%zu records: max |xi| %.3g m, |d xi| %.3g; max |M_r| %.3g N m, |d M_r| %.3g\n",
                p.size(), xi_max, dxi, mr_max, dmr);
    EXPECT_GT(xi_max, 0.0);
    EXPECT_GT(mr_max, 0.0);
    EXPECT_LE(dxi, rel * xi_max);
    EXPECT_LE(dmr, rel * mr_max);
  };
  same_records(a.contact_records(), b.contact_records(), 0.0);  // before the sort: identical
  a.step();
  b.step();
  std::size_t moved = 0;
  for (std::size_t i = 0; i < a.spheres().n_owned; ++i)
    moved += a.spheres().id[i] != b.spheres().id[i];
  EXPECT_GT(moved, a.spheres().n_owned / 2);  // b's arrays are in another order
  same_records(a.contact_records(), b.contact_records(), 1e-9);
}

// A rigid (constant-porosity) block stays translational with friction on: its spheres
// never spin, while a free sphere landing on it does.
TEST(DemInSimulation, RigidGroupsDoNotRotate) {
  const std::string yaml = R"(
name: rigid_block_and_a_sphere
domain: {size: [0.002, 0.002, 0.002]}
species: [{name: glass, diameter: 1.0e-4, density: 2500}]
particles:
  - {type: lattice, species: glass, min: [0, 0, 0], max: [0.002, 0.002, 0.0001001], voidage: 0.4765, rigid: true}
  - {type: single, species: glass, position: [0.00102, 0.00103, 0.0001434], velocity: [0.01, 0, 0]}
contact: {stiffness: 100, restitution: 0.5}
startup: {relax_steps: 2}
)";
  const Scene sc = load_scene_text(yaml, "rigid.yaml", {kFriction, kRolling});
  const SerialOpenMP serial;
  Simulation sim(sc);
  sim.relax();
  double free_spin = 0, rigid_spin = 0, rigid_torque = 0;
  for (int k = 0; k < 10; ++k) {
    sim.step();
    const DemParticles& s = sim.spheres();
    for (std::size_t i = 0; i < s.n_owned; ++i) {
      const double w = std::abs(s.wx[i]) + std::abs(s.wy[i]) + std::abs(s.wz[i]);
      if (s.rigid_group[i] >= 0) {
        rigid_spin = std::max(rigid_spin, w);
        rigid_torque = std::max(rigid_torque, std::abs(s.tx[i]) + std::abs(s.ty[i]));
      } else {
        free_spin = std::max(free_spin, w);
      }
    }
  }
  EXPECT_EQ(rigid_spin, 0.0);
  EXPECT_GT(rigid_torque, 0.0);  // friction acts on the block (the sphere's, the wall's)
  EXPECT_GT(free_spin, 0.0);
}

// With tangential friction the DEM step also resolves the sticking contact's period
// pi sqrt(2/7 m12 / k_t), shorter than the normal one once k_t/k > 2/7.
TEST(DemInSimulation, TimeStepResolvesTheTangentialSpring) {
  const Scene normal = load_scene_text(kBed, "bed.yaml");
  const Scene soft = load_scene_text(kBed, "bed.yaml", {kFriction});
  const Scene stiff = load_scene_text(
      kBed, "bed.yaml",
      {"contact.tangential={model: linear_history, friction: 0.5, stiffness_ratio: 1}"});
  const double m = 2500 * M_PI * 1e-12 / 6, k = 100;
  const Simulation a(normal), b(soft), c(stiff);
  const double tc_t =
      M_PI * std::sqrt(2.0 / 7.0 * 0.5 * m / (2.0 / 7.0 * k));  // the undamped normal period
  EXPECT_NEAR(b.contact_time(), std::min(a.contact_time(), tc_t), 1e-12 * tc_t);
  EXPECT_NEAR(b.contact_time(), a.contact_time(),
              0.03 * a.contact_time());  // the damped normal one is longer
  EXPECT_NEAR(c.contact_time(), M_PI * std::sqrt(2.0 / 7.0 * 0.5 * m / k), 1e-12 * tc_t);
  EXPECT_LT(c.dt_dem_max(), a.dt_dem_max());
}

// The sub-step also resolves the drag relaxation at the spheres' own voidage (issue 15):
// in the bed (eps ~0.5) Di Felice's drag at Re -> 0, 2.88 pi mu d eps^-3.7 on u_s =
// eps (u_f - v), relaxes a sphere at c eps / m, several times the Stokes rate 18 mu /
// (rho_p d^2) that the scene's dt_max allows for (2.6 times here, measured). With a spring soft
// enough that the contacts do not bind, the sub-step must stay below 0.1 m / (c eps) of the sphere
// that relaxes fastest. (The wiring: the rate read from the spheres' own voidage.)
TEST(DemInSimulation, SubStepResolvesTheDragRelaxationInABed) {
  const SerialOpenMP serial;
  // ten times water's viscosity: the drag bound below the SPH step's half
  const Scene sc = load_scene_text(
      kBed, "bed.yaml", {"contact.stiffness=0.01", "drag.law=di_felice", "fluid.viscosity=8.9e-3"});
  Simulation sim(sc);
  sim.relax();
  sim.step();
  sim.step();
  const DemParticles& s = sim.spheres();
  const double mu = sc.fluid.viscosity, d = 1e-4, m = 2500 * M_PI * d * d * d / 6;
  double rate = 0.0;
  for (std::size_t j = 0; j < s.n_owned; ++j) {
    const double e = s.eps[j];
    rate = std::max(rate, 23.04 / 24.0 * 3 * M_PI * mu * d * std::pow(e, -3.7) * e / m);
  }
  const double stokes_rate = 18 * mu / (2500 * d * d);
  const double h = sim.dt_sph() / sim.dem_substeps();
  std::printf("fastest drag relaxation %.3g /s (Stokes %.3g /s): sub-step %.3g s, dt_max %.3g s\n",
              rate, stokes_rate, h, sim.dt_dem_max());
  EXPECT_GT(rate, 2 * stokes_rate);         // the bed's drag is what binds here
  EXPECT_GT(sim.dt_dem_max(), 0.2 / rate);  // and dt_max alone would not resolve it
  EXPECT_LE(h, 0.1 / rate * (1 + 1e-3));    // the Re -> 0 rate is the smallest the law gives
  EXPECT_GT(h, 0.5 * 0.1 / rate);           // no finer than it must be
}
