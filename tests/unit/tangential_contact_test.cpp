// Tangential friction (linear spring with history, damper, Coulomb limit) and rolling
// resistance (EPSD) against closed forms (solver/dem/tangential_model.hpp,
// rolling_model.hpp, contact_history.hpp, contact_forces.cpp). A small DEM rig steps the
// spheres exactly as Simulation::dem_half does: half kick of v and w, drift, contact
// forces and torques (springs advanced by the step), half kick.
#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "dem/contact_forces.hpp"
#include "dem/contact_history.hpp"
#include "dem/contact_registry.hpp"
#include "dem/dem_particles.hpp"
#include "dem/rotation.hpp"
#include "domain/cell_list.hpp"
#include "domain/periodic_halo.hpp"
#include "domain/reorder.hpp"

namespace {

using namespace sphdem;

constexpr double kPi = 3.14159265358979323846;
// Thesis suspension particles and stiffness, as contact_test.cpp.
constexpr double kD = 100e-6, kR = 0.5 * kD, kRhoP = 2500.0, kK = 10.0, kG = 9.81;
const double kMass = kRhoP * kPi * kD * kD * kD / 6.0;
const double kInertia = 0.4 * kMass * kR * kR;

struct SerialOpenMP {  // a few spheres per pass: threads would only add latency
  int saved = omp_get_max_threads();
  SerialOpenMP() { omp_set_num_threads(1); }
  ~SerialOpenMP() { omp_set_num_threads(saved); }
};

ContactParams params(double e_n, double mu, double e_t, double mu_r = -1.0, double eta_r = 0.3) {
  ContactParams p;
  p.normal.k = kK;
  p.normal.restitution = e_n;
  p.tangential.model = TangentialParams::Model::kLinearHistory;
  p.tangential.friction = mu;
  if (e_t > 0) p.tangential.restitution = e_t;
  if (mu_r >= 0) {
    p.rolling.model = RollingParams::Model::kEpsd;
    p.rolling.friction = mu_r;
    p.rolling.damping_ratio = eta_r;
  }
  return p;
}

// DEM-only stepping of a few spheres above the wall z = 0.
struct Rig {
  DemParticles s;
  ContactLaw law;
  ContactNeighbourList list;
  ContactHistory hist;
  CellList cells;
  std::array<double, 3> g{0, 0, 0};
  double skin = 0.3 * kD;
  double wall_z = 0.0;
  double t = 0;

