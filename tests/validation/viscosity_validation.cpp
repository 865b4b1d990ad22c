// The effective viscosity of the SPH fluid, measured (physics.md §1): a shear wave
// u_x = U sin(2 pi y / L) must decay as exp(-nu (2 pi / L)^2 t) with nu = mu / rho_f.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "propagator/simulation.hpp"
#include "scene/scene.hpp"

using namespace sphdem;

namespace {

// Decay rate of the shear wave's amplitude, fitted by least squares to ln A(t) over
// the particles between 3.0 and 6.4 mm: the no-slip wall's boundary layer, of width
// 2 sqrt(nu t) <= 1.4 mm here, stays below 1 % there (erfc(3.0/1.4) = 0.002), and the
// top 0.8 mm, where the free surface truncates the kernel, is left out too.
// The fit runs over [t0, t1] in units of the decay time 1/(nu k^2).
// With `voidage` < 1 the fluid fills a simple-cubic lattice of fixed spheres (heavy,
// no gravity, no drag: `drag.law: none`) at that voidage, and the wave must decay at
// mu / (eps rho_f) k^2: (2.32) for uniform eps is eps rho_f du/dt = mu lap u.
struct ShearWave {
  double viscosity = 0.02, sound_speed = 1.0, alpha_artificial = 0.0;
  double t0 = 0.1, t1 = 0.8;
  double voidage = 1.0, sphere_diameter = 1.0e-4;
};

struct Decay {
  double nu = 0;   // fitted k^-2 d(-ln A)/dt (m^2/s)
  double eps = 1;  // mean voidage of the fitted band's fluid particles
};

Decay measured_decay(const ShearWave& w) {
  std::string yaml =
      fmt::format(R"(
name: shear_wave
domain: {{size: [0.0016, 0.0048, 0.0072]}}
gravity: [0, 0, 0]
fluid: {{density: 1000, viscosity: {}, spacing: 2.0e-4, smoothing_factor: 1.5, sound_speed: {},
        alpha_artificial: {}}}
startup: {{relax_steps: {}}}
time: {{end: 10.0}}
)",
                  w.viscosity, w.sound_speed, w.alpha_artificial, w.voidage < 1.0 ? 100 : 0);
  if (w.voidage < 1.0)
    yaml += fmt::format(R"(
species: [{{name: fixed, diameter: {}, density: 1.0e12}}]
particles:
  - {{type: lattice, species: fixed, voidage: {}, min: [0, 0, 0], max: [0.0016, 0.0048, 0.0072],
     rigid: true}}
drag: {{law: none}}
)",
                        w.sphere_diameter, w.voidage);
  const Scene sc = load_scene_text(yaml, "shear_wave.yaml");
  Simulation sim(sc);
  if (w.voidage < 1.0) sim.relax();
  const double L = sc.box.length(1), k = 2.0 * M_PI / L, U = 1e-3;
  const double nu = sc.fluid.viscosity / (w.voidage * sc.fluid.density), tau = 1.0 / (nu * k * k);
  FluidParticles& f = sim.fluid();
  for (std::size_t a = 0; a < f.n_owned; ++a)
    if (f.kind[a] == kFluid) f.vx[a] = U * std::sin(k * f.y[a]);
  sim.refresh();
  auto amplitude = [&] {
    double num = 0, den = 0;
    for (std::size_t a = 0; a < f.n_owned; ++a) {
      if (f.kind[a] != kFluid || f.z[a] < 0.0030 || f.z[a] > 0.0064) continue;
      const double s = std::sin(k * f.y[a]);
      num += f.vx[a] * s;
      den += s * s;
    }
    return num / den;
  };
  Decay out;
  {
    double sum = 0;
    int count = 0;
    for (std::size_t a = 0; a < f.n_owned; ++a)
      if (f.kind[a] == kFluid && f.z[a] >= 0.0030 && f.z[a] <= 0.0064) {
        sum += f.eps[a];
        ++count;
      }
    out.eps = sum / count;
  }
  double st = 0, sl = 0, stt = 0, stl = 0;
  int n = 0;
  while (sim.time() < w.t1 * tau) {
    sim.step();
    if (sim.time() < w.t0 * tau) continue;
    const double t = sim.time(), l = std::log(amplitude());
    st += t;
    sl += l;
    stt += t * t;
    stl += t * l;
    ++n;
  }
  const double slope = (n * stl - st * sl) / (n * stt - st * st);
  out.nu = -slope / (k * k);
  return out;
}

double measured_viscosity(const ShearWave& w) {
  return measured_decay(w).nu;
}

}  // namespace

