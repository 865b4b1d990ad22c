// Density diffusion (sph/density_diffusion.hpp, delta-SPH): in the `hydrostatic` form a sine
// of the fluid's density on a lattice at rest decays at the diffusivity delta h c0 (the
// closed form of the term's continuum limit, eps delta h c0 lap(psi)), with either
// instruction set; in the `renormalised` form a psi linear in space gets no term at all,
// at a wall too (where the `hydrostatic` form makes a sink of fluid volume), and a sine
// decays as (k h)^4; the fluid at rest is a zero of the term (psi = 0 everywhere at the
// hydrostatic start) and a water column with it stays at rest.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "analysis/diagnostics.hpp"
#include "domain/cell_list.hpp"
#include "domain/neighbour_list.hpp"
#include "propagator/simulation.hpp"
#include "scene/scene.hpp"
#include "sph/density_rate.hpp"
#include "sph/diffusion_gradient.hpp"
#include "sph/kernel.hpp"

namespace {

using namespace sphdem;

// A lattice of spacing 1 at rest, nx x 11 x 11, psi = A sin(k x), every particle a
// fluid particle of volume 1 and h = 1.5; D_a / (eps delta h c0) at the particles whose
// kernel lies inside the lattice, against -k^2 psi_a. Returns the worst relative error
// where |sin| > 0.5.
double sine_decay_error(int nx, double wavelength, PairIsa isa) {
  const int ny = 11;
  FluidParticles f;
  const std::size_t n = static_cast<std::size_t>(nx) * ny * ny;
  f.n_owned = n;
  f.resize(n);
  const double k = 2.0 * M_PI / wavelength, amplitude = 0.5, h = 1.5;
  for (std::size_t i = 0; i < n; ++i) {
    f.x[i] = static_cast<double>(i % nx);
    f.y[i] = static_cast<double>(i / nx % ny);
    f.z[i] = static_cast<double>(i / (static_cast<std::size_t>(nx) * ny));
    f.vx[i] = f.vy[i] = f.vz[i] = 0.0;  // at rest: (2.53)'s own sum is zero
    f.h[i] = h;
    f.inv_h[i] = 1.0 / h;
    f.rho[i] = 1000.0;
    f.mass[i] = 1000.0;
    f.eps[i] = 0.8;
    f.P[i] = 0.0;
    f.kind[i] = kFluid;
    f.diffusion_psi[i] = amplitude * std::sin(k * f.x[i]);
    f.diffusion_volume[i] = f.mass[i] / f.rho[i];
  }
  const double rc = kernel::kSupport * h + 0.1;
  CellList cells;
  cells.build(f.x.data(), f.y.data(), f.z.data(), n, rc, 2);
  NeighbourList half;
  half.build(cells, f.x.data(), f.y.data(), f.z.data(), n, rc, true, /*half=*/true);
  DensityDiffusion dd;
  dd.delta = 0.1;
  dd.c0 = 20.0;
  PairAccumulator acc;
  compute_density_rate(f, half, acc, false, {}, dd, isa);
  double worst = 0.0;
  const double reach = kernel::kSupport * h;
  for (std::size_t i = 0; i < n; ++i) {
    const bool inside = f.x[i] >= reach && f.x[i] <= nx - 1 - reach && f.y[i] >= reach &&
                        f.y[i] <= ny - 1 - reach && f.z[i] >= reach && f.z[i] <= ny - 1 - reach;
    const double s = std::sin(k * f.x[i]);
    if (!inside || std::abs(s) < 0.5) continue;
    const double want = -dd.delta * h * dd.c0 * f.eps[i] * k * k * amplitude * s;
    worst = std::max(worst, std::abs(f.drho[i] / want - 1.0));
  }
  return worst;
}

void check_sine(PairIsa isa) {
  // The lattice sum of the kernel's second moment is the continuum's to 0.2 % at h = 1.5
  // dx; the rest is the next term of the Taylor series, (k h)^2 times a kernel moment:
  // it falls fourfold when the wavelength doubles.
  const double long_wave = sine_decay_error(54, 48.0, isa);
  const double short_wave = sine_decay_error(30, 24.0, isa);
  std::printf("sine decay against delta h c0 k^2: %.4f (lambda = 48 dx), %.4f (24 dx)\n", long_wave,
              short_wave);
  EXPECT_LT(long_wave, 0.005);
  EXPECT_LT(short_wave, 0.02);
  EXPECT_GT(short_wave, 2.5 * long_wave);  // converging as (k h)^2
}

}  // namespace

