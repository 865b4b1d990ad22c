// Sand column (Zhao, Houlsby & Utili 2014), reduced (cases/sand_column_reduced.yaml):
// the excess pore pressure at the base against eq. 15, the segregation of the coarse
// grains to the base, and the bulk density of the bed (reported).
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <vector>

#include "closed_forms.hpp"
#include "run/bulk_density.hpp"
#include "run/scene.hpp"
#include "run/simulation.hpp"
#include "run/size_thirds.hpp"

using namespace sphdem;

namespace {

struct Series {
  std::vector<double> t, u;
};

// Mean of u over the window [t - w/2, t + w/2] at every sample, each sample weighted by
// the step that follows it (the samples are the SPH steps, not evenly spaced).
std::vector<double> moving_mean(const Series& s, double w) {
  const std::size_t n = s.t.size();
  std::vector<double> out(n);
  for (std::size_t i = 0; i < n; ++i) {
    double acc = 0, dur = 0;
    for (std::size_t k = 0; k + 1 < n; ++k) {
      if (std::abs(s.t[k] - s.t[i]) > 0.5 * w) continue;
      const double dt = s.t[k + 1] - s.t[k];
      acc += s.u[k] * dt;
      dur += dt;
    }
    out[i] = dur > 0 ? acc / dur : s.u[i];
  }
  return out;
}

}  // namespace

TEST(SandColumn, PorePressureSegregationAndBed) {
  const auto wall0 = std::chrono::steady_clock::now();
  const Scene sc = load_scene(SPHDEM_CASES_DIR "/sand_column_reduced.yaml");
  const SpeciesSpec& sand = sc.species.at(0);
  Simulation sim(sc);
  const DemParticles& s = sim.spheres();
  // Initial porosity of the column from the spheres actually placed.
  const double H = sc.fill_height(), area = sc.box.length(0) * sc.box.length(1);
  double solid = 0;
  for (std::size_t i = 0; i < s.n_owned; ++i) solid += s.volume(i);
  const double n0 = 1.0 - solid / (area * H);
  const double u_theory = theory::peak_excess_pore_pressure(n0, sand.density, sc.fluid.density);

  sim.relax();
  Series base;
  while (sim.time() < sc.time.end) {
    base.t.push_back(sim.time());
    base.u.push_back(sim.diagnostics().excess_pore_pressure_base);
    sim.step();
  }
  // The weakly compressible column rings at its acoustic period 4H/c0 (28 ms here) after
  // the release: the peak is taken on the mean over one period.
  const double period = 4.0 * H / sc.fluid.sound_speed;
  const std::vector<double> smooth = moving_mean(base, period);
  const std::size_t k_peak = std::max_element(smooth.begin(), smooth.end()) - smooth.begin();
  const double raw_max = *std::max_element(base.u.begin(), base.u.end());
  std::printf("%zu spheres, initial porosity n = %.4f (H = %.4g m): (1 - n)(rho_s/rho_f - 1) = %.4f\n",
              s.n_owned, n0, H, u_theory);
  std::printf("excess pore pressure at the base / (rho_f g H): peak of the %.3g s mean %.4f at t = %.4g s "
              "(ratio %.3f), raw max %.4f, at the end %.4f\n",
              period, smooth[k_peak], base.t[k_peak], smooth[k_peak] / u_theory, raw_max, smooth.back());

  // Segregation: mean d of the bottom third against the top third. For a random mixture
  // the difference of two disjoint samples of n_b and n_t spheres has standard deviation
  // sigma_d sqrt(1/n_b + 1/n_t) (sigma_d = 0.58 mm for the uniform law on [1.8, 3.8] mm:
  // 0.06 mm for ~175 spheres per third). Coarse grains at the base means a difference
  // beyond 3 of those (a random mixture exceeds it with probability 0.13 %).
  const SizeThirds th = size_thirds(s, sand.d_min(), sand.d_max(), 10);
  const double sd_random = th.std_d * std::sqrt(1.0 / th.third[0].count + 1.0 / th.third[2].count);
  const double diff = th.third[0].mean_d - th.third[2].mean_d;
  std::printf("mean d: bottom %.4g mm, middle %.4g mm, top %.4g mm; bottom - top = %.4g mm = %.1f x the "
              "random-mixture deviation %.3g mm\n", 1e3 * th.third[0].mean_d, 1e3 * th.third[1].mean_d,
              1e3 * th.third[2].mean_d, 1e3 * diff, diff / sd_random, 1e3 * sd_random);
  std::printf("d10/d50/d90 (mm): bottom %.3f/%.3f/%.3f, middle %.3f/%.3f/%.3f, top %.3f/%.3f/%.3f\n",
              1e3 * th.third[0].d10, 1e3 * th.third[0].d50, 1e3 * th.third[0].d90, 1e3 * th.third[1].d10,
              1e3 * th.third[1].d50, 1e3 * th.third[1].d90, 1e3 * th.third[2].d10, 1e3 * th.third[2].d50,
              1e3 * th.third[2].d90);

  // The bed: settled when the fastest sphere moves at < 1 % of the hindered settling speed.
  double vmax = 0, z_top = 0;
  for (std::size_t i = 0; i < s.n_owned; ++i) {
    vmax = std::max(vmax, std::sqrt(s.vx[i] * s.vx[i] + s.vy[i] * s.vy[i] + s.vz[i] * s.vz[i]));
    z_top = std::max(z_top, s.z[i] + s.radius[i]);
  }
  // Bulk density of the bed two ways: (i) all the solid under the bed's top surface,
  // rho_f + (rho_s - rho_f) V_s / (A z_top), which z_top (the highest sphere's top)
  // biases low by up to half a grain layer; (ii) the largest value of the voidage-grid
  // profile (kernel support 2h = 9.4 mm, about half the bed's thickness, so it smooths
  // the bed with the clear water above and the empty wall below).
  const double rho_bed_solid = sc.fluid.density + (sand.density - sc.fluid.density) * solid / (area * z_top);
  const double h = sc.fluid.smoothing_factor * sc.fluid.spacing;
  const GridSpec grid = column_voidage_grid(sc.box.length(0), sc.box.length(1), sc.box.length(2), sc.fluid.spacing, h);
  const BulkDensityProfile prof =
      bulk_density_profile(sim.voidage_on_grid(grid, h), grid, sc.fluid.density, sand.density, H);
  const double rho_profile_max = *std::max_element(prof.bulk_density.begin(), prof.bulk_density.end());
  const double wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  std::printf("end t = %.3g s: fastest sphere %.3g m/s, bed top %.4g m; bed bulk density %.0f kg/m^3 (solid under "
              "the top), %.0f kg/m^3 (profile max); Zhao: 1965 kg/m^3. Wall time %.0f s, %ld steps\n",
              sim.time(), vmax, z_top, rho_bed_solid, rho_profile_max, wall_s, sim.step_count());

  EXPECT_NEAR(smooth[k_peak] / u_theory, 1.0, 0.10);  // issue 4: within 10 % of eq. 15
  EXPECT_GT(diff, 3.0 * sd_random);                    // coarse grains enriched at the base
  // The bed's bulk density is reported, not tested: at ~530 grains the bed is ~7 grains
  // thick, comparable to the kernel support, and its top layer is a sizeable part of it.
}