  Rig(std::size_t n, const ContactParams& p) : law(make_contact_law(p)) {
    s.resize(n);
    s.n_owned = n;
    for (std::size_t i = 0; i < n; ++i) {
      s.radius[i] = kR;
      s.mass[i] = kMass;
      s.id[i] = static_cast<std::int64_t>(i);
      s.rigid_group[i] = -1;
    }
  }
  void rebuild() {
    hist.save(s, list);
    double rmax = 0;
    for (double r : s.radius) rmax = std::max(rmax, r);
    cells.build(s.x.data(), s.y.data(), s.z.data(), s.n_owned, 2 * rmax + skin);
    list.build(s, cells, skin);
    hist.load(s, list);
    s.x0 = s.x, s.y0 = s.y, s.z0 = s.z;
  }
  void forces(double dt) {
    compute_contact_forces(s, list, law, hist, HaloImages{s.n_owned}, wall_z, dt);
  }
  void start() {
    rebuild();
    forces(0.0);
  }
  void kick(double h) {
    for (std::size_t i = 0; i < s.n_owned; ++i) {
      s.vx[i] += h * (s.cx[i] / s.mass[i] + g[0]);
      s.vy[i] += h * (s.cy[i] / s.mass[i] + g[1]);
      s.vz[i] += h * (s.cz[i] / s.mass[i] + g[2]);
    }
    kick_spin(s, h);
  }
  void step(double h) {
    kick(0.5 * h);
    double moved = 0;
    for (std::size_t i = 0; i < s.n_owned; ++i) {
      s.x[i] += h * s.vx[i];
      s.y[i] += h * s.vy[i];
      s.z[i] += h * s.vz[i];
      moved = std::max(moved, std::hypot(s.x[i] - s.x0[i], s.y[i] - s.y0[i], s.z[i] - s.z0[i]));
    }
    if (moved > 0.5 * skin) rebuild();
    forces(h);
    kick(0.5 * h);
    t += h;
  }
  // Angular momentum about the origin, sum of m x × v + I w.
  std::array<double, 3> angular_momentum() const {
    std::array<double, 3> L{0, 0, 0};
    for (std::size_t i = 0; i < s.n_owned; ++i) {
      const double m = s.mass[i], I = s.inertia(i);
      L[0] += m * (s.y[i] * s.vz[i] - s.z[i] * s.vy[i]) + I * s.wx[i];
      L[1] += m * (s.z[i] * s.vx[i] - s.x[i] * s.vz[i]) + I * s.wy[i];
      L[2] += m * (s.x[i] * s.vy[i] - s.y[i] * s.vx[i]) + I * s.wz[i];
    }
    return L;
  }
};

// Contact time of the wall contact (undamped), pi sqrt(m/k).
const double kTcWall = kPi * std::sqrt(kMass / kK);

// ---- a sphere sliding on the wall ----------------------------------------------------

// Released on the wall at v0 without spin, it slides with friction mu m g: v = v0 - mu g t,
// w = mu m g h t / I (h = lever arm, the centre's height), until the contact point stops at
// t = 2 v0 / (7 mu g); then it rolls at 5/7 v0. With h = R - m g/k instead of R the closed
// forms become t = v0 / (mu g (1 + m h^2/I)) and v = v0 / (1 + I/(m h^2)) (angular momentum
// about the contact point): 3e-5 from 2/7 and 5/7 here, and the test checks both.
TEST(TangentialFriction, SlidingSphereRollsAtFiveSeventhsAfterTwoSeventhsV0OverMuG) {
  const SerialOpenMP serial;
  const double mu = 0.3, v0 = 0.02;
  Rig rig(1, params(0.5, mu, 0.5));
  rig.g = {0, 0, -kG};
  const double h = kR - kMass * kG / kK;  // resting overlap m g / k
  rig.s.z[0] = h;
  rig.s.vx[0] = v0;
  rig.start();
  const double dt = kTcWall / 50;
  const double t_roll = 2.0 * v0 / (7.0 * mu * kG);
  const double t_roll_h = v0 / (mu * kG * (1.0 + kMass * h * h / kInertia));
  const double v_roll_h = v0 / (1.0 + kInertia / (kMass * h * h));
  double t_stick = -1, worst_ratio = 0, prev_slip = v0;
  bool checked_half = false;
  while (rig.t < 3.0 * t_roll) {
    rig.step(dt);
    const DemParticles& s = rig.s;
    // |F_t| <= mu |F_n| at every step (the wall's F_t is (cx, cy), F_n is cz)
    worst_ratio = std::max(worst_ratio, std::hypot(s.cx[0], s.cy[0]) / (mu * std::abs(s.cz[0])));
    const double slip = s.vx[0] - s.z[0] * s.wy[0];
    if (t_stick < 0 && slip <= 0) t_stick = rig.t - dt * slip / (slip - prev_slip);
    prev_slip = slip;
    if (!checked_half && rig.t >= 0.5 * t_roll) {  // sliding: constant deceleration mu g
      checked_half = true;
      EXPECT_NEAR(s.vx[0], v0 - mu * kG * rig.t, 1e-6 * v0);
      EXPECT_NEAR(s.wy[0], mu * kMass * kG * h * rig.t / kInertia, 1e-6 * v0 / kR);
    }
  }
  std::printf("stick at t = %.6g s (2 v0/(7 mu g) = %.6g s), rolling at v = %.8g v0 (5/7 = %.8g)\n",
              t_stick, t_roll, rig.s.vx[0] / v0, 5.0 / 7.0);
  EXPECT_LE(worst_ratio, 1.0 + 1e-12);
  EXPECT_GT(worst_ratio, 1.0 - 1e-12);  // it did slide at the limit
  EXPECT_NEAR(t_stick, t_roll, 1e-3 * t_roll);
  EXPECT_NEAR(t_stick, t_roll_h, 2.0 * dt);
  EXPECT_NEAR(rig.s.vx[0], 5.0 / 7.0 * v0, 1e-4 * v0);
  EXPECT_NEAR(rig.s.vx[0], v_roll_h, 1e-7 * v0);
  EXPECT_NEAR(rig.s.z[0] * rig.s.wy[0], rig.s.vx[0], 1e-7 * v0);  // rolling without slip
}

// ---- sticking: the tangential spring oscillates at sqrt(k_t / m_t) -------------------

// A sphere at rest on the wall (F_n = m g) given a small push: mu is large, so the contact
// sticks and the contact point oscillates with omega_t = sqrt(k_t/m_t),
// 1/m_t = 1/m + h^2/I (= 7/(2m) for h = R), amplitude of xi = v1/omega_t.
TEST(TangentialFriction, StickingContactOscillatesAtTangentialFrequency) {
  const SerialOpenMP serial;
  for (double ratio : {2.0 / 7.0, 0.8}) {
    ContactParams p = params(0.5, 100.0, -1.0);  // no tangential damping
    p.tangential.stiffness_ratio = ratio;
    Rig rig(1, p);
    rig.g = {0, 0, -kG};
    const double h = kR - kMass * kG / kK, v1 = 1e-4;
    rig.s.z[0] = h;
    rig.s.vx[0] = v1;
    rig.start();
    const double kt = ratio * kK;
    const double mt = 1.0 / (1.0 / kMass + h * h / kInertia);
    const double omega_t = std::sqrt(kt / mt), period = 2 * kPi / omega_t;
    const double dt = period / 200;
    std::vector<double> crossings;
    double prev = v1, xi_max = 0;
    while (crossings.size() < 9) {
      rig.step(dt);
      const double slip = rig.s.vx[0] - rig.s.z[0] * rig.s.wy[0];
      xi_max = std::max(xi_max, std::abs(rig.hist.wall[0].xi[0]));
      if ((prev > 0) != (slip > 0)) crossings.push_back(rig.t - dt * slip / (slip - prev));
      prev = slip;
      ASSERT_LT(rig.t, 20 * period);
    }
    const double measured = (crossings.back() - crossings.front()) / 4.0;  // 8 half periods
    std::printf(
        "k_t/k_n = %.4f: period %.6g s, 2 pi sqrt(m_t/k_t) = %.6g s; xi max %.5g m, v1/omega_t = "
        "%.5g m\n",
        ratio, measured, period, xi_max, v1 / omega_t);
    // velocity Verlet: relative frequency error (omega dt)^2/24 = 4e-5
    EXPECT_NEAR(measured, period, 2e-4 * period);
    EXPECT_NEAR(xi_max, v1 / omega_t, 2e-3 * v1 / omega_t);
    if (ratio == 2.0 / 7.0) {  // equal to the normal period of the wall contact
      EXPECT_NEAR(measured, 2 * kTcWall, 1e-3 * period);
    }
  }
}

// ---- oblique impacts: the two regimes of the linear spring (Walton 1993) -------------

// An undamped normal spring and k_t/k_n = 2/7 give a tangential spring in phase with the
// normal one, so F_t / F_n = (2/7) v_t / v_n all through the contact (v_t: tangential
// velocity of the contact point, v_n: approach speed). Hence two regimes:
//  - (2/7) v_t/v_n <= mu: sticks throughout; the contact point leaves with -v_t
//    (tangential restitution 1);
//  - (2/7) v_t/v_n > mu: slides throughout at the Coulomb limit; the tangential
//    impulse is mu times the normal one, 2 mu m12 v_n, and the contact point leaves with
//    v_t - 7 mu v_n.
// The lever arms shrink by delta/2 during the contact, which detunes the two springs by
// O(delta/R) = 2e-4 here: the tolerances.
struct Impact {
  double vt_after;     // tangential contact-point velocity after the impact
  double dv_com;       // change of the tangential velocity of the first sphere's centre
  double worst_ratio;  // max |F_t| / (mu |F_n|)
  int sliding_steps, contact_steps;
};

Impact oblique_impact(bool wall, double vn, double vt, double mu) {
  const SerialOpenMP serial;
  Rig rig(wall ? 1 : 2, params(1.0, mu, -1.0));
  const double z0 = 1e-3;
  const double omega0 = std::sqrt(kK / (wall ? kMass : 0.5 * kMass));
  const double dt = kPi / omega0 / 400;
  const double gap = vn * 3.5 * dt;
  if (wall) {
    rig.s.z[0] = kR + gap;
    rig.s.vz[0] = -vn;
    rig.s.vx[0] = vt;
  } else {  // two spheres on the z axis, each moving at half the relative velocity
    rig.s.z = {z0 + kR + 0.5 * gap, z0 - kR - 0.5 * gap};
    rig.s.vz = {-0.5 * vn, 0.5 * vn};
    rig.s.vx = {0.5 * vt, -0.5 * vt};
  }
  rig.start();
  Impact m{0, 0, 0, 0, 0};
  bool touched = false;
  for (int k = 0; k < 100000; ++k) {
    rig.step(dt);
    const DemParticles& s = rig.s;
    double nx = 0, ny = 0, nz = 1;  // from sphere 1 (or the wall) to sphere 0
    if (!wall) {
      const double dx = s.x[0] - s.x[1], dy = s.y[0] - s.y[1], dz = s.z[0] - s.z[1];
      const double r = std::sqrt(dx * dx + dy * dy + dz * dz);
      nx = dx / r, ny = dy / r, nz = dz / r;
    }
    const double fn = s.cx[0] * nx + s.cy[0] * ny + s.cz[0] * nz;
    const double ft = std::hypot(s.cx[0] - fn * nx, s.cy[0] - fn * ny, s.cz[0] - fn * nz);
    if (fn != 0.0 || ft != 0.0) {
      touched = true;
      ++m.contact_steps;
      const double r = ft / (mu * std::abs(fn));
      m.worst_ratio = std::max(m.worst_ratio, r);
      m.sliding_steps += r > 1.0 - 1e-9;
    } else if (touched) {
      break;
    }
  }
  const DemParticles& s = rig.s;
  // tangential velocity of the contact point, v_0 - v_1 - (c_0 w_0 + c_1 w_1) x n, n = z
  if (wall)
    m.vt_after = s.vx[0] - s.z[0] * s.wy[0];
  else
    m.vt_after = (s.vx[0] - s.vx[1]) - kR * (s.wy[0] + s.wy[1]);
  m.dv_com = s.vx[0] - (wall ? vt : 0.5 * vt);
  return m;
}

TEST(TangentialFriction, ObliqueImpactSticksOrSlidesAsTheLinearSpringPredicts) {
  // boundary of the regimes at v_t/v_n = 3.5 mu = 1.75; slow, so that the pair's n turns
  // little as the spheres slide past each other (1.3e-4 rad)
  const double vn = 1e-4, mu = 0.5;
  for (bool wall : {true, false}) {
    SCOPED_TRACE(wall ? "sphere on the wall" : "two spheres");
    const double m12 = wall ? kMass : 0.5 * kMass;
    // sticking regime: v_t/v_n = 1
    const Impact stick = oblique_impact(wall, vn, 1.0 * vn, mu);
    std::printf("%s, v_t/v_n = 1: v_t after / before = %.6f; %d of %d steps sliding\n",
                wall ? "wall" : "pair", stick.vt_after / vn, stick.sliding_steps,
                stick.contact_steps);
    EXPECT_NEAR(stick.vt_after, -vn, 2e-3 * vn);
    EXPECT_LE(stick.worst_ratio, 1.0 + 1e-12);
    EXPECT_LT(stick.sliding_steps,
              stick.contact_steps / 20);  // at most the last few steps (detuning)
    // sliding regime: v_t/v_n = 5
    const double vt = 5.0 * vn;
    const Impact slide = oblique_impact(wall, vn, vt, mu);
    std::printf(
        "%s, v_t/v_n = 5: v_t after = %.6f v_n (v_t - 7 mu v_n = %.6f v_n); %d of %d steps "
        "sliding\n",
        wall ? "wall" : "pair", slide.vt_after / vn, (vt - 7 * mu * vn) / vn, slide.sliding_steps,
        slide.contact_steps);
    EXPECT_EQ(slide.sliding_steps, slide.contact_steps);
    EXPECT_LE(slide.worst_ratio, 1.0 + 1e-12);
    // tangential impulse on sphere 0 = -mu x normal impulse (2 m12 v_n, undamped): the
    // same sums at the wall (n = z exactly); the pair's n tilts by ~4e-4 as the spheres slide
    EXPECT_NEAR(kMass * slide.dv_com, -mu * 2.0 * m12 * vn, (wall ? 1e-9 : 2e-3) * mu * m12 * vn);
    EXPECT_NEAR(slide.vt_after, vt - 7.0 * mu * vn, 2e-3 * vn);
  }
}

// ---- Coulomb limit with damping, oblique impacts at many angles ---------------------

TEST(TangentialFriction, CoulombLimitHoldsAtEveryStepOfDampedImpacts) {
  for (bool wall : {true, false})
    for (double ratio : {0.2, 0.5, 1.0, 2.0, 5.0, 50.0}) {
      const SerialOpenMP serial;
      Rig rig(wall ? 1 : 2, params(0.6, 0.4, 0.5, 0.05));
      const double vn = 0.01, vt = ratio * vn, dt = kTcWall / 100;
      if (wall) {
        rig.s.z[0] = kR + 2.5 * vn * dt;
        rig.s.vz[0] = -vn;
        rig.s.vx[0] = vt;
        rig.s.wx[0] = 0.3 * vt / kR;  // some spin across the motion
      } else {
        rig.s.x = {0, 0.3 * kR};  // off-centre, so n turns during the contact
        const double dz = std::sqrt(std::pow(2 * kR + vn * dt, 2) - std::pow(0.3 * kR, 2));
        rig.s.z = {1e-3 + 0.5 * dz, 1e-3 - 0.5 * dz};
        rig.s.vz = {-0.5 * vn, 0.5 * vn};
        rig.s.vy = {0.5 * vt, -0.5 * vt};
        rig.s.wz = {vt / kR, 0.0};
      }
      rig.start();
      double worst = 0;
      int steps = 0;
      for (int k = 0; k < 2000; ++k) {
        rig.step(dt);
        const DemParticles& s = rig.s;
        double nx = 0, ny = 0, nz = 1;
        if (!wall) {
          const double dx = s.x[0] - s.x[1], dy = s.y[0] - s.y[1], dz = s.z[0] - s.z[1];
          const double r = std::sqrt(dx * dx + dy * dy + dz * dz);
          nx = dx / r, ny = dy / r, nz = dz / r;
        }
        const double fn = s.cx[0] * nx + s.cy[0] * ny + s.cz[0] * nz;
        const double ft = std::hypot(s.cx[0] - fn * nx, s.cy[0] - fn * ny, s.cz[0] - fn * nz);
        if (fn == 0.0 && ft == 0.0) continue;
        ++steps;
        worst = std::max(worst, ft / (0.4 * std::abs(fn)));  // decomposition round-off ~1e-16
      }
      SCOPED_TRACE(std::string(wall ? "wall" : "pair") + ", v_t/v_n = " + std::to_string(ratio));
      EXPECT_GT(steps, 10);
      EXPECT_LE(worst, 1.0 + 1e-9);
    }
}

// ---- history keyed by ids: survives re-sorting and list rebuilds --------------------

// Sphere 1 rests on the wall; sphere 0 falls on it off-centre, spinning. Mid-contact (both
// contacts with history) the arrays are permuted (permute_owned, as the every-20-steps
// sort) and the list rebuilt, with the history saved before and loaded after: the
// trajectory is the same bit for bit as without, and as with a plain list rebuild.
TEST(ContactHistory, SurvivesReorderAndRebuildBitForBit) {
  const SerialOpenMP serial;
  auto run = [](int mode) {  // 0: nothing, 1: rebuild mid-contact, 2: permute + rebuild
    Rig rig(2, params(0.5, 0.5, 0.5, 0.1));
    rig.g = {0, 0, -kG};
    rig.s.x = {0.4 * kR, 0.0};
    rig.s.z = {3 * kR + 1e-7, kR - kMass * kG / kK};
    rig.s.vz = {-0.01, 0.0};
    rig.s.vx = {0.0, -0.004};  // the lower sphere slides on the wall
    rig.s.wy = {50.0, 0.0};
    rig.start();
    const double dt = kTcWall / 50;
    int active = 0, both = 0;
    auto any_active = [](const std::vector<ContactState>& v) {
      return std::any_of(v.begin(), v.end(), [](const ContactState& st) { return st.active(); });
    };
    for (int k = 0; k < 4000; ++k) {
      rig.step(dt);
      both += any_active(rig.hist.pair) && any_active(rig.hist.wall);
      if (both == 50 && active == 0) {  // mid-contact (the runs are equal up to here)
        for (const auto& st : rig.hist.pair) active += st.active();
        for (const auto& st : rig.hist.wall) active += st.active();
        if (mode >= 1) {  // as Simulation: save, re-sort, rebuild (which loads); forces kept
          rig.hist.save(rig.s, rig.list);
          if (mode == 2) permute_owned(rig.s, {1, 0});
          rig.rebuild();
        }
      }
    }
    std::vector<double> out;
    std::vector<std::size_t> by_id(2);
    for (std::size_t i = 0; i < 2; ++i) by_id[rig.s.id[i]] = i;
    for (std::size_t i : by_id)
      for (const auto* v : {&rig.s.x, &rig.s.y, &rig.s.z, &rig.s.vx, &rig.s.vy, &rig.s.vz,
                            &rig.s.wx, &rig.s.wy, &rig.s.wz})
        out.push_back((*v)[i]);
    out.push_back(active);
    return out;
  };
  const auto plain = run(0), rebuilt = run(1), permuted = run(2);
  EXPECT_EQ(plain.back(), 3.0);  // mid-contact: the pair (both copies) and the lower wall contact
  std::printf("sphere 0 after: x = %.17g m, w_y = %.17g rad/s\n", plain[0], plain[7]);
  for (std::size_t k = 0; k < plain.size(); ++k) {
    EXPECT_EQ(plain[k], rebuilt[k]) << k;
    EXPECT_EQ(plain[k], permuted[k]) << k;
  }
  EXPECT_NE(plain[3], 0.0);  // sphere 0 moved sideways (friction acted)
}

// The store: saved records are keyed (id, partner), sorted, and a pair's two copies are
// identical; loading into a list that no longer holds a partner drops the record.
TEST(ContactHistory, StoreIsKeyedByIdPairs) {
  const SerialOpenMP serial;
  Rig rig(3, params(0.5, 0.5, -1.0));
  // ids deliberately not in array order
  rig.s.id = {7, 3, 11};
  rig.s.x = {0.0, 1.9 * kR, 10 * kR};
  rig.s.z = {kR * 0.999, kR * 0.999, 1e-3};
  rig.s.vy = {0.01, -0.01, 0.0};
  rig.start();
  for (int k = 0; k < 5; ++k) rig.step(kTcWall / 100);
  rig.hist.save(rig.s, rig.list);
  const auto& keyed = rig.hist.keyed();
  ASSERT_EQ(keyed.size(), 4u);  // 3-7 and 7-3, both walls
  EXPECT_EQ(keyed[0].id, 3);
  EXPECT_EQ(keyed[0].partner, ContactHistory::kBottomWall);
  EXPECT_EQ(keyed[1].id, 3);
  EXPECT_EQ(keyed[1].partner, 7);
  EXPECT_EQ(keyed[2].id, 7);
  EXPECT_EQ(keyed[3].partner, 3);
  const ContactState* a = rig.hist.find(3, 7);
  const ContactState* b = rig.hist.find(7, 3);
  ASSERT_TRUE(a && b);
  for (int d = 0; d < 3; ++d) EXPECT_EQ(a->xi[d], b->xi[d]);  // canonical orientation: equal
  EXPECT_NE(a->xi[0], 0.0);
  EXPECT_EQ(rig.hist.find(3, 11), nullptr);
  rig.hist.save(rig.s, rig.list);  // saving again changes nothing
  EXPECT_EQ(rig.hist.keyed().size(), 4u);
  // sphere 3 jumps away: its pair record is not loaded into the new list
  rig.s.x[1] = 5 * kR;
  rig.rebuild();
  std::size_t active = 0;
  for (const auto& st : rig.hist.pair) active += st.active();
  EXPECT_EQ(active, 0u);
  EXPECT_TRUE(rig.hist.wall[0].active() && rig.hist.wall[1].active());
}

// ---- action and reaction ------------------------------------------------------------

// Random overlapping pairs with random velocities, spins and a history built over a few
// steps: forces are exact negatives (canonical orientation), and the torques balance the
// moment of the pair force: (x_i - x_j) x F_i + tau_i + tau_j = 0 to round-off. Pairs are
// placed across the periodic face x = 0 | L too, seen through halo copies: the separation
// (x_i - x_source) - shift keeps them exact, where x_i - x_ghost would not be.
TEST(TangentialForces, ActionReactionIsExactAlsoAcrossPeriodicFaces) {
  const SerialOpenMP serial;
  std::mt19937 gen(7);
  std::uniform_real_distribution<double> u01(0.0, 1.0), sym(-1.0, 1.0);
  const std::size_t n_pairs = 200;
  const double L = 4e-3;
  Box box;
  box.lo = {0, 0, 0};
  box.hi = {L, L, L};
  box.periodic = {true, true, false};
  DemParticles s;
  s.resize(2 * n_pairs);
  s.n_owned = 2 * n_pairs;
  for (std::size_t p = 0; p < n_pairs; ++p) {
    const std::size_t i = 2 * p, j = i + 1;
    for (std::size_t q : {i, j}) {
      s.radius[q] = kR * (0.5 + u01(gen));
      s.mass[q] = kRhoP * 4.0 / 3.0 * kPi * std::pow(s.radius[q], 3);
      s.id[q] = static_cast<std::int64_t>(q);
      s.rigid_group[q] = -1;
    }
    double nx = sym(gen), ny = sym(gen), nz = sym(gen);
    const double nn = std::sqrt(nx * nx + ny * ny + nz * nz);
    const double dist = (s.radius[i] + s.radius[j]) * (1.0 - 0.05 * u01(gen));
    // pairs on a 10 x 20 grid in (y, z), 0.4 mm apart; the even ones straddle the
    // periodic face x = 0 | L (one sphere just inside x = 0, the other near x = L)
    const bool across = p % 2 == 0;
    if (across) nx = -std::abs(nx);
    s.x[i] = across ? 2e-6 * u01(gen) : 2e-3 + 1e-7 * sym(gen);
    s.y[i] = (static_cast<double>(p % 10) + 0.5) * 4e-4 + 1e-7 * sym(gen);
    s.z[i] = 1e-3 + static_cast<double>(p / 10) * 4e-4 + 1e-7 * sym(gen);
    s.x[j] = box.wrap(0, s.x[i] + dist * nx / nn);
    s.y[j] = box.wrap(1, s.y[i] + dist * ny / nn);
    s.z[j] = s.z[i] + dist * nz / nn;
    for (std::size_t q : {i, j}) {
      s.vx[q] = 0.02 * sym(gen), s.vy[q] = 0.02 * sym(gen), s.vz[q] = 0.02 * sym(gen);
      s.wx[q] = 400 * sym(gen), s.wy[q] = 400 * sym(gen), s.wz[q] = 400 * sym(gen);
    }
  }
  PeriodicHalo halo;
  const double skin = 0.3 * kD, cut = 3 * kR + skin;
  halo.build(box, cut, s.x.data(), s.y.data(), s.z.data(), s.n_owned);
  s.resize(s.n_owned + halo.n_ghost());
  halo.fill_positions(s.x.data(), s.y.data(), s.z.data());
  for (auto* v : {&s.vx, &s.vy, &s.vz, &s.wx, &s.wy, &s.wz, &s.radius, &s.mass}) halo.fill(*v);
  halo.fill(s.id);
  CellList cells;
  cells.build(s.x.data(), s.y.data(), s.z.data(), s.size(), cut);
  ContactNeighbourList list;
  list.build(s, cells, skin);
  for (std::size_t i = 0; i < s.n_owned; ++i)
    ASSERT_EQ(list.offset[i + 1] - list.offset[i], 1u) << i;
  std::size_t naive_mismatch = 0;  // what x_i - x_ghost would give
  for (std::size_t p = 0; p < n_pairs; ++p) {
    const std::uint32_t gj = list.neighbour[list.offset[2 * p]],
                        gi = list.neighbour[list.offset[2 * p + 1]];
    naive_mismatch += (s.x[2 * p] - s.x[gj]) != -(s.x[2 * p + 1] - s.x[gi]);
  }
  std::printf("pairs across the face: %zu of %zu; x_i - x_ghost not antisymmetric for %zu pairs\n",
              n_pairs / 2, n_pairs, naive_mismatch);

  for (const ContactParams& p :
       {params(0.7, 0.3, 0.6), params(0.7, 0.3, 0.6, 0.2), params(0.7, 5.0, -1.0, 0.9)}) {
    const ContactLaw law = make_contact_law(p);
    ContactHistory hist;
    hist.load(s, list);
    for (int k = 0; k < 50; ++k)  // the springs grow (positions held): some stick, some slide
      compute_contact_forces(s, list, law, hist, halo.images(), 0.0, 1e-6);
    std::size_t sticking = 0, sliding = 0;
    for (std::size_t q = 0; q < n_pairs; ++q) {
      const std::size_t i = 2 * q, j = i + 1;
      SCOPED_TRACE(q);
      EXPECT_EQ(s.cx[i] + s.cx[j], 0.0);
      EXPECT_EQ(s.cy[i] + s.cy[j], 0.0);
      EXPECT_EQ(s.cz[i] + s.cz[j], 0.0);
      // the two history copies are identical (canonical orientation)
      const ContactState& hi = hist.pair[list.offset[i]];
      const ContactState& hj = hist.pair[list.offset[j]];
      for (int d = 0; d < 3; ++d) {
        EXPECT_EQ(hi.xi[d], hj.xi[d]);
        EXPECT_EQ(hi.mr[d], hj.mr[d]);
      }
      EXPECT_TRUE(hi.active());
      // moment balance, with the minimum-image separation
      const double dx = std::remainder(s.x[i] - s.x[j], L), dy = std::remainder(s.y[i] - s.y[j], L),
                   dz = s.z[i] - s.z[j];
      const double mx = dy * s.cz[i] - dz * s.cy[i] + s.tx[i] + s.tx[j];
      const double my = dz * s.cx[i] - dx * s.cz[i] + s.ty[i] + s.ty[j];
      const double mz = dx * s.cy[i] - dy * s.cx[i] + s.tz[i] + s.tz[j];
      const double f = std::hypot(s.cx[i], s.cy[i], s.cz[i]);
      EXPECT_LT(std::hypot(mx, my, mz), 1e-12 * kR * f);
      // sticking or sliding
      const double r = std::hypot(dx, dy, dz);
      const double fn = (s.cx[i] * dx + s.cy[i] * dy + s.cz[i] * dz) / r;
      const double ft = std::sqrt(std::max(0.0, f * f - fn * fn));
      const double mu = p.tangential.friction;
      EXPECT_LE(ft, mu * std::abs(fn) * (1 + 1e-9) + 1e-12 * f);
      (ft < mu * std::abs(fn) * (1 - 1e-6) ? sticking : sliding) += 1;
    }
    std::printf("mu = %.1f%s: %zu pairs stick, %zu slide\n", p.tangential.friction,
                p.rolling.model == RollingParams::Model::kEpsd ? " + rolling" : "", sticking,
                sliding);
    EXPECT_GT(sticking, 0u);
    if (p.tangential.friction < 1) {
      EXPECT_GT(sliding, 0u);
    }
  }
}

// ---- angular momentum ---------------------------------------------------------------

// Two unequal spheres collide obliquely and spinning, without gravity or walls: the
// pair's forces and torques (tangential and rolling) have no net moment, and velocity
// Verlet keeps sum (m x × v + I w) to round-off at every step.
TEST(TangentialForces, AngularMomentumOfAnObliqueCollisionIsConserved) {
  const SerialOpenMP serial;
  for (const ContactParams& p : {params(0.6, 0.3, 0.5), params(0.6, 0.3, 0.5, 0.3, 0.5)}) {
    Rig rig(2, p);
    rig.s.radius = {kR, 0.6 * kR};
    rig.s.mass = {kMass, kMass * 0.216 * 3.0};  // the small one denser
    rig.wall_z = -1.0;  // no wall; the centres stay near the origin (round-off of x × v)
    const double vrel = 0.02;
    rig.s.x = {-0.3 * kR, 0.3 * kR};
    rig.s.y = {-0.75 * kR, 0.75 * kR};  // 4 % of R apart along the line of centres
    rig.s.z = {0.2 * kR, -0.1 * kR};
    rig.s.vy = {0.5 * vrel, -0.5 * vrel};
    rig.s.vx = {0.01, -0.004};
    rig.s.vz = {-0.002, 0.003};
    rig.s.wx = {300, -100};
    rig.s.wz = {-200, 800};
    rig.start();
    const auto L0 = rig.angular_momentum();
    const double scale = kMass * vrel * kR;
    double worst = 0;
    int contact_steps = 0;
    const double dt = kTcWall / 200;
    for (int k = 0; k < 2000; ++k) {
      rig.step(dt);
      const auto L = rig.angular_momentum();
      worst = std::max(worst, std::hypot(L[0] - L0[0], L[1] - L0[1], L[2] - L0[2]));
      contact_steps += rig.s.cx[0] != 0.0 || rig.s.cy[0] != 0.0;
    }
    const auto L1 = rig.angular_momentum();
    std::printf(
        "|L| = %.4g (m v R = %.4g); max |L - L0| = %.3g; %d steps in contact; spin after %.4g %.4g "
        "rad/s\n",
        std::hypot(L1[0], L1[1], L1[2]), scale, worst, contact_steps, rig.s.wz[0], rig.s.wz[1]);
    EXPECT_GT(contact_steps, 50);
    EXPECT_LT(worst, 1e-13 * scale);
    EXPECT_NE(rig.s.wz[0], -200.0);  // the contact changed the spins
  }
}

// ---- rolling resistance -------------------------------------------------------------

// A sphere rolling on the wall (v0, w = v0/h) with EPSD rolling resistance: once the
// rolling spring is mobilised the torque mu_r R m g decelerates it at
// a = mu_r R m g h/(I + m h^2) (5/7 mu_r g for h = R), friction keeping it rolling, so it
// stops after v0^2/(2a) = 7 v0^2/(10 mu_r g) and stays (the spring holds it elastically).
TEST(RollingResistance, RollingSphereStopsWhereTheModelPredicts) {
  const SerialOpenMP serial;
  for (double mu_r : {0.05, 0.2}) {
    const double v0 = 0.01, mu = 0.5;
    Rig rig(1, params(0.5, mu, 0.5, mu_r));
    rig.g = {0, 0, -kG};
    const double h = kR - kMass * kG / kK;
    rig.s.z[0] = h;
    rig.s.vx[0] = v0;
    rig.s.wy[0] = v0 / h;
    rig.start();
    const double a = mu_r * kR * kMass * kG * h / (kInertia + kMass * h * h);
    const double distance = v0 * v0 / (2 * a), t_stop = v0 / a;
    const double distance_57 = 7.0 * v0 * v0 / (10.0 * mu_r * kG);
    const double dt = kTcWall / 40;
    double x_first_stop = -1, t_first_stop = -1, slip_max = 0;
    bool checked_half = false;
    while (rig.t < 1.3 * t_stop) {
      rig.step(dt);
      const DemParticles& s = rig.s;
      // (the contact point slips briefly at the start while the tangential spring loads,
      // and at the stop while the springs unload)
      if (rig.t > 0.1 * t_stop && rig.t < 0.9 * t_stop)
        slip_max = std::max(slip_max, std::abs(s.vx[0] - s.z[0] * s.wy[0]));
      if (!checked_half && rig.t >= 0.5 * t_stop) {  // constant deceleration
        checked_half = true;
        EXPECT_NEAR(s.vx[0], 0.5 * v0, 2e-3 * v0);
      }
      if (x_first_stop < 0 && s.vx[0] <= 0) {
        x_first_stop = s.x[0];
        t_first_stop = rig.t;
      }
    }
    std::printf(
        "mu_r = %.2f: stops at x = %.6g m after %.5g s (v0^2/2a = %.6g m, 7 v0^2/(10 mu_r g) = "
        "%.6g m, "
        "t = %.5g s); rests at %.6g m, |v| = %.2g m/s; max slip %.2g m/s\n",
        mu_r, x_first_stop, t_first_stop, distance, distance_57, t_stop, rig.s.x[0],
        std::abs(rig.s.vx[0]), slip_max);
    EXPECT_NEAR(x_first_stop, distance, 1e-3 * distance);
    EXPECT_NEAR(x_first_stop, distance_57, 2e-3 * distance);
    EXPECT_NEAR(t_first_stop, t_stop, 2e-3 * t_stop);
    EXPECT_NEAR(rig.s.x[0], distance, 1e-3 * distance);  // and stays there
    EXPECT_LT(std::abs(rig.s.vx[0]), 1e-4 * v0);
    EXPECT_LT(slip_max, 1e-4 * v0);  // then rolls without sliding: 5/7 mu_r < mu
  }
}

// Without friction or rolling parts nothing spins; with them, the registry refuses
// rolling resistance without tangential friction.
TEST(ContactRegistry, CombinationsAndRotation) {
  ContactParams p;
  EXPECT_EQ(make_contact_law(p).index(), 0u);
  EXPECT_FALSE(contact_law_has_history(make_contact_law(p)));
  p.rolling.model = RollingParams::Model::kEpsd;
  EXPECT_THROW(make_contact_law(p), std::invalid_argument);
  p.tangential.model = TangentialParams::Model::kLinearHistory;
  EXPECT_EQ(make_contact_law(p).index(), 2u);
  p.rolling.model = RollingParams::Model::kNone;
  EXPECT_EQ(make_contact_law(p).index(), 1u);
  EXPECT_TRUE(contact_law_has_history(make_contact_law(p)));
  // restitution-based tangential damping: the sticking oscillator of mass 2/7 m12 has e_t
  p.tangential.restitution = 0.5;
  const ContactLaw any = make_contact_law(p);
  const auto& law = std::get<FrictionalContact>(any);
  const double mt = 2.0 / 7.0 * kMass, kt = 2.0 / 7.0 * p.normal.k;
  const ContactClosedForm cf(kt, law.tangential.gamma_for(kMass), mt);
  EXPECT_NEAR(cf.restitution(), 0.5, 1e-12);
}

}  // namespace