TEST(DensityDiffusion, SineDecaysAtTheDiffusivityBaseline) {
  check_sine(PairIsa::kBaseline);
}

TEST(DensityDiffusion, SineDecaysAtTheDiffusivityAvx2) {
  if (best_pair_isa() == PairIsa::kBaseline) GTEST_SKIP() << "this CPU has no AVX2 (x86-64-v3)";
  check_sine(PairIsa::kAvx2);
}

TEST(DensityDiffusion, SineDecaysAtTheDiffusivityAvx512) {
  if (best_pair_isa() != PairIsa::kAvx512) GTEST_SKIP() << "this CPU has no AVX-512 (x86-64-v4)";
  check_sine(PairIsa::kAvx512);
}

namespace {

// A lattice of spacing 1 (nx x ny x nz, h = 1.5) of fluid particles of volume 1, the lowest
// `walls` layers wall particles (V = 0, psi = 0, as prepare_density_diffusion sets them),
// with psi(x, y, z) given at the fluid ones; the gradient (renormalised or 0) and the rate
// computed as the solver does.
struct Lattice {
  FluidParticles f;
  int nx, ny, nz;
  double h = 1.5;
  DensityDiffusion dd;
  template <class Psi>
  Lattice(int nx_, int ny_, int nz_, int walls, bool renormalised, Psi psi,
          PairIsa isa = best_pair_isa())
      : nx(nx_), ny(ny_), nz(nz_) {
    const std::size_t n = static_cast<std::size_t>(nx) * ny * nz;
    f.n_owned = n;
    f.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      f.x[i] = static_cast<double>(i % nx);
      f.y[i] = static_cast<double>(i / nx % ny);
      f.z[i] = static_cast<double>(i / (static_cast<std::size_t>(nx) * ny));
      f.vx[i] = f.vy[i] = f.vz[i] = 0.0;
      f.h[i] = h;
      f.inv_h[i] = 1.0 / h;
      f.rho[i] = f.mass[i] = 1000.0;
      f.eps[i] = 0.75;
      f.P[i] = 0.0;
      f.kind[i] = f.z[i] < walls ? kWall : kFluid;
      const bool fluid = f.kind[i] == kFluid;
      f.diffusion_psi[i] = fluid ? psi(f.x[i], f.y[i], f.z[i]) : 0.0;
      f.diffusion_volume[i] = fluid ? 1.0 : 0.0;
    }
    const double rc = kernel::kSupport * h + 0.1;
    CellList cells;
    cells.build(f.x.data(), f.y.data(), f.z.data(), n, rc, 2);
    NeighbourList half;
    half.build(cells, f.x.data(), f.y.data(), f.z.data(), n, rc, true, /*half=*/true);
    dd.delta = 0.1;
    dd.c0 = 20.0;
    dd.renormalised = renormalised;
    PairAccumulator acc;
    if (renormalised) compute_diffusion_gradient(f, half, acc, isa);
    compute_density_rate(f, half, acc, false, {}, dd, isa);
  }
  // a particle whose neighbours' neighbours all lie in the lattice, except below (the wall)
  bool inside(std::size_t i, double margin) const {
    return f.x[i] >= margin && f.x[i] <= nx - 1 - margin && f.y[i] >= margin &&
           f.y[i] <= ny - 1 - margin && f.z[i] <= nz - 1 - margin;
  }
  double scale() const { return 2.0 * dd.delta * dd.c0 * h * 0.75; }
};

}  // namespace

