// time.multirate (DemSubstepper): the spheres out of contact take the fluid's step, the
// others the contact sub-steps. A dilute suspension with two pairs on collision courses and
// a sphere falling onto the wall, stepped with and without it.
#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "propagator/simulation.hpp"
#include "scene/scene.hpp"

using namespace sphdem;

namespace {

// ~300 spheres of 100 um at voidage 0.96 in a 1.6 x 1.6 x 3 mm periodic water column; two
// pairs closing head-on at 4 cm/s and one obliquely (half a diameter off centre; they meet
// within the run), one sphere 2 um above the wall and one sliding onto it.
const std::string kSuspension = R"(
name: multirate
domain: {size: [0.0016, 0.0016, 0.003]}
fluid: {density: 1000, viscosity: 8.9e-4, spacing: 2.0e-4}
species: [{name: glass, diameter: 1.0e-4, density: 2500}]
particles:
  - {type: random, species: glass, min: [0, 0, 0.0005], max: [0.0016, 0.0016, 0.0025], voidage: 0.96, seed: 3}
  - {type: single, species: glass, position: [0.0002, 0.0002, 0.00015], velocity: [0.02, 0, 0]}
  - {type: single, species: glass, position: [0.00032, 0.0002, 0.00015], velocity: [-0.02, 0, 0]}
  - {type: single, species: glass, position: [0.0012, 0.0012, 0.0001], velocity: [0, 0, -0.02]}
  - {type: single, species: glass, position: [0.0012, 0.0012, 0.000221], velocity: [0, 0, 0.02]}
  - {type: single, species: glass, position: [0.0008, 0.0004, 0.000052], velocity: [0, 0, 0]}
  - {type: single, species: glass, position: [0.0004, 0.0012, 0.00015], velocity: [0.02, 0, 0]}
  - {type: single, species: glass, position: [0.00052, 0.00125, 0.00015], velocity: [-0.02, 0, 0]}
  - {type: single, species: glass, position: [0.0012, 0.0004, 0.000056], velocity: [0.01, 0, -0.01]}
drag: {law: di_felice}
contact: {stiffness: 100, damping: 0}
startup: {relax_steps: 2}
)";

// The contact model with friction and rolling resistance (the spheres spin).
const std::vector<std::string> kFriction = {
    "contact.tangential.model=linear_history", "contact.tangential.friction=0.5",
    "contact.rolling.model=epsd", "contact.rolling.friction=0.1"};
constexpr std::size_t kMet = 8;  // the last spheres of the scene: they meet a partner or the wall

std::vector<std::string> with(std::vector<std::string> a, const std::vector<std::string>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

struct Spheres {
  std::vector<double> x, y, z, vx, vy, vz, wx, wy, wz;  // by sphere id
  MultirateTally tally;
  double largest_overlap = 0;    // over the run, in diameters
  double time = 0, vz_mean = 0;  // simulated time of the run, mean settling velocity
  int steps = 0;
};

Spheres run(const std::vector<std::string>& overrides, int steps = 40) {
  const int threads = omp_get_max_threads();
  omp_set_num_threads(1);  // a few hundred spheres: one thread, bit-reproducible
  Simulation sim(load_scene_text(kSuspension, "multirate.yaml", overrides));
  sim.relax();
  Spheres out;
  for (int k = 0; k < steps; ++k) {
    sim.step();
    const DemParticles& s = sim.spheres();
    for (std::size_t j = 0; j < s.n_owned; ++j)
      out.largest_overlap = std::max(out.largest_overlap, s.overlap_max[j] / (2 * s.radius[j]));
  }
  omp_set_num_threads(threads);
  const DemParticles& s = sim.spheres();
  for (auto* v : {&out.x, &out.y, &out.z, &out.vx, &out.vy, &out.vz, &out.wx, &out.wy, &out.wz})
    v->assign(s.n_owned, 0.0);
  for (std::size_t j = 0; j < s.n_owned; ++j) {
    const auto id = static_cast<std::size_t>(s.id[j]);
    out.x[id] = s.x[j];
    out.y[id] = s.y[j];
    out.z[id] = s.z[j];
    out.vx[id] = s.vx[j];
    out.vy[id] = s.vy[j];
    out.vz[id] = s.vz[j];
    out.wx[id] = s.wx[j];
    out.wy[id] = s.wy[j];
    out.wz[id] = s.wz[j];
  }
  out.tally = sim.multirate_tally();
  out.time = sim.time();
  out.steps = steps;
  for (std::size_t j = 0; j < s.n_owned; ++j) out.vz_mean += s.vz[j] / s.n_owned;
  return out;
}

double periodic(double d, double L) {
  return std::abs(std::remainder(d, L));
}

}  // namespace

// The largest differences between two runs: of the random suspension's spheres and of
// the ones that met a partner or the wall; and the random ones' relative difference in
// mean settling velocity.
struct Differences {
  double dx_free = 0, dvz_mean = 0, dx_met = 0, dv_met = 0, dw_met = 0;
};

