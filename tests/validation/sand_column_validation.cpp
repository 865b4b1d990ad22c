// Sand column (Zhao, Houlsby & Utili 2014), reduced (cases/sand_column_reduced.yaml):
// the loads on the base against the column's momentum balance (eq. 15 plus the momentum
// rate), the segregation of the coarse grains to the base (four seeds pooled, with
// --pooled), and the bulk density of the bed against Zhao's 1965 kg/m^3. The peak against eq. 15
// needs the 1 m column (the full validation report runs its first 0.3 s): this one is too short to
// reach it.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <vector>

#include "analysis/bulk_density.hpp"
#include "analysis/diagnostics.hpp"
#include "analysis/pore_pressure.hpp"
#include "analysis/sediment_output.hpp"
#include "analysis/size_thirds.hpp"
#include "analysis/voidage_grid.hpp"
#include "closed_forms.hpp"
#include "propagator/simulation.hpp"
#include "scene/scene.hpp"

using namespace sphdem;

namespace {

struct Series {
  std::vector<double> t, u;
};

// Mean of y over the samples [i, k), each weighted by the step that follows it.
double step_weighted_mean(const std::vector<double>& t, const std::vector<double>& y, std::size_t i,
                          std::size_t k) {
  double acc = 0;
  for (std::size_t m = i; m < k; ++m) acc += y[m] * (t[m + 1] - t[m]);
  return acc / (t[k] - t[i]);
}

// Vertical momentum of the column: the spheres and the mobile fluid (kg m/s).
double column_momentum_z(const Simulation& sim) {
  const DemParticles& s = sim.spheres();
  const FluidParticles& f = sim.fluid();
  double p = 0.0;
  for (std::size_t j = 0; j < s.n_owned; ++j) p += s.mass[j] * s.vz[j];
  for (std::size_t a = 0; a < f.n_owned; ++a)
    if (f.kind[a] == kFluid) p += f.mass[a] * f.vz[a];
  return p;
}

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

// One run of the reduced column, shared by the tests below.
struct SandColumnRun {
  double n0 = 0, u_theory = 0, period = 0, load_unit = 0;  // load_unit = area rho_f |g| H (N)
  Series base;
  std::vector<double> fluid_load, wall_load, momentum;  // at the samples of base.t
  std::vector<double> smooth;
  SizeThirds thirds;
  double v_max = 0, v_mean = 0, z_top = 0, rho_bed_solid = 0, rho_profile_max = 0, wall_seconds = 0;
  // At the end: the fluid's pressure force on the spheres over their buoyancy rho_f g V,
  // and the wall particles' pairs' share of the fluid's load (rho_f g H units).
  double pressure_over_buoyancy = 0, wall_pairs_load = 0;
  double size_height_correlation = 0;  // Pearson r of (d, z) over all spheres at the end
  long steps = 0;
  // The segregation check pools the case's seed with these: one 0.1 m column segregates
  // by only 2-3 random-mixture deviations, the statistic's own scatter being 1.
  std::vector<std::int64_t> seeds;
  std::vector<SizeThirds> seed_thirds;  // of every seed, the case's first
};

// Extra seeds of the segregation check (the case's own is 2014), run with --pooled:
// three more columns, 3 x ~130 s on 1 thread. Without it (as ctest runs the test) the
// check is the full validation report's, which pools the same four seeds.
constexpr std::int64_t kExtraSeeds[] = {2015, 2016, 2017};
bool g_pooled = false;

class SandColumn : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    const auto wall0 = std::chrono::steady_clock::now();
    const Scene sc = load_scene(SPHDEM_CASES_DIR "/sand_column_reduced.yaml");
    const SpeciesSpec& sand = sc.species.at(0);
    Simulation sim(sc);
    const DemParticles& s = sim.spheres();
    SandColumnRun& r = run_;
    // Initial porosity of the column from the spheres actually placed.
    const double H = sc.fill_height(), area = sc.box.length(0) * sc.box.length(1);
    double solid = 0;
    for (std::size_t i = 0; i < s.n_owned; ++i) solid += s.volume(i);
    r.n0 = 1.0 - solid / (area * H);
    r.u_theory = theory::peak_excess_pore_pressure(r.n0, sand.density, sc.fluid.density);
    r.load_unit = area * sc.fluid.density * std::abs(sc.gravity[2]) * H;

