// Bidisperse constant-porosity blocks (thesis §4.6, §5.3) against eq. (4.5), resolved the
// two ways the thesis compared: the classic single smoothing at h/d_big = 2, and the
// double smoothing (3.8-3.10) at h/d_small = 2.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <variant>
#include <vector>

#include "analysis/diagnostics.hpp"
#include "closed_forms.hpp"
#include "propagator/simulation.hpp"
#include "scene/initial_state.hpp"
#include "scene/scene.hpp"

using namespace sphdem;

namespace {

struct BlockRun {
  double eps, reference, slip;
  double smeared;   // the block's force balance with each sphere's own kernel voidage at release
                    // (see below)
  double balanced;  // the same with each sphere's voidage and pressure force, means over the slip's
                    // window
  double buoyancy;  // sum_i V_i (-grad P)_z,i / (sum_i V_i rho_av g), mean over the window (1: the
                    // mixture's)
  double closed;    // the same balance with each sphere's own window-mean slip shape (see below)
  double slip_spread;  // standard deviation / mean of the spheres' window-mean superficial slips
};

// Per-sphere means over the slip's window (by sphere id: the spheres are re-sorted).
struct SphereMeans {
  std::vector<double> eps, pressure_z, d_sauter,
      slip_z;  // pressure_z: (-grad P + div tau)_z (N/m^3)
  double duration = 0;
  void add(const DemParticles& s, double dt) {
    for (std::size_t i = 0; i < s.n_owned; ++i) {
      const std::size_t k = static_cast<std::size_t>(s.id[i]);
      if (k >= eps.size())
        eps.resize(k + 1), pressure_z.resize(k + 1), d_sauter.resize(k + 1), slip_z.resize(k + 1);
      eps[k] += s.eps[i] * dt;
      pressure_z[k] += s.gz[i] * dt;
      d_sauter[k] += s.d_sauter[i] * dt;
      slip_z[k] += s.eps[i] * (s.ufz[i] - s.vz[i]) *
                   dt;  // superficial slip (2.74), upward for a falling block
    }
    duration += dt;
  }
};

// What the block's force balance takes of sphere i: its voidage, the shape of its
// superficial slip (u_i = shape_i w for one scalar w) and its Sauter mean diameter.
struct BalanceSphere {
  double eps, shape, d_sauter;
};

// The block's force balance sum_i c(eps_i, u_i) u_i = weight with u_i = shape_i w;
// returns the mean superficial slip mean_i(shape_i) w.
template <class Sphere>
double block_balance_slip(const Simulation& sim, const Scene& sc, double weight, Sphere sphere) {
  const DemParticles& s = sim.spheres();
  const drag::Fluid fl{sc.fluid.density, sc.fluid.viscosity};
  double shape_mean = 0;
  for (std::size_t i = 0; i < s.n_owned; ++i) shape_mean += sphere(i).shape / s.n_owned;
  auto residual = [&](double w) {
    double drag_sum = 0;
    for (std::size_t i = 0; i < s.n_owned; ++i) {
      const BalanceSphere b = sphere(i);
      const double us = b.shape * w;
      drag_sum +=
          std::visit(
              [&](const auto& law) {
                return drag::drag_coefficient(law, b.eps, us, 2.0 * s.radius[i], b.d_sauter, fl);
              },
              sc.drag) *
          us;
    }
    return drag_sum - weight;
  };
  return shape_mean * theory::bisect(residual, 1e-9, 1.0e3);
}

// The balance with each sphere's own voidage eps_i and pressure force V_i p_i (window
// means): the weight is sum_i V_i (rho_p,i g - p_i), the slips u_i = eps_i w for one
// interstitial slip w, or (same_interstitial_slip false) u_i = lambda s_i with s_i each
// sphere's window-mean slip.
double balanced_block_slip(const Simulation& sim, const Scene& sc, const SphereMeans& m,
                           bool same_interstitial_slip = true) {
  const DemParticles& s = sim.spheres();
  const double g = std::abs(sc.gravity[2]), inv_t = 1.0 / m.duration;
  double weight = 0;
  for (std::size_t i = 0; i < s.n_owned; ++i)
    weight += s.volume(i) * (sc.species[s.species[i]].density * g -
                             m.pressure_z[static_cast<std::size_t>(s.id[i])] * inv_t);
  return block_balance_slip(sim, sc, weight, [&](std::size_t i) {
    const std::size_t k = static_cast<std::size_t>(s.id[i]);
    return BalanceSphere{m.eps[k] * inv_t,
                         (same_interstitial_slip ? m.eps[k] : m.slip_z[k]) * inv_t,
                         m.d_sauter[k] * inv_t};
  });
}

// The kernel smooths the block's top and bottom faces over its support 2h: the outer
// sphere layers see eps_i above the lattice voidage (0.9 -> up to 0.935 at h/d = 2, the
// sphere mean 0.909), so they feel less drag and the block falls faster than (4.4)/(4.5),
// more so for a coarser fluid and a steeper drag law. The force balance of the block with
// those eps_i, sum_i c(eps_i, eps_i w) eps_i w = sum_i eps (rho_p - rho_f) V_i g for one
// interstitial slip w, predicts the mean superficial slip mean_i(eps_i) w.
double smeared_block_slip(const Simulation& sim, const Scene& sc, double eps) {
  const DemParticles& s = sim.spheres();
  const double g = std::abs(sc.gravity[2]);
  double weight = 0;
  for (std::size_t i = 0; i < s.n_owned; ++i)
    weight += eps * (sc.species[s.species[i]].density - sc.fluid.density) * s.volume(i) * g;
  return block_balance_slip(sim, sc, weight, [&](std::size_t i) {
    return BalanceSphere{s.eps[i], s.eps[i], s.d_sauter[i]};
  });
}

// Mean superficial slip of the whole block (both sizes, by sphere count) over the last
// acoustic period 4H/c0 (7 ms) of a 16 ms run. Not two periods as the monodisperse block:
// the 150 and 200 um spheres take ~3-5 ms to reach their terminal slip (the 200/100 block
// is at 0.69 of it at 2 ms), and a window from 2 ms averaged that start-up in (+2.8 %
// instead of +7.5 % for 200/100 with double smoothing).
BlockRun run_block(const std::string& file, const std::vector<std::string>& overrides) {
  std::vector<std::string> set = overrides;
  set.push_back("time.end=0.016");
  const Scene sc = load_scene(std::string(SPHDEM_CASES_DIR) + "/" + file, set);
  const SpeciesSpec& big = sc.species.at(0);
  const SpeciesSpec& small = sc.species.at(1);
  BlockRun r;
  r.eps = block_lattice(sc, sc.particles.at(0)).voidage;
  r.reference = theory::bidisperse_block_slip(
      big.diameter, small.diameter, sc.particles.at(0).fractions.at(0), big.density,
      sc.fluid.density, sc.fluid.viscosity, std::abs(sc.gravity[2]), r.eps);
  Simulation sim(sc);
  const DemParticles& s = sim.spheres();
  double n_big = 0;
  for (std::size_t i = 0; i < s.n_owned; ++i) n_big += s.species[i] == 0;
  const double w_big = n_big / static_cast<double>(s.n_owned);
  sim.relax();
  r.smeared = smeared_block_slip(sim, sc, r.eps);
  const double period = 4.0 * sc.fill_height() / sc.fluid.sound_speed;
  const double t0 = sc.time.end - period;
  double sum = 0, wsum = 0;
  SphereMeans means;
  while (sim.time() < sc.time.end) {
    sim.step();
    if (sim.time() > t0) {
      const auto d = diagnostics(sim);
      sum += (w_big * d.slip_z_mean[0] + (1.0 - w_big) * d.slip_z_mean[1]) * sim.dt_sph();
      wsum += sim.dt_sph();
      means.add(s, sim.dt_sph());
    }
  }
  r.slip = sum / wsum;
  r.balanced = balanced_block_slip(sim, sc, means);
  r.closed = balanced_block_slip(sim, sc, means, false);
  {
    double m1 = 0, m2 = 0, pressure = 0, volume = 0;
    const double inv_t = 1.0 / means.duration;
    for (std::size_t i = 0; i < s.n_owned; ++i) {
      const std::size_t k = static_cast<std::size_t>(s.id[i]);
      const double u = means.slip_z[k] * inv_t;
      m1 += u / s.n_owned;
      m2 += u * u / s.n_owned;
      pressure += s.volume(i) * means.pressure_z[k] * inv_t;
      volume += s.volume(i);
    }
    r.slip_spread = std::sqrt(std::max(0.0, m2 - m1 * m1)) / m1;
    const double rho_av =
        r.eps * sc.fluid.density + (1.0 - r.eps) * big.density;  // both species share rho_p
    r.buoyancy = pressure / (volume * rho_av * std::abs(sc.gravity[2]));
  }
  std::printf(
      "%s %s: eps = %.4f, (4.5) %.5g m/s, simulated %.5g m/s: error %+.2f %%; with the "
      "kernel-smeared "
      "faces %.5g m/s (%+.2f %% from 4.5), simulated %+.2f %% from it\n",
      file.c_str(), overrides.empty() ? "classic, h/d_big = 2" : "double smoothing, h/d_small = 2",
      r.eps, r.reference, r.slip, 100 * (r.slip / r.reference - 1), r.smeared,
      100 * (r.smeared / r.reference - 1), 100 * (r.slip / r.smeared - 1));
  std::printf(
      "  over the window: pressure force on the spheres %.4f of rho_av g V; the force balance with "
      "each "
      "sphere's window-mean voidage and pressure force %.5g m/s (%+.2f %% from 4.5), simulated "
      "%+.2f %% "
      "from it\n",
      r.buoyancy, r.balanced, 100 * (r.balanced / r.reference - 1),
      100 * (r.slip / r.balanced - 1));
  std::printf(
      "  with each sphere's own window-mean slip (spread %.2f %% of the mean): %.5g m/s (%+.2f %% "
      "from 4.5), "
      "simulated %+.2f %% from it\n",
      100 * r.slip_spread, r.closed, 100 * (r.closed / r.reference - 1),
      100 * (r.slip / r.closed - 1));
  return r;
}

const std::vector<std::string> kDouble = {"fluid.spacing=2.0e-4",
                                          "coupling.voidage_smoothing=double"};

}  // namespace