// psi = 3 + 0.2 x - 0.5 z + 0.1 y (a suspension's fluid under its weight: psi grows with
// depth) over three wall layers: the renormalised gradient is psi's own, and no particle
// down to the wall gets any term, while the `hydrostatic` form makes a sink of fluid
// volume in the layer on the wall (D < 0: its density falls, and the pressure draws in
// fluid that no flow accounts for).
namespace {
void check_linear_psi_at_a_wall(PairIsa isa) {
  auto psi = [](double x, double y, double z) { return 3.0 + 0.2 * x + 0.1 * y - 0.5 * z; };
  const Lattice renorm(15, 15, 16, 3, true, psi, isa), hydro(15, 15, 16, 3, false, psi, isa);
  const double margin = 2.0 * kernel::kSupport * renorm.h;  // the gradient's reach and D's
  double worst_g = 0.0, worst_d = 0.0, hydro_floor = 0.0, hydro_bulk = 0.0;
  for (std::size_t i = 0; i < renorm.f.n_owned; ++i) {
    if (renorm.f.kind[i] != kFluid || !renorm.inside(i, margin)) continue;
    worst_g = std::max({worst_g, std::abs(renorm.f.diffusion_gx[i] - 0.2),
                        std::abs(renorm.f.diffusion_gy[i] - 0.1),
                        std::abs(renorm.f.diffusion_gz[i] + 0.5)});
    worst_d = std::max(worst_d, std::abs(renorm.f.drho[i]));
    if (renorm.f.z[i] == 3.0) hydro_floor = std::min(hydro_floor, hydro.f.drho[i]);
    if (renorm.f.z[i] == 7.0) hydro_bulk = std::max(hydro_bulk, std::abs(hydro.f.drho[i]));
  }
  std::printf(
      "renormalised: |G - grad psi| %.2g, |D| %.2g; hydrostatic: D %.3g on the wall, "
      "%.2g in the bulk (scale %.3g)\n",
      worst_g, worst_d, hydro_floor, hydro_bulk, renorm.scale());
  EXPECT_LT(worst_g, 1e-12);
  EXPECT_LT(worst_d, 1e-12 * renorm.scale());
  EXPECT_LT(hydro_floor, -0.05 * renorm.scale());  // what the renormalised form removes
  EXPECT_LT(hydro_bulk, 1e-12 * renorm.scale());   // both forms agree where psi is linear
}
}  // namespace

TEST(DensityDiffusion, RenormalisedFormLeavesALinearPsiAloneAtAWallBaseline) {
  check_linear_psi_at_a_wall(PairIsa::kBaseline);
}

TEST(DensityDiffusion, RenormalisedFormLeavesALinearPsiAloneAtAWallAvx2) {
  if (best_pair_isa() == PairIsa::kBaseline) GTEST_SKIP() << "this CPU has no AVX2 (x86-64-v3)";
  check_linear_psi_at_a_wall(PairIsa::kAvx2);
}

TEST(DensityDiffusion, RenormalisedFormLeavesALinearPsiAloneAtAWallAvx512) {
  if (best_pair_isa() != PairIsa::kAvx512) GTEST_SKIP() << "this CPU has no AVX-512 (x86-64-v4)";
  check_linear_psi_at_a_wall(PairIsa::kAvx512);
}

