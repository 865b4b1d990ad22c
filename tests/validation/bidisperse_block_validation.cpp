// Bidisperse constant-porosity blocks (thesis §4.6, §5.3) against eq. (4.5), resolved the
// two ways the thesis compared: the classic single smoothing at h/d_big = 2, and the
// double smoothing (3.8-3.10) at h/d_small = 2.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "closed_forms.hpp"
#include "run/initial_state.hpp"
#include "run/scene.hpp"
#include "run/simulation.hpp"

using namespace sphdem;

namespace {

struct BlockRun {
  double eps, reference, slip;
};

// Mean superficial slip of the whole block (both sizes, by sphere count) over the last
// two acoustic periods 4H/c0 of a 16 ms run, as the monodisperse block.
BlockRun run_block(const std::string& file, const std::vector<std::string>& overrides) {
  std::vector<std::string> set = overrides;
  set.push_back("time.end=0.016");
  const Scene sc = load_scene(std::string(SPHDEM_CASES_DIR) + "/" + file, set);
  const SpeciesSpec& big = sc.species.at(0);
  const SpeciesSpec& small = sc.species.at(1);
  BlockRun r;
  r.eps = block_lattice(sc, sc.particles.at(0)).voidage;
  r.reference = theory::bidisperse_block_slip(big.diameter, small.diameter, sc.particles.at(0).fractions.at(0),
                                              big.density, sc.fluid.density, sc.fluid.viscosity,
                                              std::abs(sc.gravity[2]), r.eps);
  Simulation sim(sc);
  const DemParticles& s = sim.spheres();
  double n_big = 0;
  for (std::size_t i = 0; i < s.n_owned; ++i) n_big += s.species[i] == 0;
  const double w_big = n_big / static_cast<double>(s.n_owned);
  sim.relax();
  const double period = 4.0 * sc.fill_height() / sc.fluid.sound_speed;
  const double t0 = sc.time.end - 2.0 * period;
  double sum = 0, wsum = 0;
  while (sim.time() < sc.time.end) {
    sim.step();
    if (sim.time() > t0) {
      const auto d = sim.diagnostics();
      sum += (w_big * d.slip_z_mean[0] + (1.0 - w_big) * d.slip_z_mean[1]) * sim.dt_sph();
      wsum += sim.dt_sph();
    }
  }
  r.slip = sum / wsum;
  std::printf("%s %s: eps = %.4f, (4.5) %.5g m/s, simulated %.5g m/s: error %+.2f %%\n", file.c_str(),
              overrides.empty() ? "classic, h/d_big = 2" : "double smoothing, h/d_small = 2", r.eps, r.reference,
              r.slip, 100 * (r.slip / r.reference - 1));
  return r;
}

const std::vector<std::string> kDouble = {"fluid.spacing=2.0e-4", "coupling.voidage_smoothing=double"};

}  // namespace

// (4.5) for a monodisperse mixture is the Beetstra force balance of one size:
// u = (rho_p - rho_f) g d^2 eps / (18 mu f_mono).
TEST(BidisperseBlock, ReferenceReducesToMonodisperse) {
  const double d = 1e-4, eps = 0.9, mu = 8.9e-4;
  const double u = theory::bidisperse_block_slip(d, d, 0.5, 2500, 1000, mu, 9.81, eps);
  const double re = 1000 * d * u / mu;
  EXPECT_NEAR(u, 1500 * 9.81 * d * d * eps / (18 * mu * theory::beetstra_f_mono(eps, re)), 1e-12);
}

// issue #4: under 4 % at h/d = 2 (the thesis reached 4.3 % for the monodisperse block).
TEST(BidisperseBlock, Block150And100DoubleSmoothing) {
  const BlockRun r = run_block("block_bidisperse_150_100.yaml", kDouble);
  EXPECT_NEAR(r.slip / r.reference, 1.0, 0.04);
}
TEST(BidisperseBlock, Block200And100DoubleSmoothing) {
  const BlockRun r = run_block("block_bidisperse_200_100.yaml", kDouble);
  EXPECT_NEAR(r.slip / r.reference, 1.0, 0.04);
}
TEST(BidisperseBlock, Block200And100Classic) {
  const BlockRun r = run_block("block_bidisperse_200_100.yaml", {});
  EXPECT_NEAR(r.slip / r.reference, 1.0, 0.04);
}