TEST(Viscosity, ShearWaveDecaysWithThePhysicalViscosity) {
  const double nu = 0.02 / 1000.0;
  const double nu0 = measured_viscosity({});
  std::printf("Morris viscosity: measured nu = %.4g m^2/s, mu/rho_f = %.4g (%+.2f %%)\n", nu0, nu,
              100 * (nu0 / nu - 1));
  // The Morris term is a consistent second-derivative estimate whose error grows as
  // (k h)^2; with 24 particles per wavelength (k h = 0.39) it is ~1 %.
  EXPECT_NEAR(nu0 / nu, 1.0, 0.03);

  ShearWave artificial;
  artificial.alpha_artificial = 0.1;
  const double nu_a = measured_viscosity(artificial);
  std::printf("with alpha_artificial = 0.1: nu = %.4g m^2/s (%+.2f %% over mu/rho_f)\n", nu_a,
              100 * (nu_a / nu - 1));
  // Monaghan's term acts only on approaching pairs; for alpha = 0.1, c0 = 1 m/s and
  // h = 0.3 mm its full-strength equivalent alpha h c0 / 10 is 3e-6 m^2/s (15 % of
  // nu); in a shear wave about half the pairs approach, so it adds a positive share.
  EXPECT_GT(nu_a, nu0);
  EXPECT_LT(nu_a, nu0 + 3e-6);
}

// Water at the resolution and sound speed of the 6 mm scenes (dx = 0.2 mm, h = 1.5 dx,
// c0 = 3.431 m/s: single_particle, block_monodisperse, suspension_monodisperse): the
// Morris term alone gives water's viscosity (to the 5 % of issue 14's matrix); with
// those cases' alpha_artificial = 0.02 the Monaghan term adds a share of its
// full-strength equivalent alpha h c0 / 10 = 2.06e-6 m^2/s (2.3 x water's) — the share a
// shear wave brings out is measured and printed (bench/TRADEOFF.md), and must lie
// between none and all of it. The fit covers 0.05-0.3 decay times (0.04-0.2 s), where
// the wall's boundary layer (2 sqrt(nu t) <= 1.6 mm) stays below the fitted band.
TEST(Viscosity, WaterAtTheSixMillimetreCasesResolution) {
  const double nu = 8.9e-4 / 1000.0, c0 = 3.431, h = 1.5 * 2.0e-4;
  ShearWave water;
  water.viscosity = 8.9e-4;
  water.sound_speed = c0;
  water.t0 = 0.05;
  water.t1 = 0.3;
  const double nu0 = measured_viscosity(water);
  ShearWave cases = water;
  cases.alpha_artificial = 0.02;
  const double nu_a = measured_viscosity(cases);
  const double full = 0.02 * h * c0 / 10.0;
  std::printf(
      "water, dx = 0.2 mm, c0 = %.4g m/s: Morris alone nu = %.4g m^2/s (%+.2f %% of mu/rho_f); "
      "with alpha = 0.02 nu = %.4g m^2/s (%.2f x mu/rho_f; the Monaghan part %.3g = %.2f of alpha "
      "h c0/10)\n",
      c0, nu0, 100 * (nu0 / nu - 1), nu_a, nu_a / nu, nu_a - nu0, (nu_a - nu0) / full);
  RecordProperty("morris_error", fmt::format("{:+.4f}", nu0 / nu - 1));
  EXPECT_NEAR(nu0 / nu, 1.0, 0.05);
  EXPECT_GT(nu_a - nu0, 0.0);
  EXPECT_LT(nu_a - nu0, full);
}

// Issue 14's matrix: the viscosity at eps = 0.6, at the 6 mm cases' h (dx = 0.2 mm) and
// c0, with the defaults (Morris alone, alpha 0), among fixed spheres on a lattice. The
// SPH viscous term divides by the superficial density eps rho_f, so the wave decays at
// mu / (eps rho_f) k^2; a term written with rho_f, or carrying eps inside the
// divergence's sum, would be off by the factor eps (40 %). Effective viscosity
// mu_eff = eps rho_f nu_measured, with eps the band's mean. The spheres are 200 um (the
// cases' are 100 um: 8 times the spheres, 4 times the run) on a lattice 0.22 mm apart,
// finer than dx = 0.2 mm's kernel (support 0.71 mm). Measured when written: -2.2 % (as
// -2.2 % at eps = 1); with 300 um spheres (d/dx = 1.5, 0.33 mm apart) +63 %: the fluid
// particles then feel each sphere's hole in eps and lose the wave's energy to it, the
// averaged equations' limit d < dx.
TEST(Viscosity, WaterAmongFixedSpheresAtVoidageSixTenths) {
  ShearWave w;
  w.viscosity = 8.9e-4;
  w.sound_speed = 3.431;
  w.t0 = 0.05;
  w.t1 = 0.3;
  w.voidage = 0.6;
  w.sphere_diameter = 2.0e-4;
  const Decay d = measured_decay(w);
  const double mu_eff = d.eps * 1000.0 * d.nu;
  std::printf(
      "eps = %.4f (lattice 0.6, spheres %.0f um): nu = %.4g m^2/s, mu/(eps rho_f) = %.4g; "
      "mu_eff = eps rho_f nu = %.4g Pa s (%+.2f %% of mu)\n",
      d.eps, 1e6 * w.sphere_diameter, d.nu, 8.9e-4 / (d.eps * 1000.0), mu_eff,
      100 * (mu_eff / 8.9e-4 - 1));
  RecordProperty("voidage", fmt::format("{:.4f}", d.eps));
  RecordProperty("mu_eff_error", fmt::format("{:+.4f}", mu_eff / 8.9e-4 - 1));
  EXPECT_NEAR(d.eps, 0.6, 0.01);
  EXPECT_NEAR(mu_eff / 8.9e-4, 1.0, 0.05);
}