    sim.relax();
    while (sim.time() < sc.time.end) {
      r.base.t.push_back(sim.time());
      const Diagnostics d = diagnostics(sim);
      r.base.u.push_back(d.excess_pore_pressure_base);
      r.fluid_load.push_back(d.fluid_load_base);
      r.wall_load.push_back(d.wall_load_base);
      r.momentum.push_back(column_momentum_z(sim));
      sim.step();
    }
    // The weakly compressible column rings at its acoustic period 4H/c0 (28.6 ms here)
    // after the release: the loads are compared as means over one period (the first
    // layer's reading too, in the CSV below).
    r.period = 4.0 * H / sc.fluid.sound_speed;
    r.smooth = moving_mean(r.base, r.period);
    r.thirds = size_thirds(s, sand.d_min(), sand.d_max(), 10);
    for (std::size_t i = 0; i < s.n_owned; ++i) {
      const double v = std::sqrt(s.vx[i] * s.vx[i] + s.vy[i] * s.vy[i] + s.vz[i] * s.vz[i]);
      r.v_max = std::max(r.v_max, v);
      r.v_mean += v / s.n_owned;
      r.z_top = std::max(r.z_top, s.z[i] + s.radius[i]);
    }
    // Bulk density of the bed two ways: (i) all the solid under the bed's top surface,
    // rho_f + (rho_s - rho_f) V_s / (A z_top), which z_top (the highest sphere's top)
    // biases low by up to half a grain layer; (ii) the largest value of the profile of the
    // grains' voidage at the lattice's h (its kernel's support about half the bed's
    // thickness, so it smooths the bed with the clear water above and the empty wall below).
    r.rho_bed_solid =
        sc.fluid.density + (sand.density - sc.fluid.density) * solid / (area * r.z_top);
    const GridSpec grid =
        column_voidage_grid(sc.box.length(0), sc.box.length(1), H, sc.fluid.spacing);
    const BulkDensityProfile prof =
        bulk_density_profile(grain_voidage_on_grid(sim, grid, sc.fluid.lattice_h()), grid,
                             sc.fluid.density, sand.density, H);
    r.rho_profile_max = *std::max_element(prof.bulk_density.begin(), prof.bulk_density.end());
    r.steps = sim.step_count();
    {
      double md = 0, mz = 0, sdd = 0, szz = 0, sdz = 0;
      const double n = static_cast<double>(s.n_owned);
      for (std::size_t i = 0; i < s.n_owned; ++i) md += 2 * s.radius[i] / n, mz += s.z[i] / n;
      for (std::size_t i = 0; i < s.n_owned; ++i) {
        const double dd = 2 * s.radius[i] - md, dz = s.z[i] - mz;
        sdd += dd * dd, szz += dz * dz, sdz += dd * dz;
      }
      r.size_height_correlation = sdz / std::sqrt(sdd * szz);
    }
    {
      double pz = 0;
      for (std::size_t i = 0; i < s.n_owned; ++i) pz += s.volume(i) * s.gz[i];
      r.pressure_over_buoyancy = pz / (solid * sc.fluid.density * std::abs(sc.gravity[2]));
      const BasePorePressure b{sc.fluid.density, std::abs(sc.gravity[2]), H, sc.fluid.spacing};
      r.wall_pairs_load = diagnostics(sim).fluid_load_base -
                          fluid_load_base(sim.fluid(), s, 0.0, sim.hydrostatic_split(), area, b);
    }

