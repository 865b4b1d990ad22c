// Linear spring-dashpot contacts (solver/dem/contact_model.hpp, contact_forces.hpp;
// physics.md §2, thesis eq. 2.36-2.47). Collisions are integrated here with a small
// velocity-Verlet loop, and the measured contact time, restitution and largest overlap
// are compared with the damped oscillator written out in this file and with
// ContactClosedForm.
#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <tuple>
#include <vector>

#include "dem/contact_forces.hpp"
#include "dem/contact_model.hpp"
#include "dem/dem_particles.hpp"
#include "domain/cell_list.hpp"

namespace {

using namespace sphdem;

constexpr double kPi = 3.14159265358979323846;
// Thesis suspension particles (§5) and the peers' contact check (shared/peers/README.md).
constexpr double kD = 100e-6, kR = 0.5 * kD, kRhoP = 2500.0, kK = 10.0, kV0 = 0.01;
const double kMass = kRhoP * kPi * kD * kD * kD / 6.0;
constexpr double kSkin = 0.3 * kD;

// ---- the damped oscillator m12 d2(delta)/dt2 = -k delta - beta d(delta)/dt, delta(0) = 0,
// d(delta)/dt(0) = v: delta(t) = v/omega e^(-eta t) sin(omega t), written out independently.
struct Oscillator {
  double omega0, eta, omega;
  Oscillator(double k, double beta, double m12)
      : omega0(std::sqrt(k / m12)),
        eta(beta / (2.0 * m12)),
        omega(std::sqrt(k / m12 - eta * eta)) {}
  double contact_time() const { return kPi / omega; }  // delta returns to 0 at omega t = pi
  double restitution() const {                         // -delta'(t_c)/v = e^(-eta pi/omega)
    return std::exp(-eta * contact_time());
  }
  double max_overlap(double v) const {  // delta' = 0 at tan(omega t) = omega/eta
    const double t = std::atan2(omega, eta) / omega;
    return v / omega * std::exp(-eta * t) * std::sin(omega * t);
  }
  // With the force clipped at 0 (never attractive), the contact ends when k delta + beta delta' =
  // 0, i.e. delta'' = 0, at omega t = pi - phi with tan(phi) = 2 eta omega/(omega^2 - eta^2); from
  // then on the spheres fly apart at -delta'(t).
  double clipped_restitution() const {
    const double phi = std::atan2(2.0 * eta * omega, omega * omega - eta * eta);
    const double t = (kPi - phi) / omega;
    return std::exp(-eta * t) * (std::cos(phi) + eta / omega * std::sin(phi));
  }
};

// Dashpot that gives restitution e for reduced mass m12: e = exp(-pi eta/omega) (2.46)
// solved for eta with omega^2 = k/m12 - eta^2.
double beta_for_restitution(double e, double k, double m12) {
  const double a = -std::log(e) / kPi;  // eta/omega
  return 2.0 * m12 * std::sqrt(k / m12) * a / std::sqrt(1.0 + a * a);
}

// ---- a tiny DEM driver -------------------------------------------------------------

DemParticles spheres(std::size_t n) {
  DemParticles s;
  s.resize(n);
  s.n_owned = n;
  std::fill(s.radius.begin(), s.radius.end(), kR);
  std::fill(s.mass.begin(), s.mass.end(), kMass);
  return s;
}

// One or two spheres per step: an OpenMP team per step only adds wake-up latency, which
// on a loaded 2-core machine made this binary take 15 s. Serial for the collisions.
struct SerialOpenMP {
  int saved = omp_get_max_threads();
  SerialOpenMP() { omp_set_num_threads(1); }
  ~SerialOpenMP() { omp_set_num_threads(saved); }
};

struct Measured {
  double contact_time = 0;  // first touch (free flight, exact) to release (interpolated)
  double restitution = 0;   // post/pre relative normal speed
  double max_overlap = 0;   // largest DemParticles::overlap_max
  double max_pull = 0;      // largest attractive normal force seen (0 if never attractive)
};

// Integrates until the overlap ends. `overlap(s)` and `normal_force(s)` (positive =
// repulsive) define the geometry; the spheres start apart and close at speed v_rel.
template <class Overlap, class NormalForce>
Measured collide(DemParticles& s, const LinearSpringDashpot& law, double wall_z, double dt,
                 double v_rel, Overlap overlap, NormalForce normal_force) {
  const SerialOpenMP serial;
  CellList cells;
  cells.build(s.x.data(), s.y.data(), s.z.data(), s.size(), 2.0 * kR + kSkin);
  ContactNeighbourList list;
  list.build(s, cells, kSkin);  // spheres move < 1 µm in total: one build suffices

  const double t_touch = -overlap(s) / v_rel;  // free flight until then
  auto kick = [&](double h) {
    for (std::size_t i = 0; i < s.n_owned; ++i) {
      s.vx[i] += h * s.cx[i] / s.mass[i];
      s.vy[i] += h * s.cy[i] / s.mass[i];
      s.vz[i] += h * s.cz[i] / s.mass[i];
    }
  };
  Measured m;
  compute_contact_forces(s, list, law, HaloImages{s.n_owned}, wall_z);
  double t = 0, prev = overlap(s), t_release = -1;
  for (int step = 0; step < 100000 && t_release < 0; ++step) {
    kick(0.5 * dt);
    for (std::size_t i = 0; i < s.n_owned; ++i) {
      s.x[i] += dt * s.vx[i];
      s.y[i] += dt * s.vy[i];
      s.z[i] += dt * s.vz[i];
    }
    // the dashpot needs v(t + dt): predict it as v(t + dt/2) + a(t) dt/2 (Groot & Warren 1997,
    // lambda = 1); with the half-step velocity alone the error would be first order, ~eta dt/2
    const std::vector<double> vx = s.vx, vy = s.vy, vz = s.vz;
    kick(0.5 * dt);
    compute_contact_forces(s, list, law, HaloImages{s.n_owned}, wall_z);
    s.vx = vx, s.vy = vy, s.vz = vz;
    kick(0.5 * dt);
    t += dt;
    const double now = overlap(s);
    m.max_overlap =
        std::max(m.max_overlap, *std::max_element(s.overlap_max.begin(), s.overlap_max.end()));
    m.max_pull = std::max(m.max_pull, -normal_force(s));
    if (prev > 0 && now <= 0) t_release = t - dt * now / (now - prev);  // linear zero crossing
    prev = now;
  }
  m.contact_time = t_release - t_touch;
  return m;
}

// Two equal spheres on the x axis approaching head-on at +-v/2; returns the measurement.
Measured head_on(const LinearSpringDashpot& law, double dt) {
  DemParticles s = spheres(2);
  const double gap = kV0 * 5.5 * dt;  // touch mid-step, 5.5 steps in
  s.x = {-kR - 0.5 * gap, kR + 0.5 * gap};
  s.z = {1e-3, 1e-3};  // far above the wall at z = 0
  s.vx = {0.5 * kV0, -0.5 * kV0};
  Measured m = collide(
      s, law, 0.0, dt, kV0, [](const DemParticles& p) { return 2.0 * kR - (p.x[1] - p.x[0]); },
      [](const DemParticles& p) { return -p.cx[0]; });  // repulsion pushes sphere 0 towards -x
  m.restitution = (s.vx[1] - s.vx[0]) / kV0;
  return m;
}

// One sphere falling (no gravity) onto the wall z = 0 at speed v.
Measured wall_impact(const LinearSpringDashpot& law, double dt) {
  DemParticles s = spheres(1);
  s.z = {kR + kV0 * 5.5 * dt};
  s.vz = {-kV0};
  Measured m = collide(
      s, law, 0.0, dt, kV0, [](const DemParticles& p) { return kR - p.z[0]; },
      [](const DemParticles& p) { return p.cz[0]; });
  m.restitution = s.vz[0] / kV0;
  return m;
}

LinearSpringDashpot dashpot(double beta, bool clip = false) {
  LinearSpringDashpot law;
  law.k = kK;
  law.beta = beta;
  law.clip_attraction = clip;
  return law;
}
LinearSpringDashpot restitution(double e, bool clip = false) {
  LinearSpringDashpot law;
  law.k = kK;
  law.restitution = e;
  law.clip_attraction = clip;
  return law;
}

// Time step t_c/200, omega dt = pi/200. Velocity Verlet with the predicted velocity is
// second order: t_c, e and the largest overlap err by O((omega dt)^2) = 2.5e-4 times a
// small constant (measured <= 6e-5, falling 4x per halving of dt); sampling the peak
// overlap at discrete steps costs <= (omega dt/2)^2/2 = 3e-5. Hence 2e-4 relative.
constexpr double kStepsPerContact = 200.0;
constexpr double kTolTime = 2e-4, kTolRestitution = 2e-4, kTolOverlap = 2e-4;

// Measured collision of reduced mass m12 and dashpot beta at approach speed v_rel against
// the independent Oscillator and the header's ContactClosedForm (2.44, 2.46, 2.47).
void expect_matches(const Measured& m, double beta, double m12, double v_rel) {
  const Oscillator osc(kK, beta, m12);
  const ContactClosedForm cf(kK, beta, m12);
  // closed forms against each other: same quantities by different formulas (a few ulps)
  EXPECT_NEAR(cf.contact_time(), osc.contact_time(), 1e-12 * osc.contact_time());
  EXPECT_NEAR(cf.restitution(), osc.restitution(), 1e-12);
  EXPECT_NEAR(cf.max_overlap(v_rel), osc.max_overlap(v_rel), 1e-12 * osc.max_overlap(v_rel));
  // the integrated collision against both
  for (const auto& [tc, e, dmax] :
       {std::tuple{osc.contact_time(), osc.restitution(), osc.max_overlap(v_rel)},
        std::tuple{cf.contact_time(), cf.restitution(), cf.max_overlap(v_rel)}}) {
    EXPECT_NEAR(m.contact_time, tc, kTolTime * tc);
    EXPECT_NEAR(m.restitution, e, kTolRestitution * e);
    EXPECT_NEAR(m.max_overlap, dmax, kTolOverlap * dmax);
  }
}

// ---- collisions -------------------------------------------------------------------

constexpr double kBeta = 2e-5;  // kg/s: eta/omega0 = 0.12 pair, 0.088 wall; e = 0.68 / 0.76

TEST(ContactCollision, HeadOnWithDashpot) {
  const Oscillator osc(kK, kBeta, 0.5 * kMass);  // m12 = m/2
  const Measured m = head_on(dashpot(kBeta), osc.contact_time() / kStepsPerContact);
  expect_matches(m, kBeta, 0.5 * kMass, kV0);
}

TEST(ContactCollision, WallImpactWithDashpot) {
  const Oscillator osc(kK, kBeta, kMass);  // wall: m12 = m
  const Measured m = wall_impact(dashpot(kBeta), osc.contact_time() / kStepsPerContact);
  expect_matches(m, kBeta, kMass, kV0);
}

TEST(ContactCollision, UndampedIsElastic) {
  const Oscillator osc(kK, 0.0, 0.5 * kMass);
  const Measured m = head_on(dashpot(0.0), osc.contact_time() / kStepsPerContact);
  expect_matches(m, 0.0, 0.5 * kMass, kV0);
  EXPECT_NEAR(m.restitution, 1.0, kTolRestitution);
}

// Restitution given: beta chosen per pair from m12 (LIGGGHTS-style), so the wall
// (m12 = m) and a pair (m12 = m/2) both bounce with e; the peers measured 0.8998 / 0.9001.
TEST(ContactCollision, RestitutionGivenHoldsForPairAndWall) {
  const double e = 0.9;
  const LinearSpringDashpot law = restitution(e);
  for (double m12 : {0.5 * kMass, kMass}) {
    EXPECT_NEAR(law.beta_for(m12), beta_for_restitution(e, kK, m12),
                1e-12 * beta_for_restitution(e, kK, m12));
    EXPECT_NEAR(Oscillator(kK, law.beta_for(m12), m12).restitution(), e, 1e-12);
  }
  // the peers' table (shared/peers/README.md, 7 digits): beta = m_eff gamma_n
  EXPECT_NEAR(law.beta_for(0.5 * kMass), 5.423357e-6, 1e-12);
  EXPECT_NEAR(law.beta_for(kMass), 7.669786e-6, 1e-12);

  const Oscillator pair(kK, law.beta_for(0.5 * kMass), 0.5 * kMass),
      wall(kK, law.beta_for(kMass), kMass);
  const Measured mp = head_on(law, pair.contact_time() / kStepsPerContact);
  const Measured mw = wall_impact(law, wall.contact_time() / kStepsPerContact);
  expect_matches(mp, law.beta_for(0.5 * kMass), 0.5 * kMass, kV0);
  expect_matches(mw, law.beta_for(kMass), kMass, kV0);
  EXPECT_NEAR(mp.restitution, e, kTolRestitution * e);
  EXPECT_NEAR(mw.restitution, e, kTolRestitution * e);
  EXPECT_NEAR(mp.restitution, mw.restitution, kTolRestitution * e);
  // contact times differ by sqrt(2) (m12 = m/2 vs m)
  EXPECT_NEAR(mw.contact_time / mp.contact_time, std::sqrt(2.0), 2 * kTolTime * std::sqrt(2.0));
  // limits of beta_for: e >= 1 means no dashpot
  EXPECT_EQ(restitution(1.0).beta_for(kMass), 0.0);
}

// Without clipping the dashpot pulls the spheres together at the end of the contact
// (delta > 0, d(delta)/dt < -k delta/beta); with clip_attraction it never pulls, and the
// spheres leave earlier with a larger restitution (the clipped oscillator, see Oscillator).
TEST(ContactCollision, ClipAttraction) {
  const double e = 0.9;
  const Oscillator pair(kK, restitution(e).beta_for(0.5 * kMass), 0.5 * kMass);
  const Oscillator wall(kK, restitution(e).beta_for(kMass), kMass);
  const double scale = kK * pair.max_overlap(kV0);  // peak spring force

  const Measured free_p = head_on(restitution(e, false), pair.contact_time() / kStepsPerContact);
  const Measured free_w =
      wall_impact(restitution(e, false), wall.contact_time() / kStepsPerContact);
  // the pull at release is beta e v ~ 5e-8 N (pair), ~6 % of the peak spring force k delta_max
  EXPECT_GT(free_p.max_pull, 0.01 * scale);
  EXPECT_GT(free_w.max_pull, 0.01 * scale);

  const Measured clip_p = head_on(restitution(e, true), pair.contact_time() / kStepsPerContact);
  const Measured clip_w = wall_impact(restitution(e, true), wall.contact_time() / kStepsPerContact);
  EXPECT_LE(clip_p.max_pull, 0.0);
  EXPECT_LE(clip_w.max_pull, 0.0);
  // e_clipped = 0.90203 for e = 0.9, for pair and wall alike (depends on eta/omega only)
  EXPECT_NEAR(pair.clipped_restitution(), wall.clipped_restitution(), 1e-12);
  EXPECT_GT(pair.clipped_restitution(), e + 1e-3);
  EXPECT_NEAR(clip_p.restitution, pair.clipped_restitution(), kTolRestitution * e);
  EXPECT_NEAR(clip_w.restitution, wall.clipped_restitution(), kTolRestitution * e);

  // and the scalar law itself
  const LinearSpringDashpot on = restitution(e, true), off = restitution(e, false);
  const double beta = on.beta_for(kMass), delta = 1e-8, pulling_rate = -2.0 * kK * delta / beta;
  EXPECT_EQ(on.normal_force(delta, pulling_rate, beta), 0.0);
  EXPECT_NEAR(off.normal_force(delta, pulling_rate, beta), -kK * delta, 1e-12 * kK * delta);
  EXPECT_NEAR(on.normal_force(delta, 0.01, beta), kK * delta + beta * 0.01, 1e-15);  // (2.36)
}

// ---- action and reaction ------------------------------------------------------------

// Isolated overlapping pairs of unequal spheres with random geometry and velocities:
// the force on i is the exact negative of the force on j (the pair force is written
// antisymmetrically, contact_forces.hpp), so the sum is zero bitwise.
TEST(ContactForces, ActionReactionIsExact) {
  std::mt19937 gen(2024);
  std::uniform_real_distribution<double> u01(0.0, 1.0), sym(-1.0, 1.0);
  const std::size_t n_pairs = 200;
  DemParticles s = spheres(2 * n_pairs);
  for (std::size_t p = 0; p < n_pairs; ++p) {
    const std::size_t i = 2 * p, j = i + 1;
    s.radius[i] = kR * (0.5 + u01(gen));
    s.radius[j] = kR * (0.5 + u01(gen));
    s.mass[i] = kRhoP * 4.0 / 3.0 * kPi * std::pow(s.radius[i], 3);
    s.mass[j] = kRhoP * 4.0 / 3.0 * kPi * std::pow(s.radius[j], 3);
    // pairs 1 mm apart on a line, each well clear of the others and of the wall
    double nx = sym(gen), ny = sym(gen), nz = sym(gen);
    const double nn = std::sqrt(nx * nx + ny * ny + nz * nz);
    const double dist = (s.radius[i] + s.radius[j]) * (1.0 - 0.05 * u01(gen));  // up to 5 % overlap
    s.x[i] = 1e-3 * p + 1e-7 * sym(gen);
    s.y[i] = 1e-7 * sym(gen);
    s.z[i] = 1e-3 + 1e-7 * sym(gen);
    s.x[j] = s.x[i] + dist * nx / nn;
    s.y[j] = s.y[i] + dist * ny / nn;
    s.z[j] = s.z[i] + dist * nz / nn;
    for (std::size_t q : {i, j}) {
      s.vx[q] = 0.02 * sym(gen);
      s.vy[q] = 0.02 * sym(gen);
      s.vz[q] = 0.02 * sym(gen);
    }
  }
  CellList cells;
  cells.build(s.x.data(), s.y.data(), s.z.data(), s.size(), 2.0 * 1.5 * kR + kSkin);
  ContactNeighbourList list;
  list.build(s, cells, kSkin);
  for (std::size_t i = 0; i < s.n_owned; ++i)
    ASSERT_EQ(list.offset[i + 1] - list.offset[i], 1u) << i;

  for (const LinearSpringDashpot& law :
       {dashpot(kBeta), restitution(0.7), restitution(0.7, true)}) {
    compute_contact_forces(s, list, law, HaloImages{s.n_owned}, 0.0);
    std::size_t nonzero = 0;
    for (std::size_t p = 0; p < n_pairs; ++p) {
      const std::size_t i = 2 * p, j = i + 1;
      EXPECT_EQ(s.cx[i] + s.cx[j], 0.0) << "pair " << p;
      EXPECT_EQ(s.cy[i] + s.cy[j], 0.0) << "pair " << p;
      EXPECT_EQ(s.cz[i] + s.cz[j], 0.0) << "pair " << p;
      nonzero += (s.cx[i] != 0.0);
      // and the force is along the line of centres, magnitude k delta + beta d(delta)/dt (2.36)
      const double dx = s.x[i] - s.x[j], dy = s.y[i] - s.y[j], dz = s.z[i] - s.z[j];
      const double r = std::sqrt(dx * dx + dy * dy + dz * dz);
      const double delta = s.radius[i] + s.radius[j] - r;
      const double rate =
          -((s.vx[i] - s.vx[j]) * dx + (s.vy[i] - s.vy[j]) * dy + (s.vz[i] - s.vz[j]) * dz) / r;
      const double m12 = s.mass[i] * s.mass[j] / (s.mass[i] + s.mass[j]);
      const double beta =
          law.restitution > 0 ? beta_for_restitution(law.restitution, kK, m12) : law.beta;
      double fn = kK * delta + beta * rate;
      if (law.clip_attraction) fn = std::max(fn, 0.0);
      const double f = (s.cx[i] * dx + s.cy[i] * dy + s.cz[i] * dz) / r;
      // rounding: ulp(r) k ~ 1e-19 N; 5e-13 N is < 1e-6 of a typical pair force (k delta ~ 1e-5 N)
      EXPECT_NEAR(f, fn, 1e-9 * kK * kR) << "pair " << p;
      EXPECT_NEAR(s.overlap_max[i], delta, 1e-12 * kR);
    }
    EXPECT_GT(nonzero, n_pairs / 2);
  }
}

}  // namespace
