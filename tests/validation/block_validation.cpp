// Constant-porosity block (thesis §4.5) against the Di Felice terminal slip (4.4).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "analysis/diagnostics.hpp"
#include "closed_forms.hpp"
#include "propagator/simulation.hpp"
#include "scene/initial_state.hpp"
#include "scene/scene.hpp"

using namespace sphdem;

TEST(MonodisperseBlock, MeanSlipMatchesDiFelice) {
  const Scene sc = load_scene(SPHDEM_CASES_DIR "/block_monodisperse.yaml", {"time.end=0.016"});
  const SpeciesSpec& sp = sc.species.at(0);
  const double eps = block_lattice(sc, sc.particles.at(0), sp.diameter).voidage;
  const double v_ref = theory::di_felice_block_slip(
      sp.diameter, sp.density, sc.fluid.density, sc.fluid.viscosity, std::abs(sc.gravity[2]), eps);
  Simulation sim(sc);
  sim.relax();
  // The weakly compressible column rings at its acoustic period 4H/c0 (7 ms here):
  // average the slip over whole periods after the start-up transient.
  const double period = 4.0 * sc.fill_height() / sc.fluid.sound_speed;
  const double t0 = sc.time.end - 2.0 * period;
  double sum = 0, wsum = 0;
  while (sim.time() < sc.time.end) {
    sim.step();
    if (sim.time() > t0) {
      sum += diagnostics(sim).slip_z_mean[0] * sim.dt_sph();
      wsum += sim.dt_sph();
    }
  }
  const double slip = sum / wsum;
  std::printf(
      "eps = %.4f: Di Felice slip (4.4) %.5g m/s, simulated mean slip %.5g m/s over [%.4g, %.4g] "
      "s: "
      "error %+.2f %%\n",
      eps, v_ref, slip, t0, sc.time.end, 100 * (slip / v_ref - 1));
  EXPECT_NEAR(v_ref, 0.004924, 0.00003);  // the thesis' value of (4.4) at eps = 0.9
  EXPECT_NEAR(slip / v_ref, 1.0, 0.05);   // issue #2: within 5 %
}
