// Density diffusion (sph/density_diffusion.hpp, delta-SPH with the hydrostatic correction):
// a sine of the fluid's density on a lattice at rest decays at the diffusivity delta h c0
// (the closed form of the term's continuum limit, eps delta h c0 lap(psi)), with either
// instruction set; the fluid at rest is a zero of the term (psi = 0 everywhere at the
// hydrostatic start) and a water column with it stays at rest.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "analysis/diagnostics.hpp"
#include "domain/cell_list.hpp"
#include "domain/neighbour_list.hpp"
#include "propagator/simulation.hpp"
#include "scene/scene.hpp"
#include "sph/density_rate.hpp"
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