    // The end-of-run files, as `sphdem run` writes them, for a look
    // (scripts/plot_contact_network.py sand_column_validation_out), and the series.
    std::filesystem::create_directories("sand_column_validation_out");
    write_sediment_output(sim, "sand_column_validation_out");
    if (std::FILE* csv =
            std::fopen("sand_column_validation_out/excess_pore_pressure_base.csv", "w")) {
      std::fprintf(csv, "time,excess_pore_pressure_base,mean_over_acoustic_period\n");
      for (std::size_t k = 0; k < r.base.t.size(); ++k)
        std::fprintf(csv, "%.9g,%.9g,%.9g\n", r.base.t[k], r.base.u[k], r.smooth[k]);
      std::fclose(csv);
    }
    r.wall_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
    std::printf(
        "%zu spheres, initial porosity n = %.4f (H = %.4g m); %ld steps to t = %.3g s in %.0f s "
        "wall\n",
        s.n_owned, r.n0, H, r.steps, sim.time(), r.wall_seconds);
    r.seeds.push_back(sc.particles.at(0).seed);
    r.seed_thirds.push_back(r.thirds);
    for (const std::int64_t seed : kExtraSeeds) {
      if (!g_pooled) break;  // the one column only (as ctest runs it)
      const auto w0 = std::chrono::steady_clock::now();
      Scene other = sc;
      other.particles.at(0).seed = seed;
      Simulation column(other);
      column.relax();
      while (column.time() < other.time.end) column.step();
      r.seeds.push_back(seed);
      r.seed_thirds.push_back(size_thirds(column.spheres(), sand.d_min(), sand.d_max(), 10));
      std::printf("seed %lld: %zu spheres, %ld steps in %.0f s wall\n",
                  static_cast<long long>(seed), column.spheres().n_owned, column.step_count(),
                  std::chrono::duration<double>(std::chrono::steady_clock::now() - w0).count());
    }
  }
  static SandColumnRun run_;
};
SandColumnRun SandColumn::run_;

// The column's vertical momentum balance (solid + fluid, periodic sides): over any
// window, the mean of the base's loads, the fluid's on the wall particles
// (fluid_load_base) plus the spheres' contacts with the wall (wall_load_base), equals
// eq. 15 (the grains' buoyant weight) plus the rate of the column's upward momentum,
// both in rho_f |g| H. Every force from below is in one of the two loads and the pairs
// act and react exactly, so what is left is the sampling: the loads are read once per
// SPH step, the contacts between the DEM sub-steps and the drag's reaction a step late.
// Checked on every window of one acoustic period 4H/c0 (the column rings at it) and on
// the last one, where the bed is at rest and eq. 15 is carried by the contacts alone.
// The first fluid layer's reading (excess_pore_pressure_base) is not a load: without the
// case's hydrostatic split it stays at 0.36-0.38 at rest, twice eq. 15, while the wall
// carries 0.91 x eq. 15 in contacts (the kernel sums' error times the absolute pressure;
// with the split 0.008). Nor does this column reach eq. 15 as a peak: its grains reach
// their steady speed at ~0.1 s, after the lowest have landed; the 1 m column does, in the
// full report (validation/README.md).
TEST_F(SandColumn, BaseLoadsCloseTheMomentumBalance) {
  // Measured (seed 2014, 1 thread): worst window 0.32 % (t = 35 ms, the grains still
  // accelerating and landing), at rest 0.0041 + 0.1771 = 0.1813 (-0.14 %). With the first
  // layer's reading in place of the fluid's load the sum was 0.02-0.14 while the bed
  // formed (session 5, validation/README.md): the wall particles' pairs with the spheres
  // carry the difference.
  constexpr double TOLERANCE_ANY_WINDOW = 0.02, TOLERANCE_AT_REST = 0.01;  // of eq. 15
  const SandColumnRun& r = run_;
  const std::vector<double>& t = r.base.t;
  const std::size_t n = t.size();
  double worst = 0, t_worst = 0, peak_load = 0, t_peak = 0;
  for (std::size_t i = 0; i < n; ++i) {
    // Window [t_i, t_i + period].
    std::size_t k = i;
    while (k + 1 < n && t[k + 1] - t[i] <= r.period) ++k;
    if (t[k] - t[i] < 0.95 * r.period) break;  // the window runs past the end
    const double fl = step_weighted_mean(t, r.fluid_load, i, k),
                 wl = step_weighted_mean(t, r.wall_load, i, k);
    const double rate = (r.momentum[k] - r.momentum[i]) / (t[k] - t[i]) / r.load_unit;
    const double miss = std::abs(fl + wl - r.u_theory - rate) / r.u_theory;
    if (miss > worst) worst = miss, t_worst = t[i];
    if (fl > peak_load) peak_load = fl, t_peak = t[i] + 0.5 * r.period;
  }
  // The bed at rest: the last window.
  std::size_t i_end = n - 1;
  while (i_end > 0 && t[n - 1] - t[i_end - 1] <= r.period) --i_end;
  const double fl_end = step_weighted_mean(t, r.fluid_load, i_end, n - 1);
  const double wl_end = step_weighted_mean(t, r.wall_load, i_end, n - 1);
  std::printf(
      "eq. 15 = %.4f; loads + momentum rate against it, worst window (4H/c0 = %.3g s) %.2f %% at t "
      "= %.3g s; "
      "at rest: fluid %.4f + contacts %.4f = %.4f (%+.2f %%); peak of the fluid's load %.4f (%.2f "
      "x eq. 15) "
      "at %.3g s; first layer's reading at rest %.4f\n",
      r.u_theory, r.period, 100 * worst, t_worst, fl_end, wl_end, fl_end + wl_end,
      100 * ((fl_end + wl_end) / r.u_theory - 1), peak_load, peak_load / r.u_theory, t_peak,
      r.smooth.back());
  RecordProperty("worst_window_error", fmt::format("{:.4f}", worst));
  RecordProperty("at_rest_error", fmt::format("{:+.4f}", (fl_end + wl_end) / r.u_theory - 1));
  EXPECT_LT(worst, TOLERANCE_ANY_WINDOW);
  EXPECT_NEAR((fl_end + wl_end) / r.u_theory, 1.0, TOLERANCE_AT_REST);
  std::printf(
      "at the end: the fluid's pressure force on the spheres %.4f x their buoyancy rho_f g V; the "
      "wall "
      "particles' pairs with the spheres carry %.4f of the fluid's load\n",
      r.pressure_over_buoyancy, r.wall_pairs_load);
  // The bed's weight is on its contacts, not on the fluid: a bed at rest leaves the fluid
  // none of it. Measured (1 thread) 2.3 %: the fluid's pressure force on the resting
  // spheres is 1.014 x rho_f g V. Without the case's hydrostatic split (and at h) it was
  // 9.8 % and 1.15 x: the variational pairs' kernel sums in the disordered bed times the
  // absolute pressure (the wall particles' pairs alone pushed the lowest spheres up by
  // 0.28 rho_f g H and the fluid above pushed them back).
  EXPECT_LT(std::abs(fl_end) / r.u_theory, 0.05);
}