Differences differences(const Spheres& a, const Spheres& b) {
  const double L = 0.0016;
  const std::size_t n_random = a.x.size() - kMet;
  Differences r;
  double vz_a = 0.0, vz_b = 0.0;
  for (std::size_t i = 0; i < a.x.size(); ++i) {
    const double dx = std::max(
        {periodic(a.x[i] - b.x[i], L), periodic(a.y[i] - b.y[i], L), std::abs(a.z[i] - b.z[i])});
    const double dv = std::max(
        {std::abs(a.vx[i] - b.vx[i]), std::abs(a.vy[i] - b.vy[i]), std::abs(a.vz[i] - b.vz[i])});
    const double dw = std::max(
        {std::abs(a.wx[i] - b.wx[i]), std::abs(a.wy[i] - b.wy[i]), std::abs(a.wz[i] - b.wz[i])});
    if (i < n_random) {
      r.dx_free = std::max(r.dx_free, dx);
      vz_a += a.vz[i];
      vz_b += b.vz[i];
    } else {
      r.dx_met = std::max(r.dx_met, dx);
      r.dv_met = std::max(r.dv_met, dv);
      r.dw_met = std::max(r.dw_met, dw);
    }
  }
  r.dvz_mean = std::abs(vz_a / vz_b - 1.0);
  return r;
}

// With it, a free sphere takes one velocity-Verlet step of T = dt/2 under its drag where it
// took ~25: on the drag's relaxation (time tau = rho_p d^2 / 18 mu, 1.56 ms) that moves its
// velocity by O((T / tau)^2) of itself, and its path by as much of the way it went. The
// spheres that met a partner or the wall are sub-stepped in both runs: they differ by no
// more than refining the contact sub-step by a quarter moves them (their spin too, with
// friction). It did run (most half steps, a few spheres sub-stepped) and the collisions did
// happen.
// Returns the run with every sphere sub-stepped.
Spheres expect_multirate_matches_substepping(const std::vector<std::string>& model) {
  const Spheres on = run(model);
  const Spheres off = run(with(model, {"time.multirate=false"}));
  const Spheres finer = run(with(model, {"time.multirate=false", "time.dem_steps_per_contact=25"}));
  EXPECT_EQ(on.x.size(), off.x.size());
  if (on.x.size() != off.x.size()) return off;
  EXPECT_GE(on.tally.multirate, on.tally.half_steps * 9 / 10);
  EXPECT_EQ(on.tally.sent_back, 0);
  EXPECT_LT(on.tally.near_spheres, 0.1 * on.tally.owned_spheres);
  EXPECT_GT(on.tally.near_spheres, 0.0);
  EXPECT_EQ(off.tally.multirate, 0);
  EXPECT_GT(on.largest_overlap, 1e-4);  // the pairs met (2.47: ~3e-4 d at 4 cm/s)
  const double T = 0.5 * off.time / off.steps, tau = 2500.0 * 1e-8 / (18.0 * 8.9e-4);
  const double relative = (T / tau) * (T / tau);
  const Differences multirate = differences(on, off), substep = differences(finer, off);
  EXPECT_LT(multirate.dvz_mean, relative);
  EXPECT_LT(multirate.dx_free, relative * std::abs(off.vz_mean) * off.time);
  EXPECT_LT(multirate.dx_met, 2.0 * substep.dx_met);
  EXPECT_LT(multirate.dv_met, 2.0 * substep.dv_met);
  EXPECT_GT(substep.dx_met, 0.0);
  EXPECT_LE(multirate.dw_met, 2.0 * substep.dw_met);
  return off;
}

TEST(Multirate, MatchesSubsteppingEverySphere) {
  expect_multirate_matches_substepping({});
}

// With friction and rolling resistance the spheres out of contact keep their spin (no
// torque on them) and the near ones sub-step it with their contact history.
TEST(Multirate, MatchesSubsteppingEverySphereWithFriction) {
  const Spheres off = expect_multirate_matches_substepping(kFriction);
  double w_met = 0.0;  // the oblique pair and the sliding sphere spin
  for (std::size_t i = off.wx.size() - kMet; i < off.wx.size(); ++i)
    w_met = std::max({w_met, std::abs(off.wx[i]), std::abs(off.wy[i]), std::abs(off.wz[i])});
  EXPECT_GT(w_met, 1.0);  // rad/s
}

// A margin of 0 sends every half step back (any motion reaches it): what remains must be
// the run without it, bit for bit, so the state saved and put back is the whole of it
// (with friction: the spin, the torque and the near spheres' contact history too).
void expect_sent_back_is_substepped(const std::vector<std::string>& model) {
  const Spheres back = run(with(model, {"time.multirate_margin=0"}));
  const Spheres off = run(with(model, {"time.multirate=false"}));
  EXPECT_GT(back.tally.sent_back, 0);
  EXPECT_EQ(back.tally.multirate, 0);
  EXPECT_EQ(back.x, off.x);
  EXPECT_EQ(back.y, off.y);
  EXPECT_EQ(back.z, off.z);
  EXPECT_EQ(back.vx, off.vx);
  EXPECT_EQ(back.vy, off.vy);
  EXPECT_EQ(back.vz, off.vz);
  EXPECT_EQ(back.wx, off.wx);
  EXPECT_EQ(back.wy, off.wy);
  EXPECT_EQ(back.wz, off.wz);
}

TEST(Multirate, SentBackHalfStepsAreTheSubsteppedOnes) {
  expect_sent_back_is_substepped({});
}

TEST(Multirate, SentBackHalfStepsAreTheSubsteppedOnesWithFriction) {
  expect_sent_back_is_substepped(kFriction);
}