// (4.5) for a monodisperse mixture is the Beetstra force balance of one size:
// u = (rho_p - rho_f) g d^2 eps / (18 mu f_mono).
TEST(BidisperseBlock, ReferenceReducesToMonodisperse) {
  const double d = 1e-4, eps = 0.9, mu = 8.9e-4;
  const double u = theory::bidisperse_block_slip(d, d, 0.5, 2500, 1000, mu, 9.81, eps);
  const double re = 1000 * d * u / mu;
  EXPECT_NEAR(u, 1500 * 9.81 * d * d * eps / (18 * mu * theory::beetstra_f_mono(eps, re)), 1e-12);
}

// (4.5) for the 200/100 block (double smoothing: +2.83 % measured; classic at h/d_big = 2:
// +7.61 %) is a row of validation/report.py, which CI runs in its reduced mode.

// The 150/100 block misses the 4 % of issue #4: +7.3 % over the last period (the report's
// row; the 200/100 block +7.5 %), more than the monodisperse 100 um block with the same
// Beetstra drag at h/d = 2 (+6.1 %; with Di Felice +3.4 %). All of it is the kernel at the
// block's faces, which the face spheres see three ways; the block's force balance with
// what each sphere sees accounts for it step by step (seed-free lattice, 1 thread):
//                                     150/100 double  200/100 double  150/100 classic  200/100
//                                     classic
//   simulated                             +7.26 %         +7.44 %         +9.26 %          +12.56 %
//   voidage at release (smeared)          +5.77 %         +5.44 %         +7.62 %          +10.46 %
//   + window means of voidage and
//     pressure force (balanced)           +6.16 %         +5.19 %         +8.80 %          +12.29 %
//     (pressure force / rho_av g V)       0.9971          1.0031          0.9868           0.9793
//   + each sphere's own slip (closed)     +7.01 %         +7.58 %         +9.04 %          +12.55 %
//     (spread of the slips)               7.25 %          9.70 %          4.54 %           3.50 %
// The last step: the fluid velocity interpolated at a face sphere mixes the interstitial
// flow with the clear fluid's outside the block, so the slips differ between spheres
// and their count mean (the row's quantity) is not the one interstitial slip of the
// balance. What is left, 0.24 / -0.13 / 0.20 / 0.01 %, is the window's ringing. An
// unbounded block (the closed form's) has no faces; a taller one halves the error (the
// monodisperse block, validation/README.md).
// The tests: the voidage at release accounts for at least 70 % of the excess over (4.5),
// and the balance with all three closes within 0.5 %.
TEST(BidisperseBlock, Block150And100DoubleSmoothingExcessIsTheSmearedFaces) {
  const BlockRun r = run_block("block_bidisperse_150_100.yaml", kDouble);
  EXPECT_GT(r.slip, r.reference);
  EXPECT_LT(std::abs(r.slip - r.smeared), 0.3 * std::abs(r.slip - r.reference));
  EXPECT_NEAR(r.slip / r.closed, 1.0, 0.005);
}