// Coarse grains at the base (Zhao et al. Fig. 7): the mean d of the bottom third of the
// spheres against the top third's. For a random mixture the difference of two disjoint
// samples of n_b and n_t spheres has standard deviation sigma_d sqrt(1/n_b + 1/n_t)
// (sigma_d = 0.58 mm for the uniform law on [1.8, 3.8] mm: 0.031 mm for ~705 spheres per
// third). One 0.1 m column is too short to decide: the grains that land first (the
// lowest, during the ~0.05 s they accelerate) land in size order only loosely, so the
// middle third comes out as coarse as the bottom one, and the bottom - top difference is
// 2-3 of those deviations whatever the coupling (session 5: 2.2-4.2 over six couplings,
// one seed each). So the check pools independent columns (the case's seed and
// kExtraSeeds, with --pooled; without it the test prints the one column's and skips): their
// differences add, and so do their variances; coarse grains at the base means a pooled difference
// beyond 3 pooled deviations (a random mixture exceeds it with probability 0.13 %). Measured (1
// thread, --pooled, 488 s): seeds 2014-2017 +3.06, +2.06, +2.52, +1.55, pooled +4.60. The middle
// third is the coarsest in all four (2.85-2.90 mm, the bottom 2.80-2.82, the top 2.73-2.76,
// the law's mean 2.80): the bottom third is nearly a random mixture, the grains that landed while
// still accelerating.
TEST_F(SandColumn, CoarseGrainsAtTheBase) {
  const SandColumnRun& r = run_;
  double diff_sum = 0, var_sum = 0;
  for (std::size_t k = 0; k < r.seeds.size(); ++k) {
    const SizeThirds& th = r.seed_thirds[k];
    const double sd = th.std_d * std::sqrt(1.0 / th.third[0].count + 1.0 / th.third[2].count);
    const double diff = th.third[0].mean_d - th.third[2].mean_d;
    std::printf(
        "seed %lld: mean d bottom %.4g, middle %.4g, top %.4g mm; bottom - top = %.4g mm = %.2f x "
        "the "
        "random-mixture deviation %.3g mm\n",
        static_cast<long long>(r.seeds[k]), 1e3 * th.third[0].mean_d, 1e3 * th.third[1].mean_d,
        1e3 * th.third[2].mean_d, 1e3 * diff, diff / sd, 1e3 * sd);
    diff_sum += diff;
    var_sum += sd * sd;
  }
  const double pooled = diff_sum / std::sqrt(var_sum);
  std::printf("pooled over %zu seeds: bottom - top = %.2f x the random-mixture deviation\n",
              r.seeds.size(), pooled);
  RecordProperty("segregation_deviations", fmt::format("{:.2f}", pooled));
  RecordProperty("segregation_seeds", static_cast<int>(r.seeds.size()));
  const SizeThirds& th = r.thirds;
  std::printf(
      "seed %lld, d10/d50/d90 (mm): bottom %.3f/%.3f/%.3f, middle %.3f/%.3f/%.3f, top "
      "%.3f/%.3f/%.3f\n",
      static_cast<long long>(r.seeds.front()), 1e3 * th.third[0].d10, 1e3 * th.third[0].d50,
      1e3 * th.third[0].d90, 1e3 * th.third[1].d10, 1e3 * th.third[1].d50, 1e3 * th.third[1].d90,
      1e3 * th.third[2].d10, 1e3 * th.third[2].d50, 1e3 * th.third[2].d90);
  // Informative: the same question asked of all the spheres of the case's seed, the
  // correlation of d with height (a random mixture gives r sqrt(n - 2) / sqrt(1 - r^2)
  // ~ N(0, 1)); with the middle third as coarse as the bottom one it is no stronger.
  const double rc = r.size_height_correlation,
               n = th.third[0].count + th.third[1].count + th.third[2].count;
  std::printf(
      "correlation of d with height over all %.0f spheres: r = %.4f, %.1f random-mixture "
      "deviations\n",
      n, rc, rc * std::sqrt(n - 2) / std::sqrt(1 - rc * rc));
  if (!g_pooled)
    GTEST_SKIP()
        << "one 0.1 m column segregates by only 2-3 random-mixture deviations, as much as "
           "the statistic's scatter: the check pools four seeds (--pooled, ~6 min more; the "
           "full validation report runs them too)";
  EXPECT_GT(pooled, 3.0);
}