// Each instruction set's gradient and rate agree with the scalar rows' on a psi that is not
// linear (G and D then depend on which pairs are summed; over a linear psi any subset gives
// the exact G).
TEST(DensityDiffusion, RenormalisedGradientAgreesAcrossInstructionSets) {
  auto psi = [](double x, double y, double z) {
    return std::sin(0.3 * x) + 0.1 * y * y - 0.05 * x * z;
  };
  const Lattice base(12, 12, 12, 3, true, psi, PairIsa::kBaseline);
  for (PairIsa isa : {PairIsa::kAvx2, PairIsa::kAvx512}) {
    if (isa == PairIsa::kAvx2 && best_pair_isa() == PairIsa::kBaseline) continue;
    if (isa == PairIsa::kAvx512 && best_pair_isa() != PairIsa::kAvx512) continue;
    const Lattice other(12, 12, 12, 3, true, psi, isa);
    double worst_g = 0.0, worst_d = 0.0, largest_g = 0.0;
    for (std::size_t i = 0; i < base.f.n_owned; ++i) {
      worst_g = std::max({worst_g, std::abs(base.f.diffusion_gx[i] - other.f.diffusion_gx[i]),
                          std::abs(base.f.diffusion_gy[i] - other.f.diffusion_gy[i]),
                          std::abs(base.f.diffusion_gz[i] - other.f.diffusion_gz[i])});
      largest_g = std::max(largest_g, std::abs(base.f.diffusion_gx[i]));
      worst_d = std::max(worst_d, std::abs(base.f.drho[i] - other.f.drho[i]));
    }
    EXPECT_GT(largest_g, 0.1);
    EXPECT_LT(worst_g, 1e-12);
    EXPECT_LT(worst_d, 1e-12 * base.scale());
  }
}

// A sine of psi along x: the renormalised form still damps it (D psi < 0), as (k h)^4
// (halving the wavelength raises the rate sixteen-fold, against four-fold for the
// `hydrostatic` form's lap), so the long waves are left to the viscosity.
TEST(DensityDiffusion, RenormalisedFormDampsAsTheFourthPowerOfTheWavenumber) {
  auto rate = [](int nx, double wavelength, bool renormalised) {
    const double k = 2.0 * M_PI / wavelength;
    const Lattice l(nx, 15, 15, 0, renormalised,
                    [k](double x, double, double) { return 0.5 * std::sin(k * x); });
    const double margin = 2.0 * kernel::kSupport * l.h;
    double sum = 0.0;
    int count = 0;
    for (std::size_t i = 0; i < l.f.n_owned; ++i) {
      const double s = std::sin(k * l.f.x[i]);
      if (!l.inside(i, margin) || l.f.z[i] < margin || std::abs(s) < 0.5) continue;
      sum += -l.f.drho[i] / (0.5 * s * l.scale() / 2.0);  // -D / (psi delta h c0 eps)
      ++count;
    }
    return sum / count;  // the hydrostatic form's continuum: k^2
  };
  const double hydro_long = rate(66, 48.0, false), renorm_long = rate(66, 48.0, true);
  const double hydro_short = rate(42, 24.0, false), renorm_short = rate(42, 24.0, true);
  const double hydro_6 = rate(30, 6.0, false), renorm_6 = rate(30, 6.0, true);
  std::printf(
      "decay rates (hydrostatic, renormalised): lambda 48 (%.3g, %.3g), 24 (%.3g, %.3g), "
      "6 (%.3g, %.3g)\n",
      hydro_long, renorm_long, hydro_short, renorm_short, hydro_6, renorm_6);
  EXPECT_GT(renorm_long, 0.0);
  EXPECT_GT(renorm_6, 0.0);
  EXPECT_NEAR(hydro_short / hydro_long, 4.0, 0.1);
  EXPECT_NEAR(renorm_short / renorm_long, 16.0, 1.0);
  EXPECT_LT(renorm_long, 0.02 * hydro_long);
  EXPECT_GT(renorm_6, 0.1 * hydro_6);  // a wave of a few particles is still damped
}

namespace {
const char* kColumn = R"(
name: column
domain: {size: [0.0016, 0.0016, 0.006]}
fluid: {density: 1000, viscosity: 8.9e-4, spacing: 2.0e-4, density_diffusion: 0.1}
startup: {relax_steps: 0}
time: {end: 0.01}
)";
}

