// The regime matrix's rows that test how the sound speed and the depth act on one
// sphere's drag (issue 14), with the defaults only (no coupling key): a 100 um sphere
// released 7 and 30 mm deep (c0 from the column: the extra drag of the hole a sphere
// drags through the fluid particles grows with depth and c0) within 1 % of the Stokes
// transient (4.1), and a 2.8 mm grain at the 1 m sand column's c0 = 44 m/s within 2 % of
// Brown-Lawler's terminal speed. The 1 mm depth is the report's single-sphere row.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "analysis/diagnostics.hpp"
#include "closed_forms.hpp"
#include "propagator/simulation.hpp"
#include "scene/scene.hpp"

using namespace sphdem;

namespace {

// single_particle.yaml (the sphere 4.8 mm above the wall) under `depth` of water, to
// 8 ms (5.1 t_d): the superficial slip against (4.1) at that time.
double sphere_slip_error(double depth) {
  const double H = 4.8e-3 + depth;
  const Scene sc = load_scene(SPHDEM_CASES_DIR "/single_particle.yaml",
                              {fmt::format("domain.size=[0.004,0.004,{}]", H), "time.end=0.008"});
  EXPECT_EQ(sc.fill_height(), H);
  const SpeciesSpec& sp = sc.species.at(0);
  const theory::StokesSettling stokes(sp.diameter, sp.density, sc.fluid.density, sc.fluid.viscosity,
                                      sc.gravity_magnitude());
  Simulation sim(sc);
  sim.relax();
  while (sim.time() < sc.time.end) sim.step();
  const Diagnostics d = diagnostics(sim);
  const double err = d.slip_z_mean.at(0) / stokes.speed(d.time) - 1;
  std::printf("%.0f mm deep: c0 = %.3g m/s, kernel %.3g h (%s), slip at %.4g s %+.2f %% of (4.1)\n",
              depth * 1e3, sc.fluid.sound_speed, sc.sphere_kernel_scale,
              sc.sphere_kernel_reason.c_str(), d.time, 100 * err);
  return err;
}

}  // namespace

TEST(SphereAtDepth, SevenMillimetres) {
  const double err = sphere_slip_error(7e-3);
  RecordProperty("slip_error", fmt::format("{:+.2f} %", 100 * err));
  EXPECT_LT(std::abs(err), 0.01);
}

TEST(SphereAtDepth, ThirtyMillimetres) {
  const double err = sphere_slip_error(30e-3);
  RecordProperty("slip_error", fmt::format("{:+.2f} %", 100 * err));
  EXPECT_LT(std::abs(err), 0.01);
}

// One 2.8 mm sand grain released 0.14 m up a 0.15 m column of water at the reduced sand
// column's resolution (dx = 5.56 mm, h/d = 2.98) and the 1 m column's c0; its mean
// superficial slip over 0.15-0.28 s (the grain from z ~ 0.10 to 0.055 m, at its terminal
// speed after ~0.1 s) against Brown-Lawler's terminal speed.
TEST(InertialGrain, TerminalSlipAtTheMetreColumnsSoundSpeed) {
  const Scene sc = load_scene_text(R"(
name: inertial_grain
domain: {size: [0.05, 0.05, 0.15]}
fluid: {density: 1000, viscosity: 1.0e-3, spacing: 5.5555555555555556e-3, sound_speed: 44}
species: [{name: sand, diameter: 2.8e-3, density: 2650}]
particles: [{type: single, species: sand, position: [0.025, 0.025, 0.14]}]
drag: {law: brown_lawler}
time: {end: 0.28}
startup: {relax_steps: 200}
)",
                                   "inertial_grain");
  const SpeciesSpec& sp = sc.species.at(0);
  const double v_t = theory::brown_lawler_terminal(sp.diameter, sp.density, sc.fluid.density,
                                                   sc.fluid.viscosity, sc.gravity_magnitude());
  Simulation sim(sc);
  sim.relax();
  double sum = 0;
  long n = 0;
  while (sim.time() < sc.time.end) {
    sim.step();
    if (sim.time() < 0.15) continue;
    sum += diagnostics(sim).slip_z_mean.at(0);
    ++n;
  }
  ASSERT_GT(n, 0);
  const double err = sum / n / v_t - 1;
  std::printf(
      "grain: v_T = %.4g m/s (Brown-Lawler), kernel %.3g h (%s), mean slip over "
      "0.15-%.3g s %+.2f %%\n",
      v_t, sc.sphere_kernel_scale, sc.sphere_kernel_reason.c_str(), sim.time(), 100 * err);
  RecordProperty("slip_error", fmt::format("{:+.2f} %", 100 * err));
  EXPECT_LT(std::abs(err), 0.02);
}