// Zhao et al. report 1965 kg/m^3 for the final sediment (n = 0.415). Random packings of
// frictional spheres (mu = 0.577) settle at n = 0.40-0.45, 1907-1990 kg/m^3, i.e. within
// 3 % of that value. Measured (seed 2014, 1 thread): the bed at rest (mean sphere speed
// 5e-5 m/s at 0.6 s), profile maximum 1932 kg/m^3 (-1.7 %); the kernel (support 16.7 mm
// against a 21 mm bed) smooths the bed with the clear water above, so this is biased
// low. The solid under the highest sphere's top gives 1857 kg/m^3 (biased low by the
// rough top, up to half a grain layer).
TEST_F(SandColumn, BedBulkDensityMatchesZhao) {
  const SandColumnRun& r = run_;
  std::printf(
      "end: mean sphere speed %.3g m/s, fastest %.3g m/s, bed top %.4g m; bed bulk density %.0f "
      "kg/m^3 "
      "(solid under the top), %.0f kg/m^3 (profile max); Zhao: 1965 kg/m^3\n",
      r.v_mean, r.v_max, r.z_top, r.rho_bed_solid, r.rho_profile_max);
  RecordProperty("bed_mean_speed_m_per_s", fmt::format("{:.3g}", r.v_mean));
  EXPECT_LT(r.v_mean, 0.01);  // the bed has come to rest (a falling grain moves at ~0.2 m/s)
  EXPECT_NEAR(r.rho_profile_max / 1965.0, 1.0, 0.03);
}

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  for (int k = 1; k < argc; ++k) g_pooled = g_pooled || std::strcmp(argv[k], "--pooled") == 0;
  return RUN_ALL_TESTS();
}
