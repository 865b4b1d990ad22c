// The SPH pair passes over a half Verlet list (sph/density_rate.cpp, sph/momentum.cpp)
// against the same sums taken over every pair by brute force, on a jittered lattice with
// varied h, density, pressure and velocity, halo points among the neighbours and a list
// with a skin. Both instruction sets of the passes (sph/pair_isa.hpp): the x86-64 baseline
// always, AVX2 and AVX-512 where the CPU has them. The reference evaluates (2.53), (2.54), (2.55),
// (2.56) and the Morris term as written in the passes' headers, pair by pair, one particle
// at a time: it shares with the passes only the kernel (tested in kernel_test.cpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "domain/cell_list.hpp"
#include "domain/neighbour_list.hpp"
#include "sph/density_rate.hpp"
#include "sph/kernel.hpp"
#include "sph/momentum.hpp"

namespace {

using namespace sphdem;

constexpr std::size_t kSide = 9;     // 9^3 points on a lattice of spacing 1
constexpr std::size_t kOwned = 600;  // the rest stand in for halo copies
constexpr double kSkin = 0.3;        // list radius: 2 h_max + skin

struct Column {
  FluidParticles f;
  NeighbourList half;
};

Column make_column() {
  Column c;
  FluidParticles& f = c.f;
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const std::size_t total = kSide * kSide * kSide;
  f.n_owned = kOwned;
  f.resize(total);
  for (std::size_t i = 0; i < total; ++i) {
    f.x[i] = static_cast<double>(i % kSide) + 0.2 * u(rng);
    f.y[i] = static_cast<double>(i / kSide % kSide) + 0.2 * u(rng);
    f.z[i] = static_cast<double>(i / (kSide * kSide)) + 0.2 * u(rng);
    f.vx[i] = 0.3 * u(rng);
    f.vy[i] = 0.3 * u(rng);
    f.vz[i] = 0.3 * u(rng);
    f.h[i] = 1.5 * (1.0 + 0.1 * u(rng));
    f.inv_h[i] = 1.0 / f.h[i];
    f.rho[i] = 1000.0 * (1.0 + 0.05 * u(rng));
    f.mass[i] = 1000.0 * (1.0 + 0.02 * u(rng));
    f.P[i] = 500.0 * (1.0 + u(rng));
    f.cs[i] = 10.0 * (1.0 + 0.1 * u(rng));
    f.p_term[i] = f.P[i] / (f.rho[i] * f.rho[i]);  // the halo's; owned ones are recomputed
    f.kind[i] = i % 7 == 3 ? kWall : kFluid;       // walls among them: no density diffusion
    f.eps[i] = 0.7 + 0.3 * std::abs(u(rng));
    f.diffusion_psi[i] = f.kind[i] == kFluid ? 2.0 * u(rng) : 0.0;
    f.diffusion_volume[i] = f.kind[i] == kFluid ? f.mass[i] / f.rho[i] : 0.0;
    // a renormalised gradient of psi (the `renormalised` form's correction; any values do)
    f.diffusion_gx[i] = f.kind[i] == kFluid ? 0.7 * u(rng) : 0.0;
    f.diffusion_gy[i] = f.kind[i] == kFluid ? 0.7 * u(rng) : 0.0;
    f.diffusion_gz[i] = f.kind[i] == kFluid ? 0.7 * u(rng) : 0.0;
  }
  const double hmax = *std::max_element(f.h.begin(), f.h.end());
  const double rc = kernel::kSupport * hmax + kSkin;
  CellList cells;
  cells.build(f.x.data(), f.y.data(), f.z.data(), total, rc, 2);
  c.half.build(cells, f.x.data(), f.y.data(), f.z.data(), kOwned, rc, true, /*half=*/true);
  return c;
}

// Brute-force sums for owned a over every other point b within the larger support.
struct Reference {
  std::vector<double> omega, drho, thx, thy, thz, vsig, scale_drho, scale_th;
};

// sph/density_diffusion.hpp's D_a over every other point b (zero for a wall a).
double brute_force_diffusion(const FluidParticles& f, const DensityDiffusion& dd, std::size_t a,
                             double& scale) {
  double sum = 0.0;
  scale = 0.0;
  if (!dd.on() || f.kind[a] != kFluid) return 0.0;
  for (std::size_t b = 0; b < f.size(); ++b) {
    if (b == a) continue;
    const double dx = f.x[a] - f.x[b], dy = f.y[a] - f.y[b], dz = f.z[a] - f.z[b];
    const double r2 = dx * dx + dy * dy + dz * dz;
    const double minus_f =
        -0.5 * (kernel::grad_factor(r2, f.h[a]) + kernel::grad_factor(r2, f.h[b]));
    // psi_b - psi_a less (G_a + G_b)/2 . (r_b - r_a)
    const double dpsi = f.diffusion_psi[b] - f.diffusion_psi[a] +
                        0.5 * ((f.diffusion_gx[a] + f.diffusion_gx[b]) * dx +
                               (f.diffusion_gy[a] + f.diffusion_gy[b]) * dy +
                               (f.diffusion_gz[a] + f.diffusion_gz[b]) * dz);
    const double term = dpsi * minus_f * f.diffusion_volume[b];
    sum += term;
    scale += std::abs(term);
  }
  const double c = 2.0 * dd.delta * dd.c0 * f.h[a] * f.eps[a];
  scale *= c;
  return c * sum;
}

Reference brute_force(const FluidParticles& f, const MomentumParams& p,
                      const DensityDiffusion& dd) {
  const std::size_t n = f.n_owned, total = f.size();
  Reference ref;
  for (auto* v : {&ref.omega, &ref.drho, &ref.thx, &ref.thy, &ref.thz, &ref.vsig, &ref.scale_drho,
                  &ref.scale_th})
    v->assign(n, 0.0);
  for (std::size_t a = 0; a < n; ++a) {
    double dwdh = f.mass[a] * kernel::dw_dh(0.0, f.h[a]), div = 0.0, div_abs = 0.0;
    for (std::size_t b = 0; b < total; ++b) {
      if (b == a) continue;
      const double dx = f.x[a] - f.x[b], dy = f.y[a] - f.y[b], dz = f.z[a] - f.z[b];
      const double r2 = dx * dx + dy * dy + dz * dz;
      const double udotr =
          (f.vx[a] - f.vx[b]) * dx + (f.vy[a] - f.vy[b]) * dy + (f.vz[a] - f.vz[b]) * dz;
      dwdh += f.mass[b] * kernel::dw_dh(r2, f.h[a]);               // (2.54)
      div += f.mass[b] * kernel::grad_factor(r2, f.h[a]) * udotr;  // (2.53)
      div_abs += std::abs(f.mass[b] * kernel::grad_factor(r2, f.h[a]) * udotr);
    }
    const double omega = 1.0 + f.h[a] / (3.0 * f.rho[a]) * dwdh;
    double diff_abs = 0.0;
    const double diff = brute_force_diffusion(f, dd, a, diff_abs);
    ref.omega[a] = omega;
    ref.drho[a] = div / omega + diff;
    ref.scale_drho[a] = div_abs / omega + diff_abs;
  }
  for (std::size_t a = 0; a < n; ++a) {
    double th[3] = {0, 0, 0}, th_abs = 0.0, vsig_max = f.cs[a];
    for (std::size_t b = 0; b < total; ++b) {
      if (b == a) continue;
      const double r_ab[3] = {f.x[a] - f.x[b], f.y[a] - f.y[b], f.z[a] - f.z[b]};
      const double u_ab[3] = {f.vx[a] - f.vx[b], f.vy[a] - f.vy[b], f.vz[a] - f.vz[b]};
      const double r2 = r_ab[0] * r_ab[0] + r_ab[1] * r_ab[1] + r_ab[2] * r_ab[2];
      if (r2 >= std::pow(kernel::kSupport * std::max(f.h[a], f.h[b]), 2)) continue;
      const double r = std::sqrt(r2);
      const double udotr = u_ab[0] * r_ab[0] + u_ab[1] * r_ab[1] + u_ab[2] * r_ab[2];
      const double vsig = 0.5 * (f.cs[a] + f.cs[b]) + std::abs(udotr) / r;
      const double pi_ab =
          udotr < 0.0 ? -p.alpha_artificial * vsig * (udotr / r) / (f.rho[a] + f.rho[b]) : 0.0;
      const double Fa = kernel::grad_factor(r2, f.h[a]), Fb = kernel::grad_factor(r2, f.h[b]);
      const double hm = 0.5 * (f.h[a] + f.h[b]);
      const double morris =
          2.0 * p.viscosity * 0.5 * (Fa + Fb) * r2 / (f.rho[a] * f.rho[b] * (r2 + 0.01 * hm * hm));
      for (int d = 0; d < 3; ++d) {
        const double term =
            f.mass[b] * (-((f.p_term[a] + pi_ab) * Fa + (f.p_term[b] + pi_ab) * Fb) * r_ab[d] +
                         morris * u_ab[d]);
        th[d] += term;
        th_abs += std::abs(term);
      }
      vsig_max = std::max(vsig_max, vsig);
    }
    ref.thx[a] = th[0];
    ref.thy[a] = th[1];
    ref.thz[a] = th[2];
    ref.scale_th[a] = th_abs;
    ref.vsig[a] = vsig_max;
  }
  return ref;
}

void check_passes(PairIsa isa, bool diffusion) {
  Column c = make_column();
  FluidParticles& f = c.f;
  ASSERT_GT(c.half.neighbour.size(), 40 * kOwned);  // a real neighbourhood, with halo entries
  PairAccumulator acc;
  DensityDiffusion dd;
  if (diffusion) {  // comparable with the continuity term here
    dd.delta = 0.1;
    dd.c0 = 30.0;
  }
  const std::size_t bounded = compute_density_rate(f, c.half, acc, false, {}, dd, isa);
  EXPECT_EQ(bounded, 0u);  // a full lattice neighbourhood keeps Omega inside [0.5, 2]
  MomentumParams p;
  p.viscosity = 2.0;  // a Morris term comparable with the pressure term here
  p.alpha_artificial = 0.5;
  p.cfl = 0.25;
  compute_fluid_acceleration(f, c.half, p, acc, isa);
  const Reference ref = brute_force(f, p, dd);
  double worst_drho = 0.0, worst_th = 0.0;
  for (std::size_t a = 0; a < kOwned; ++a) {
    EXPECT_NEAR(f.omega[a], ref.omega[a], 1e-13) << "a = " << a;
    worst_drho = std::max(worst_drho, std::abs(f.drho[a] - ref.drho[a]) / ref.scale_drho[a]);
    EXPECT_NEAR(f.p_term[a], f.P[a] / (ref.omega[a] * f.rho[a] * f.rho[a]),
                1e-13 * std::abs(f.p_term[a]));
    if (f.kind[a] == kWall) {  // walls only lend their pressure to the pairs
      EXPECT_EQ(f.thx[a], 0.0);
      continue;
    }
    for (auto [got, want] :
         {std::pair{f.thx[a], ref.thx[a]}, {f.thy[a], ref.thy[a]}, {f.thz[a], ref.thz[a]}})
      worst_th = std::max(worst_th, std::abs(got - want) / ref.scale_th[a]);
    EXPECT_NEAR(f.dt_limit[a], p.cfl * f.h[a] / ref.vsig[a], 1e-13 * f.dt_limit[a]) << "a = " << a;
  }
  // Round-off of sums of ~60 terms, measured against the sum of the terms' magnitudes.
  EXPECT_LT(worst_drho, 1e-13);
  EXPECT_LT(worst_th, 1e-13);
}

TEST(SphPairs, BaselineMatchesBruteForce) {
  check_passes(PairIsa::kBaseline, false);
  check_passes(PairIsa::kBaseline, true);  // with the density diffusion
}

TEST(SphPairs, Avx2MatchesBruteForce) {
  if (best_pair_isa() == PairIsa::kBaseline) GTEST_SKIP() << "this CPU has no AVX2 (x86-64-v3)";
  check_passes(PairIsa::kAvx2, false);
  check_passes(PairIsa::kAvx2, true);
}

TEST(SphPairs, Avx512MatchesBruteForce) {
  if (best_pair_isa() != PairIsa::kAvx512) GTEST_SKIP() << "this CPU has no AVX-512 (x86-64-v4)";
  check_passes(PairIsa::kAvx512, false);
  check_passes(PairIsa::kAvx512, true);
}

}  // namespace