// The hydrostatic start is a zero of the term: psi = rho/eps - rho_H(z) vanishes to
// round-off (without the correction psi would be rho - rho0, up to rho0 g H / c0^2 =
// 6e-4 rho0 here), and the column stays at rest with the diffusion on.
TEST(DensityDiffusion, WaterColumnAtRestStaysAtRest) {
  const Scene sc = load_scene_text(kColumn, "column.yaml");
  Simulation sim(sc);
  FluidParticles& f0 = const_cast<FluidParticles&>(sim.fluid());
  StepParams p = compile_step_params(sc);
  prepare_density_diffusion(f0, p.fluid.diffusion);
  double worst_psi = 0.0;
  for (std::size_t a = 0; a < f0.n_owned; ++a)
    worst_psi = std::max(worst_psi, std::abs(f0.diffusion_psi[a]));
  EXPECT_LT(worst_psi, 1e-9 * sc.fluid.density);
  const double period = 4.0 * sc.fill_height() / sc.fluid.sound_speed;
  while (sim.time() < 1.5 * period) sim.step();
  const FluidParticles& f = sim.fluid();
  double vmax = 0;
  for (std::size_t a = 0; a < f.n_owned; ++a)
    vmax = std::max(vmax, std::sqrt(f.vx[a] * f.vx[a] + f.vy[a] * f.vy[a] + f.vz[a] * f.vz[a]));
  const Diagnostics d = diagnostics(sim);
  std::printf("with delta = 0.1: max |u| %.3g m/s, max density error %.3f %%\n", vmax,
              100 * d.max_density_error);
  EXPECT_LT(vmax, 1e-3);
  EXPECT_LT(d.max_density_error, 0.01);
}

namespace {
const char* kSuspension = R"(
name: suspension
domain: {size: [0.0016, 0.0016, 0.0032]}
fluid: {density: 1000, viscosity: 8.9e-4, spacing: 2.0e-4}
species: [{name: glass, diameter: 1.0e-4, density: 2500}]
particles:
  - {type: random, species: glass, voidage: 0.9, min: [0, 0, 0], max: [0.0016, 0.0016, 0.0016], seed: 3}
)";
const char* kPeriodicSuspension = R"(
name: periodic
domain: {size: [0.0016, 0.0016, 0.0016], periodic_z: true}
fluid: {density: 1000, viscosity: 8.9e-4, spacing: 2.0e-4}
species: [{name: glass, diameter: 1.0e-4, density: 2500}]
particles:
  - {type: random, species: glass, voidage: 0.9, min: [0, 0, 0], max: [0.0016, 0.0016, 0.0016], seed: 3}
flow: {times: [0], superficial_velocity: [0]}
)";
bool renormalised(const char* text, std::vector<std::string> sets = {}) {
  return compile_step_params(load_scene_text(text, "t.yaml", sets)).fluid.diffusion.renormalised;
}
}  // namespace

// fluid.density_diffusion_form: auto is renormalised where spheres settle under gravity onto
// a floor, hydrostatic without spheres, without gravity or periodic in z; a given form wins.
TEST(DensityDiffusion, AutoFormIsRenormalisedWhereSpheresSettleOntoAFloor) {
  EXPECT_TRUE(renormalised(kSuspension));
  EXPECT_FALSE(renormalised(kColumn));
  EXPECT_FALSE(renormalised(kSuspension, {"gravity=[0, 0, 0]"}));
  EXPECT_FALSE(renormalised(kPeriodicSuspension));
  EXPECT_FALSE(renormalised(kSuspension, {"fluid.density_diffusion_form=hydrostatic"}));
  EXPECT_TRUE(renormalised(kColumn, {"fluid.density_diffusion_form=renormalised"}));
}
