// Fluid-sphere coupling passes on a hand-made configuration: exact action-reaction
// (2.71-2.72), Shepard interpolation (2.69), the voidage (2.50) and the variational
// pressure coupling.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <utility>

#include "coupling/drag_exchange.hpp"
#include "coupling/drag_law_table.hpp"
#include "coupling/fluid_sphere_pairs.hpp"
#include "coupling/interpolation.hpp"
#include "coupling/pressure_coupling.hpp"
#include "coupling/reaction.hpp"
#include "coupling/voidage.hpp"
#include "domain/box.hpp"
#include "domain/cell_list.hpp"
#include "domain/halo.hpp"
#include "sph/kernel.hpp"

using namespace sphdem;

namespace {

struct Config {
  Box box;
  FluidParticles f;
  DemParticles s;
  Halo fh, sh;
  CellList fcells, scells;
  FluidSpherePairs pairs;
  PairAccumulator scratch;
  double cutoff = 0;
  double kernel_scale = 1.0;       // coupling.sphere_kernel_scale: the spheres' kernel H = scale h
  double drag_kernel_scale = 0.0;  // coupling.drag_kernel_scale (0: the same)
};

// The sphere halo (reaching the spheres' kernel, scale x the fluid cut-off), the sphere
// bins, the fluid-sphere pairs and the voidage, from the owned spheres' positions.
void rebuild_sphere_side(Config& c) {
  FluidParticles& f = c.f;
  DemParticles& s = c.s;
  s.resize(s.n_owned);
  const double sphere_cutoff = c.cutoff * c.kernel_scale;
  c.sh.build(c.box, sphere_cutoff, s.x.data(), s.y.data(), s.z.data(), s.n_owned);
  s.resize(s.n_owned + c.sh.n_ghost());
  c.sh.fill_positions(s.x.data(), s.y.data(), s.z.data());
  c.sh.fill(s.radius);
  c.scells.build(s.x.data(), s.y.data(), s.z.data(), s.size(), sphere_cutoff, 2);
  c.pairs.build(f, s, c.scells, c.kernel_scale, c.drag_kernel_scale);
  compute_fluid_voidage(f, s, c.pairs, 0.05);
}

// A jittered fluid lattice (bottom layer = wall) and random spheres, some across
// the periodic faces, with halos and cell lists built as Simulation does.
void build(Config& c, int n_spheres, unsigned seed, double jitter = 0.1, double kernel_scale = 1.0,
           double drag_kernel_scale = 0.0) {
  c.kernel_scale = kernel_scale;
  c.drag_kernel_scale = drag_kernel_scale;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const double dx = 2e-4, rho0 = 1000.0;
  const int nx = 8, nz = 10;
  c.box.lo = {0, 0, 0};
  c.box.hi = {nx * dx, nx * dx, nz * dx};
  FluidParticles& f = c.f;
  f.resize(nx * nx * nz);
  f.n_owned = f.size();
  std::size_t k = 0;
  for (int iz = 0; iz < nz; ++iz)
    for (int iy = 0; iy < nx; ++iy)
      for (int ix = 0; ix < nx; ++ix, ++k) {
        f.x[k] = (ix + 0.5 + jitter * u(rng)) * dx;
        f.y[k] = (iy + 0.5 + jitter * u(rng)) * dx;
        f.z[k] = (iz + 0.5 + jitter * u(rng)) * dx;
        f.kind[k] = iz == 0 ? kWall : kFluid;
        f.rho[k] = rho0 * (0.95 + 0.05 * u(rng));
        f.mass[k] = rho0 * dx * dx * dx;
        f.h[k] = 1.5 * std::cbrt(f.mass[k] / f.rho[k]);
        f.inv_h[k] = 1.0 / f.h[k];
        f.vx[k] = u(rng);
        f.vy[k] = u(rng);
        f.vz[k] = u(rng);
        f.thx[k] = u(rng);
        f.thy[k] = u(rng);
        f.thz[k] = u(rng);
      }
  DemParticles& s = c.s;
  s.resize(n_spheres);
  s.n_owned = n_spheres;
  for (int j = 0; j < n_spheres; ++j) {
    s.x[j] = c.box.hi[0] * (0.5 + 0.5 * u(rng));
    s.y[j] = (j % 3 == 0) ? 1e-6 : c.box.hi[1] * (0.5 + 0.5 * u(rng));  // some on the face
    s.z[j] = c.box.hi[2] * (0.5 + 0.3 * u(rng));
    s.radius[j] = 5e-5 * (1.0 + 0.2 * u(rng));
    s.mass[j] = 2500.0 * s.volume(j);
  }
  double hmax = 0;
  for (double h : f.h) hmax = std::max(hmax, h);
  c.cutoff = kernel::kSupport * hmax * 1.05;
  c.fh.build(c.box, c.cutoff, f.x.data(), f.y.data(), f.z.data(), f.n_owned);
  f.resize(f.n_owned + c.fh.n_ghost());
  c.fh.fill_positions(f.x.data(), f.y.data(), f.z.data());
  for (auto* v : {&f.vx, &f.vy, &f.vz, &f.mass, &f.h, &f.inv_h, &f.rho, &f.thx, &f.thy, &f.thz})
    c.fh.fill(*v);
  c.fh.fill(f.kind);
  c.fcells.build(f.x.data(), f.y.data(), f.z.data(), f.size(), c.cutoff, 2);
  rebuild_sphere_side(c);
  c.fh.fill(f.eps);
}

}  // namespace

// Sum over fluid of m_a * (reaction acceleration) + sum over spheres of fm_j = 0, with the
// drag's kernel the spheres' or apart from it (narrower). A conservation check: it holds
// for any weights shared by the interpolation and the reaction.
TEST(Coupling, ActionAndReactionCancelToRoundOff) {
  for (unsigned seed : {1u, 2u, 3u, 4u}) {
    Config c;
    build(c, 25, seed, 0.1, seed == 4u ? 1.5 : 1.0, seed == 4u ? 1.0 : 0.0);
    ASSERT_EQ(c.pairs.drag_apart(), seed == 4u);
    FluidParticles& f = c.f;
    DemParticles& s = c.s;
    interpolate_fluid_at_spheres(s, f, c.pairs, c.sh, c.scratch);
    std::mt19937 rng(seed + 100);
    std::uniform_real_distribution<double> u(-1e-8, 1e-8);
    double fsum[3] = {0, 0, 0}, fabs_sum = 0;
    for (std::size_t j = 0; j < s.n_owned; ++j) {
      s.fmx[j] = u(rng);
      s.fmy[j] = u(rng);
      s.fmz[j] = u(rng);
      fsum[0] += s.fmx[j];
      fsum[1] += s.fmy[j];
      fsum[2] += s.fmz[j];
      fabs_sum += std::abs(s.fmx[j]) + std::abs(s.fmy[j]) + std::abs(s.fmz[j]);
      ASSERT_GT(s.shepard[j], 0.0);
    }
    for (auto* v : {&s.fmx, &s.fmy, &s.fmz, &s.shepard}) c.sh.fill(*v);
    std::fill(f.ax.begin(), f.ax.end(), 0.0);
    std::fill(f.ay.begin(), f.ay.end(), 0.0);
    std::fill(f.az.begin(), f.az.end(), 0.0);
    add_reaction_on_fluid(f, s, c.pairs, c.scratch);
    double rsum[3] = {0, 0, 0};
    for (std::size_t a = 0; a < f.n_owned; ++a) {
      if (f.kind[a] == kWall) {
        EXPECT_EQ(f.ax[a], 0.0);  // fixed walls take no reaction
      }
      rsum[0] += f.mass[a] * f.ax[a];
      rsum[1] += f.mass[a] * f.ay[a];
      rsum[2] += f.mass[a] * f.az[a];
    }
    for (int d = 0; d < 3; ++d)
      EXPECT_LT(std::abs(rsum[d] + fsum[d]), 1e-13 * fabs_sum) << "axis " << d;
  }
}

// The drag rate K_a (coupling/reaction.hpp) is the reaction's pull per unit fluid velocity:
// with every sphere's mean force g_j u (a uniform slip u), the reaction is -K_a u to
// round-off. Then the semi-implicit exchange (coupling/drag_exchange.hpp) at steps from
// the explicit limit to 40 times it: the momentum the fluid does not take is what the
// spheres get, to round-off. Both are conservation checks, true of any weights shared by
// the passes; the physics is held by the extremes' fine_20um rows (the bulk's slip against
// (4.4) at a step past the explicit limit).
TEST(Coupling, DragExchangeKeepsTheMomentumExact) {
  for (unsigned seed : {1u, 2u, 3u}) {
    Config c;
    build(c, 25, seed, 0.1, seed == 3u ? 1.5 : 1.0, seed == 3u ? 1.0 : 0.0);
    FluidParticles& f = c.f;
    DemParticles& s = c.s;
    interpolate_fluid_at_spheres(s, f, c.pairs, c.sh, c.scratch);
    std::mt19937 rng(seed + 200);
    std::uniform_real_distribution<double> u(0.5, 1.5);
    std::vector<double> gain(s.size(), 0.0);
    const double slip[3] = {1e-3, -2e-3, 3e-3};
    for (std::size_t j = 0; j < s.n_owned; ++j) {
      gain[j] = 1e-6 * u(rng);
      s.fmx[j] = gain[j] * slip[0];
      s.fmy[j] = gain[j] * slip[1];
      s.fmz[j] = gain[j] * slip[2];
    }
    for (auto* v : {&s.fmx, &s.fmy, &s.fmz, &s.shepard, &gain}) c.sh.fill(*v);
    std::fill(f.ax.begin(), f.ax.end(), 0.0);
    std::fill(f.ay.begin(), f.ay.end(), 0.0);
    std::fill(f.az.begin(), f.az.end(), 0.0);
    add_reaction_on_fluid(f, s, c.pairs, c.scratch, gain.data());
    double k_max = 0;
    for (std::size_t a = 0; a < f.n_owned; ++a) {
      const double k = f.drag_rate[a];
      if (f.kind[a] == kWall) {
        EXPECT_EQ(k, 0.0);
      }
      k_max = std::max(k_max, k);
      EXPECT_NEAR(f.ax[a], -k * slip[0], 1e-12 * k * 3e-3);
      EXPECT_NEAR(f.ay[a], -k * slip[1], 1e-12 * k * 3e-3);
      EXPECT_NEAR(f.az[a], -k * slip[2], 1e-12 * k * 3e-3);
    }
    ASSERT_GT(k_max, 0.0);
    std::uniform_real_distribution<double> a_rand(-1.0, 1.0);
    std::vector<double> a0(3 * f.n_owned);
    for (double& v : a0) v = a_rand(rng);
    for (double dt_k : {kExplicitDragLimit, 4.0, 40.0}) {  // dt K at the fastest particle
      const double dt = dt_k / k_max;
      std::vector<double> phi(3 * f.n_owned, 0.0), impulse;
      double deficit[3] = {0, 0, 0}, scale = 0, withheld = 0;
      long implicit = 0;
      for (std::size_t a = 0; a < f.n_owned; ++a) {
        if (f.kind[a] == kWall) continue;
        double ax = a0[3 * a], ay = a0[3 * a + 1], az = a0[3 * a + 2];
        implicit += take_drag_exchange(dt, f.drag_rate[a], f.mass[a] / f.rho[a], ax, ay, az,
                                       phi.data() + 3 * a);
        deficit[0] += f.mass[a] * dt * (a0[3 * a] - ax);
        deficit[1] += f.mass[a] * dt * (a0[3 * a + 1] - ay);
        deficit[2] += f.mass[a] * dt * (a0[3 * a + 2] - az);
        scale += f.mass[a] * dt *
                 (std::abs(a0[3 * a]) + std::abs(a0[3 * a + 1]) + std::abs(a0[3 * a + 2]));
        withheld += f.mass[a] * dt *
                    (std::abs(a0[3 * a] - ax) + std::abs(a0[3 * a + 1] - ay) +
                     std::abs(a0[3 * a + 2] - az));
      }
      drag_exchange_impulses(s, gain.data(), c.pairs, c.sh, phi.data(), f.n_owned, dt, c.scratch,
                             impulse);
      double given[3] = {0, 0, 0};
      for (std::size_t j = 0; j < s.n_owned; ++j)
        for (int d = 0; d < 3; ++d) given[d] += impulse[3 * j + d];
      if (dt_k == kExplicitDragLimit) {
        EXPECT_EQ(implicit, 0);  // explicit up to the limit
      } else {
        EXPECT_GT(implicit, 0);
      }
      for (int d = 0; d < 3; ++d)
        EXPECT_NEAR(given[d], deficit[d], 1e-13 * scale) << "dt K " << dt_k << ", axis " << d;
      if (dt_k == 40.0) {
        EXPECT_GT(withheld, 0.1 * scale);  // not a trivial zero
      }
    }
  }
}

// Shepard interpolation reproduces a constant field exactly (to round-off).
TEST(Coupling, ShepardInterpolationIsExactForConstants) {
  Config c;
  build(c, 10, 7);
  FluidParticles& f = c.f;
  for (std::size_t a = 0; a < f.size(); ++a) {
    f.vx[a] = 0.25;
    f.vy[a] = -1.5;
    f.vz[a] = 3.0;
    f.eps_drag[a] = 0.8;  // the voidage the drag reads
    f.thx[a] = 2.0;
    f.thy[a] = 0.0;
    f.thz[a] = 9.81;
  }
  interpolate_fluid_at_spheres(c.s, f, c.pairs, c.sh, c.scratch);
  for (std::size_t j = 0; j < c.s.n_owned; ++j) {
    EXPECT_NEAR(c.s.ufx[j], 0.25, 1e-14);
    EXPECT_NEAR(c.s.ufy[j], -1.5, 1e-14);
    EXPECT_NEAR(c.s.ufz[j], 3.0, 1e-14);
    EXPECT_NEAR(c.s.eps[j], 0.8, 1e-14);
    // (-grad P + div tau) = sum m theta W / S = rho_Shepard * theta; rho varies +-5 %
    EXPECT_NEAR(c.s.gz[j] / 9.81, c.s.gx[j] / 2.0, 1e-12);
  }
}

// coupling.drag_upstream: over a suspension's top (voidage 0.75 and the return flow below
// z = 1.3 mm, clear liquid at rest above), spheres under it read exactly the suspension's
// voidage and flow from the kernel's half on gravity's side, where the whole kernel reads
// the clear liquid too; the Shepard sum (and so the reaction) keeps the whole kernel; a
// sphere whose gravity side holds only the wall (V = 0) reads the whole kernel, and so do
// lone spheres.
TEST(Coupling, DragUpstreamReadsTheHalfGravityPointsTo) {
  Config c;
  build(c, 12, 11);
  DemParticles& s = c.s;
  const double z_top = 1.3e-3;
  for (std::size_t j = 0; j < s.n_owned; ++j) s.z[j] = j == 0 ? 0.2e-3 : 0.95e-3 + 0.03e-3 * j;
  rebuild_sphere_side(c);
  FluidParticles& f = c.f;
  for (std::size_t a = 0; a < f.n_owned; ++a) {
    const bool below = f.z[a] < z_top;
    f.eps_drag[a] = below ? 0.75 : 1.0;
    f.vx[a] = f.vy[a] = 0.0;
    f.vz[a] = below ? 1e-3 : 0.0;
  }
  interpolate_fluid_at_spheres(s, f, c.pairs, c.sh, c.scratch);
  const std::vector<double> eps_whole = s.eps, shepard_whole = s.shepard;
  c.pairs.upstream = {0.0, 0.0, -1.0};
  interpolate_fluid_at_spheres(s, f, c.pairs, c.sh, c.scratch);
  double read_clear = 0.0;
  for (std::size_t j = 1; j < s.n_owned; ++j) {
    EXPECT_NEAR(s.eps[j], 0.75, 1e-14) << "sphere " << j << " at z = " << s.z[j];
    EXPECT_NEAR(s.ufz[j], 1e-3, 1e-17);
    EXPECT_DOUBLE_EQ(s.shepard[j], shepard_whole[j]);
    read_clear = std::max(read_clear, eps_whole[j] - 0.75);
  }
  EXPECT_GT(read_clear, 0.01) << "the whole kernel should reach the clear liquid";
  EXPECT_DOUBLE_EQ(s.eps[0], eps_whole[0]) << "the sphere on the floor reads the whole kernel";
  // lone spheres (voidage >= kLoneSphereVoidage) read the whole kernel: the flow they drag
  // along is not read from ahead of them
  for (std::size_t a = 0; a < f.n_owned; ++a) {
    f.eps_drag[a] = 0.995;
    f.vz[a] = f.z[a];
  }
  c.pairs.upstream = {};
  interpolate_fluid_at_spheres(s, f, c.pairs, c.sh, c.scratch);
  const std::vector<double> ufz_whole = s.ufz;
  c.pairs.upstream = {0.0, 0.0, -1.0};
  interpolate_fluid_at_spheres(s, f, c.pairs, c.sh, c.scratch);
  for (std::size_t j = 1; j < s.n_owned; ++j) EXPECT_DOUBLE_EQ(s.ufz[j], ufz_whole[j]);
}

// A simple cubic lattice of spheres (spacing dx / 2, solid fraction 0.3) filling the column
// up to z_top, on the fluid lattice without jitter, so that the sphere layers lie
// symmetrically about every fluid particle.
void fill_with_spheres(Config& c, double z_top) {
  DemParticles& s = c.s;
  const double ds = 1e-4, r = std::cbrt(0.3 * ds * ds * ds * 3.0 / (4.0 * M_PI));
  const int nxy = static_cast<int>(std::lround(c.box.hi[0] / ds));
  const int nz = static_cast<int>(std::floor(z_top / ds));
  s.resize(nxy * nxy * nz);
  s.n_owned = s.size();
  std::size_t j = 0;
  for (int k = 0; k < nz; ++k)
    for (int iy = 0; iy < nxy; ++iy)
      for (int ix = 0; ix < nxy; ++ix, ++j) {
        s.x[j] = (ix + 0.25) * ds;
        s.y[j] = (iy + 0.25) * ds;
        s.z[j] = (k + 0.5) * ds;
        s.radius[j] = r;
        s.mass[j] = 2500.0 * s.volume(j);
      }
  rebuild_sphere_side(c);
}

// coupling.drag_voidage_upstream: under a suspension's top every fluid particle whose
// support clears the floor reads, as its drag's voidage, exactly what it reads inside a
// column full of the same suspension (the lower half of its kernel doubled), where the
// whole kernel reads the clear liquid above too; inside the suspension the doubled half
// equals the whole kernel; within a support of the floor, off, or for a lone sphere the
// whole kernel is read; the voidage the pressure coupling reads (eps) never changes.
TEST(Coupling, DragVoidageUpstreamReadsTheSuspensionUnderItsTop) {
  Config top, full;
  build(top, 0, 5, 0.0);
  build(full, 0, 5, 0.0);
  const double z_top = 1.6e-3;
  fill_with_spheres(top, z_top);
  fill_with_spheres(full, top.box.hi[2] + 0.7e-3);
  VoidageUpstream upstream;
  upstream.on = true;  // the floor at z = 0
  FluidParticles& f = top.f;
  compute_fluid_voidage(f, top.s, top.pairs, 0.05);
  const std::vector<double> eps_whole = f.eps_drag;
  compute_fluid_voidage(f, top.s, top.pairs, 0.05, nullptr, upstream);
  compute_fluid_voidage(full.f, full.s, full.pairs, 0.05, nullptr, upstream);
  int under_top = 0, inside = 0, at_floor = 0;
  double read_clear = 0.0;  // how much more voidage the whole kernel reads under the top
  for (std::size_t a = 0; a < f.n_owned; ++a) {
    EXPECT_EQ(f.eps[a], eps_whole[a]) << "eps itself keeps the whole kernel";
    const double support = kernel::kSupport * f.h[a];
    if (f.kind[a] == kWall || f.z[a] < support) {  // the whole kernel at the floor
      EXPECT_EQ(f.eps_drag[a], eps_whole[a]) << "z = " << f.z[a];
      ++at_floor;
    } else if (f.z[a] + support <= z_top - 0.5e-4) {  // the whole support in the suspension
      EXPECT_NEAR(f.eps_drag[a], eps_whole[a], 1e-12) << "z = " << f.z[a];
      ++inside;
    } else if (f.z[a] < z_top) {  // under the top: the suspension's own reading
      EXPECT_NEAR(f.eps_drag[a], full.f.eps[a], 1e-12) << "z = " << f.z[a];
      read_clear = std::max(read_clear, eps_whole[a] - full.f.eps[a]);
      ++under_top;
    } else if (eps_whole[a] < kLoneSphereVoidage) {  // above the top: more of the suspension
      EXPECT_LT(f.eps_drag[a], eps_whole[a]) << "z = " << f.z[a];
    } else {  // as few spheres as a lone one: the whole kernel
      EXPECT_EQ(f.eps_drag[a], eps_whole[a]) << "z = " << f.z[a];
    }
  }
  EXPECT_GT(under_top, 0);
  EXPECT_GT(inside, 0);
  EXPECT_GT(at_floor, 0);
  EXPECT_GT(read_clear, 0.05) << "the whole kernel should reach the clear liquid";
  // a lone sphere, well clear of the floor: the whole kernel
  Config lone;
  build(lone, 1, 5, 0.0);
  lone.s.z[0] = 1.2e-3;
  rebuild_sphere_side(lone);
  compute_fluid_voidage(lone.f, lone.s, lone.pairs, 0.05, nullptr, upstream);
  for (std::size_t a = 0; a < lone.f.n_owned; ++a) EXPECT_EQ(lone.f.eps_drag[a], lone.f.eps[a]);
}

// The floor's height under a particle: the bottom wall, the nearest of a periodic column's
// plate images, or none (periodic without a plate).
TEST(Coupling, DragVoidageUpstreamFindsTheFloor) {
  VoidageUpstream wall{true, 0.5, 0.0, true};
  EXPECT_DOUBLE_EQ(wall.above_floor(0.75), 0.25);
  VoidageUpstream plate{true, 0.0, 2.0, true};
  EXPECT_DOUBLE_EQ(plate.above_floor(0.25), 0.25);
  EXPECT_DOUBLE_EQ(plate.above_floor(1.75), 0.25);  // under the plate's image at 2
  EXPECT_DOUBLE_EQ(plate.above_floor(-0.25), 0.25);
  VoidageUpstream open{true, 0.0, 2.0, false};
  EXPECT_TRUE(std::isinf(open.above_floor(0.1)));
}

// With the drag's kernel apart (sphere_kernel_scale 1.5, drag_kernel_scale 1), the fluid
// keeps the wide voidage and everything the drag reads is what the narrow kernel alone
// gives: eps_drag and the Sauter mean at the fluid particles, and the Shepard sum, the
// voidage and the fluid velocity at the spheres.
TEST(Coupling, DragKernelApartGathersWithTheNarrowKernel) {
  Config apart, narrow, wide;
  build(apart, 25, 9, 0.1, 1.5, 1.0);
  build(narrow, 25, 9, 0.1, 1.0);
  build(wide, 25, 9, 0.1, 1.5);
  ASSERT_TRUE(apart.pairs.drag_apart());
  ASSERT_FALSE(wide.pairs.drag_apart());
  for (Config* c : {&apart, &narrow, &wide}) {  // two sizes, so the Sauter mean varies
    for (std::size_t j = 0; j < c->s.n_owned; ++j) c->s.radius[j] = j % 2 ? 4e-5 : 7e-5;
    c->sh.fill(c->s.radius);
    compute_fluid_voidage(c->f, c->s, c->pairs, 0.05);
  }
  double eps_moved = 0;
  for (std::size_t a = 0; a < apart.f.n_owned; ++a) {
    EXPECT_NEAR(apart.f.eps_drag[a], narrow.f.eps[a], 1e-14) << a;
    EXPECT_NEAR(apart.f.d_sauter[a], narrow.f.d_sauter[a], 1e-18) << a;
    EXPECT_NEAR(apart.f.eps[a], wide.f.eps[a], 1e-14) << a;
    eps_moved = std::max(eps_moved, std::abs(apart.f.eps[a] - apart.f.eps_drag[a]));
  }
  EXPECT_GT(eps_moved, 1e-3);  // the two voidages differ: the test can tell them apart
  for (Config* c : {&apart, &narrow})
    interpolate_fluid_at_spheres(c->s, c->f, c->pairs, c->sh, c->scratch);
  for (std::size_t j = 0; j < apart.s.n_owned; ++j) {
    EXPECT_NEAR(apart.s.shepard[j] / narrow.s.shepard[j], 1.0, 1e-13) << j;
    EXPECT_NEAR(apart.s.eps[j], narrow.s.eps[j], 1e-14) << j;
    EXPECT_NEAR(apart.s.ufz[j], narrow.s.ufz[j], 1e-13) << j;
    EXPECT_NEAR(apart.s.d_sauter[j], narrow.s.d_sauter[j], 1e-18) << j;
  }
}

// The voidage deficit integrates to the solid volume: sum_a (m_a/rho_a)(1 - eps_a)
// = sum_j V_j sum_a (m_a/rho_a) W_aj, which is V_j times the kernel's partition of
// unity at the sphere (1 within the lattice's quadrature error, here ~1e-3).
TEST(Coupling, VoidageDeficitIntegratesToSolidVolume) {
  Config c;
  build(c, 1, 11);
  FluidParticles& f = c.f;
  DemParticles& s = c.s;
  // one sphere in the middle of a regular lattice of equal volumes
  const double dx = 2e-4;
  for (std::size_t a = 0; a < f.n_owned; ++a) {
    f.x[a] = (std::floor(f.x[a] / dx) + 0.5) * dx;
    f.y[a] = (std::floor(f.y[a] / dx) + 0.5) * dx;
    f.z[a] = (std::floor(f.z[a] / dx) + 0.5) * dx;
    f.rho[a] = 1000.0;
    f.h[a] = 1.5 * dx;
    f.inv_h[a] = 1.0 / f.h[a];
  }
  s.x[0] = 0.8e-3;
  s.y[0] = 0.8e-3;
  s.z[0] = 1.0e-3;
  s.resize(1);
  c.scells.build(s.x.data(), s.y.data(), s.z.data(), 1, c.cutoff, 2);
  c.pairs.build(f, s, c.scells);
  compute_fluid_voidage(f, s, c.pairs, 0.05);
  double deficit = 0;
  for (std::size_t a = 0; a < f.n_owned; ++a) deficit += f.mass[a] / f.rho[a] * (1.0 - f.eps[a]);
  EXPECT_NEAR(deficit / s.volume(0), 1.0, 2e-3);
}

// The local Sauter mean diameter (2.80) carried to the spheres: exactly d for one size,
// and between the sizes (the volume-weighted harmonic mean) for a mixture.
TEST(Coupling, SauterMeanDiameterAtSpheres) {
  Config c;
  build(c, 25, 5);
  FluidParticles& f = c.f;
  DemParticles& s = c.s;
  for (std::size_t j = 0; j < s.size(); ++j) s.radius[j] = 6e-5;  // one size (halo copies too)
  c.pairs.build(f, s, c.scells);
  compute_fluid_voidage(f, s, c.pairs, 0.05);
  interpolate_fluid_at_spheres(s, f, c.pairs, c.sh, c.scratch);
  for (std::size_t j = 0; j < s.n_owned; ++j) EXPECT_NEAR(s.d_sauter[j], 1.2e-4, 1e-16);
  for (std::size_t j = 0; j < s.n_owned; ++j) s.radius[j] = (j % 2) ? 4e-5 : 8e-5;
  c.sh.fill(s.radius);
  c.pairs.build(f, s, c.scells);
  compute_fluid_voidage(f, s, c.pairs, 0.05);
  interpolate_fluid_at_spheres(s, f, c.pairs, c.sh, c.scratch);
  for (std::size_t j = 0; j < s.n_owned; ++j) {
    EXPECT_GT(s.d_sauter[j], 0.8e-4);
    EXPECT_LT(s.d_sauter[j], 1.6e-4);
  }
}

// Variational pressure coupling (coupling/pressure_coupling.hpp): with the walls' pressure
// zero, the fluid particles' pair forces V_a P_a grad eps_a and the spheres' pressure
// forces V_j g_j cancel to round-off (each pair is written with both signs).
TEST(Coupling, VariationalPressureForcesCancelPairByPair) {
  for (unsigned seed : {4u, 5u}) {
    Config c;
    build(c, 25, seed);
    FluidParticles& f = c.f;
    DemParticles& s = c.s;
    std::mt19937 rng(seed + 200);
    std::uniform_real_distribution<double> u(0.0, 100.0);
    for (std::size_t a = 0; a < f.n_owned; ++a) f.P[a] = f.kind[a] == kWall ? 0.0 : u(rng);
    std::fill(f.ax.begin(), f.ax.end(), 0.0);
    std::fill(f.ay.begin(), f.ay.end(), 0.0);
    std::fill(f.az.begin(), f.az.end(), 0.0);
    couple_pressure_variationally(f, s, c.pairs, c.sh, c.scratch);
    double sum[3] = {0, 0, 0}, scale = 0;
    for (std::size_t a = 0; a < f.n_owned; ++a) {
      const double m = f.mass[a];
      sum[0] += m * f.ax[a];
      sum[1] += m * f.ay[a];
      sum[2] += m * f.az[a];
      scale += m * (std::abs(f.ax[a]) + std::abs(f.ay[a]) + std::abs(f.az[a]));
    }
    for (std::size_t j = 0; j < s.n_owned; ++j) {
      const double V = s.volume(j);
      sum[0] += V * s.gx[j];
      sum[1] += V * s.gy[j];
      sum[2] += V * s.gz[j];
    }
    ASSERT_GT(scale, 0.0);
    for (int d = 0; d < 3; ++d) EXPECT_LT(std::abs(sum[d]), 1e-13 * scale) << "axis " << d;
  }
}

// In a hydrostatic fluid, P = rho g (z_ref - z), the variational pressure force on a
// sphere well inside the fluid is Archimedes' V rho g, upward: the sum
// sum_a V_a P_a grad_a W_aj is the SPH estimate of -grad P at the sphere. Uniform rho,
// so V_a = dx^3, and h = 1.5 dx. Neither sum is corrected, so the estimate carries the
// lattice's discrete kernel moments: measured, for the 23 spheres 3.5 dx or more from
// the wall and the top, at most 1.1 % on the regular lattice and 6.7 % on the lattice
// jittered by 0.1 dx (mostly the zeroth-order error P_j sum_a V_a grad W, which grows
// with the sphere's distance from z_ref). A wrong sign, factor V or kernel is off by
// 100 % or more.
TEST(Coupling, VariationalPressureForceIsBuoyancy) {
  for (double jitter : {0.0, 0.1}) {
    Config c;
    build(c, 40, 6u, jitter);
    FluidParticles& f = c.f;
    DemParticles& s = c.s;
    const double rho = 1000.0, g = 9.81, z_ref = 0.5 * c.box.hi[2], dx = 2e-4;
    for (std::size_t a = 0; a < f.size(); ++a) {
      f.rho[a] = rho;
      f.h[a] = 1.5 * dx;
      f.inv_h[a] = 1.0 / f.h[a];
      f.P[a] = rho * g * (z_ref - f.z[a]);
    }
    c.pairs.build(f, s, c.scells);
    couple_pressure_variationally(f, s, c.pairs, c.sh, c.scratch);
    int checked = 0;
    double worst = 0.0;
    for (std::size_t j = 0; j < s.n_owned; ++j) {
      if (s.z[j] < 3.5 * dx || s.z[j] > c.box.hi[2] - 3.5 * dx)
        continue;  // kernel cut by the wall or the top
      ++checked;
      worst = std::max(worst, std::abs(s.gz[j] / (rho * g) - 1.0));
      worst = std::max(worst, std::hypot(s.gx[j], s.gy[j]) / (rho * g));
    }
    std::printf("jitter %.1f dx: %d spheres, largest relative error of the buoyancy %.2e\n", jitter,
                checked, worst);
    EXPECT_GE(checked, 10);
    EXPECT_LT(worst, jitter == 0.0 ? 0.015 : 0.08);
  }
}

namespace {

// Tait: e(rho) with de/drho = P/rho^2 for P = B((rho/rho0)^gamma - 1), rho intrinsic.
struct TaitEnergy {
  double rho0 = 1000.0, B = 1e5;
  int gamma = 7;
  double pressure(double rho) const { return B * (std::pow(rho / rho0, gamma) - 1.0); }
  double energy(double rho) const {
    return B * (std::pow(rho / rho0, gamma) / ((gamma - 1) * rho) + 1.0 / rho);
  }
};

// Rebuilds the sphere halo, pairs and voidage after moving particles, sets P from the
// EOS at the new voidage, and returns the energy whose gradient the variational coupling
// is: U = sum_a m_a [e(rho_a/eps_a) + P_h(z_a) eps_a/rho_a] + sum_j V_j P_h(z_j)
// (rho_a, the superficial density, held fixed: its own dependence on the positions is
// the SPH pair term).
double coupling_energy(Config& c, const TaitEnergy& eos, const HydrostaticPressure& ph) {
  FluidParticles& f = c.f;
  DemParticles& s = c.s;
  rebuild_sphere_side(c);
  double U = 0.0;
  for (std::size_t a = 0; a < f.n_owned; ++a) {
    const double rho_i = f.rho[a] / f.eps[a];
    f.P[a] = eos.pressure(rho_i);
    U += f.mass[a] * (eos.energy(rho_i) + ph(f.z[a]) / rho_i);
  }
  for (std::size_t j = 0; j < s.n_owned; ++j) U += s.volume(j) * ph(s.z[j]);
  return U;
}

}  // namespace

// The split's P_h (sph/hydrostatic_pressure.hpp): the depth below z_s times rho0 |g|,
// zero above z_s, and gradient_z the derivative of its value on either side (a taper, a
// depth continued above z_s or a wrong sign fails).
TEST(Coupling, HydrostaticSplitIsTheDepthBelowTheFillHeight) {
  const double rho0 = 1000.0, g = -9.81, zs = 0.1;
  const HydrostaticPressure ph{rho0, g, zs};
  for (const double z : {0.0, 0.03, 0.099, zs - 1e-9}) {
    EXPECT_NEAR(ph(z), rho0 * 9.81 * (zs - z), 1e-12 * rho0 * 9.81) << "z " << z;
    EXPECT_DOUBLE_EQ(ph.gradient_z(z), rho0 * g) << "z " << z;
  }
  for (const double z : {zs, zs + 1e-9, zs + 0.01}) {
    EXPECT_EQ(ph(z), 0.0) << "z " << z;
    EXPECT_EQ(ph.gradient_z(z), 0.0) << "z " << z;
  }
  EXPECT_EQ(HydrostaticPressure{}(0.0), 0.0);  // no split
  EXPECT_EQ(HydrostaticPressure{}.gradient_z(0.0), 0.0);
}

// The variational coupling's forces are minus the gradient of the energy above, with and
// without the hydrostatic split (scene key coupling.hydrostatic_split; with z_s at the box's
// top, and at half its height, among the spheres, where P_h and its force stop: a force added
// above z_s fails), with the fluid's
// kernel and with the spheres' kernel twice as wide (coupling.sphere_kernel_scale = 2; its
// support, 1.3 mm, exceeds half the 1.6 mm periodic box, so spheres near a face reach a
// fluid particle through two images): checked against
// central differences (step 1e-7 m, 5e-4 of the spacing; truncation ~1e-7) on every
// axis of the spheres off the periodic faces and of 20 fluid particles near spheres.
// A wrong sign, factor or missing term (the split's -grad P_h/rho on the fluid, its
// buoyancy on the spheres, P_h's force above z_s) is an O(1) error. Measured: 7.1e-5 (no
// split, and z_s at half the box, the same top-layer particle), 9.3e-6 or less in the other
// four, the floor of the differences (step 3e-7: 9e-5, truncation; 1e-8: 9e-5, round-off).
TEST(Coupling, VariationalPressureForcesAreMinusTheEnergyGradient) {
  const TaitEnergy eos;
  for (const auto& [split, kernel_scale] :
       {std::pair{0, 1.0}, {1, 1.0}, {2, 1.0}, {0, 2.0}, {1, 2.0}, {2, 2.0}}) {
    Config c;
    build(c, 12, 9u, 0.1, kernel_scale);
    FluidParticles& f = c.f;
    DemParticles& s = c.s;
    for (std::size_t j = 0; j < s.n_owned; ++j)
      s.radius[j] *= 2.0;  // voidage 0.9-1, away from the floor
    // a strong 'gravity' so that P_h (up to 4e4 Pa) is as large as the EOS's P (B = 1e5 Pa)
    // split 2: z_s at half the box, among the spheres (0.2-0.8 of it)
    const double surface = (split == 2 ? 0.5 : 1.0) * c.box.hi[2];
    const HydrostaticPressure ph =
        split ? HydrostaticPressure{1000.0, -2e4, surface} : HydrostaticPressure{};
    coupling_energy(c, eos, ph);
    std::fill(f.ax.begin(), f.ax.end(), 0.0);
    std::fill(f.ay.begin(), f.ay.end(), 0.0);
    std::fill(f.az.begin(), f.az.end(), 0.0);
    couple_pressure_variationally(f, s, c.pairs, c.sh, c.scratch, ph);
    const std::vector<double> fax = f.ax, fay = f.ay, faz = f.az;
    const std::vector<double> sgx(s.gx.begin(), s.gx.begin() + s.n_owned),
        sgy(s.gy.begin(), s.gy.begin() + s.n_owned), sgz(s.gz.begin(), s.gz.begin() + s.n_owned);
    const double step = 1e-7;
    auto minus_gradient = [&](double& coord) {
      const double x0 = coord;
      coord = x0 + step;
      const double up = coupling_energy(c, eos, ph);
      coord = x0 - step;
      const double down = coupling_energy(c, eos, ph);
      coord = x0;
      return -(up - down) / (2.0 * step);
    };
    double worst = 0.0;
    int spheres = 0, fluid = 0, above = 0;  // above: those checked above z_s (split 2)
    for (std::size_t j = 0; j < s.n_owned; ++j) {
      if (c.sh.n_ghost() && (s.y[j] < 1e-5))
        continue;  // on the periodic face (images move too; kept simple)
      above += split == 2 && s.z[j] > ph.surface;
      const double V = s.volume(j);
      const double analytic[3] = {V * sgx[j], V * sgy[j], V * sgz[j]};
      double* coord[3] = {&s.x[j], &s.y[j], &s.z[j]};
      const double scale = std::hypot(analytic[0], analytic[1], analytic[2]);
      for (int d = 0; d < 3; ++d)
        worst = std::max(worst, std::abs(minus_gradient(*coord[d]) - analytic[d]) / scale);
      ++spheres;
    }
    for (std::size_t k = 0; k < f.n_owned && fluid < 20; ++k) {
      const std::size_t a = f.n_owned - 1 - k;  // from the top layer down
      if (f.kind[a] != kFluid || std::abs(fax[a]) + std::abs(fay[a]) < 1e-3 * std::abs(faz[a]))
        continue;
      above += split == 2 && f.z[a] > ph.surface;
      const double m = f.mass[a];
      const double analytic[3] = {m * fax[a], m * fay[a], m * faz[a]};
      double* coord[3] = {&f.x[a], &f.y[a], &f.z[a]};
      const double scale = std::hypot(analytic[0], analytic[1], analytic[2]);
      for (int d = 0; d < 3; ++d)
        worst = std::max(worst, std::abs(minus_gradient(*coord[d]) - analytic[d]) / scale);
      ++fluid;
    }
    std::printf(
        "split %d, sphere kernel scale %g: %d spheres, %d fluid particles, largest relative "
        "deviation %.2e (%d above z_s)\n",
        split, kernel_scale, spheres, fluid, worst, above);
    EXPECT_GE(spheres, 5);
    if (split == 2) {
      EXPECT_GE(above, 10);
    }
    EXPECT_EQ(fluid, 20);
    EXPECT_LT(worst, 1e-4);
  }
}

// Each fluid particle's kept entries are exactly the spheres (owned and halo) within its
// kernel support 2 H_a, with W(r, H_a) and its gradient factor; the voidage (2.50) and the
// reaction (2.71) over them are the sums over every sphere: all found here by brute force,
// with either instruction set of the passes (sph/pair_isa.hpp).
TEST(Coupling, PairPassesMatchBruteForceWithEitherInstructionSet) {
  for (double drag_kernel_scale : {0.0, 1.0}) {  // the drag's kernel the spheres', or apart
    Config c;
    build(c, 60, 11, 0.1, /*kernel_scale=*/1.5, drag_kernel_scale);
    FluidParticles& f = c.f;
    DemParticles& s = c.s;
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (std::size_t j = 0; j < s.size(); ++j) {  // halo copies need not match their owners here
      s.fmx[j] = u(rng);
      s.fmy[j] = u(rng);
      s.fmz[j] = u(rng);
      s.shepard[j] = j % 7 == 0 ? 0.0 : 1.0 + 0.5 * u(rng);  // some spheres see no fluid
    }
    std::vector<PairIsa> isas{PairIsa::kBaseline};
    if (best_pair_isa() == PairIsa::kAvx512) isas.push_back(PairIsa::kAvx512);
    for (PairIsa isa : isas) {
      c.pairs.evaluate(f, s, true, isa);
      compute_fluid_voidage(f, s, c.pairs, 0.0);
      for (std::size_t a = 0; a < f.n_owned; ++a) f.ax[a] = f.ay[a] = f.az[a] = 0.0;
      add_reaction_on_fluid(f, s, c.pairs, c.scratch, nullptr, isa);
      std::size_t pairs_seen = 0;
      for (std::size_t a = 0; a < f.n_owned; ++a) {
        const double inv_h = c.pairs.inv_kernel_h(f, a), H = 1.0 / inv_h;
        const double Hd = 1.0 / c.pairs.inv_drag_kernel_h(f, a);
        std::vector<std::pair<std::uint32_t, double>> want, got;
        double solid = 0.0, drag_solid = 0.0, react[3] = {0, 0, 0}, react_abs = 0.0;
        for (std::uint32_t j = 0; j < s.size(); ++j) {
          const double dx = f.x[a] - s.x[j], dy = f.y[a] - s.y[j], dz = f.z[a] - s.z[j];
          const double r2 = dx * dx + dy * dy + dz * dz;
          if (r2 >= 4.0 * H * H) continue;
          want.push_back({j, r2});
          solid += 4.0 / 3.0 * M_PI * std::pow(s.radius[j], 3) * kernel::w(r2, H);
          drag_solid += 4.0 / 3.0 * M_PI * std::pow(s.radius[j], 3) * kernel::w(r2, Hd);
          if (s.shepard[j] == 0.0) continue;
          const double share = kernel::w(r2, Hd) / s.shepard[j];  // the reaction: the drag's W
          react[0] += s.fmx[j] * share;
          react[1] += s.fmy[j] * share;
          react[2] += s.fmz[j] * share;
          react_abs += (std::abs(s.fmx[j]) + std::abs(s.fmy[j]) + std::abs(s.fmz[j])) * share;
        }
        EXPECT_NEAR(f.eps[a], 1.0 - solid, 1e-13) << "fluid particle " << a;
        EXPECT_NEAR(f.eps_drag[a], 1.0 - drag_solid, 1e-13) << "fluid particle " << a;
        if (f.kind[a] == kFluid) {
          const double tol = 1e-13 * react_abs / f.rho[a];
          EXPECT_NEAR(f.ax[a], -react[0] / f.rho[a], tol) << "fluid particle " << a;
          EXPECT_NEAR(f.ay[a], -react[1] / f.rho[a], tol) << "fluid particle " << a;
          EXPECT_NEAR(f.az[a], -react[2] / f.rho[a], tol) << "fluid particle " << a;
        }
        for (std::uint32_t k = c.pairs.begin(a); k < c.pairs.end(a); ++k)
          got.push_back({c.pairs.sphere[k], 0.0});
        ASSERT_EQ(got.size(), want.size()) << "fluid particle " << a;
        std::sort(got.begin(), got.end());
        for (std::size_t i = 0; i < want.size(); ++i)
          ASSERT_EQ(got[i].first, want[i].first) << "fluid particle " << a;
        for (std::uint32_t k = c.pairs.begin(a); k < c.pairs.end(a); ++k) {
          const std::uint32_t j = c.pairs.sphere[k];
          const double dx = f.x[a] - s.x[j], dy = f.y[a] - s.y[j], dz = f.z[a] - s.z[j];
          const double r2 = dx * dx + dy * dy + dz * dz;
          EXPECT_NEAR(c.pairs.w[k], kernel::w(r2, H), 1e-13 * kernel::w(0.0, H));
          EXPECT_NEAR(c.pairs.drag_w()[k], kernel::w(r2, Hd), 1e-13 * kernel::w(0.0, Hd));
          EXPECT_NEAR(c.pairs.grad[k], kernel::grad_factor(r2, H),
                      1e-13 * std::abs(kernel::grad_factor(0.25 * H * H, H)));
          ++pairs_seen;
        }
      }
      EXPECT_GT(pairs_seen, 10 * f.n_owned)
          << "the configuration should give every particle spheres";
    }
  }
}

// The pass from the fluid to the spheres (interpolation.hpp), interpolated and with the
// variational pairs (pressure_coupling.hpp), against sums over every fluid particle and
// every sphere image found by brute force, with either instruction set: the Shepard sum
// S_j, u_f,j, eps_j and g_j = sum_b m_b theta_b W_jb / S_j (2.69, 2.72), or
// g_j = sum_a V_a P_a grad_a W_aj - dP_h/dz and the fluid's share -P_a/rho_a sum_j V_j
// grad_a W_aj. A wrong kernel (the drag's or the pairs'), field or image is an O(1) error.
TEST(Coupling, SphereSumsMatchBruteForceWithEitherInstructionSet) {
  for (double drag_kernel_scale : {0.0, 1.0}) {
    Config c;
    build(c, 60, 12, 0.1, /*kernel_scale=*/1.5, drag_kernel_scale);
    FluidParticles& f = c.f;
    DemParticles& s = c.s;
    std::mt19937 rng(8);
    std::uniform_real_distribution<double> u(0.0, 100.0);
    for (std::size_t a = 0; a < f.n_owned; ++a) f.P[a] = u(rng);
    const HydrostaticPressure ph{1000.0, -9.81, 0.6 * c.box.hi[2]};  // z_s among the spheres
    const std::size_t ns = s.n_owned;
    const auto owner = [&](std::size_t j) { return j < ns ? j : c.sh.periodic().source()[j - ns]; };
    // brute force: per owned sphere, S, S eps, S u_x, m theta_x W, and the pressure sums
    std::vector<double> S(ns, 0.0), Se(ns, 0.0), Su(ns, 0.0), Mt(ns, 0.0), Pg[3];
    for (auto& v : Pg) v.assign(ns, 0.0);
    std::vector<double> fluid_share(f.n_owned, 0.0);  // -P_a/rho_a sum_j V_j dW/dz_a
    for (std::size_t a = 0; a < f.n_owned; ++a) {
      const double H = 1.0 / c.pairs.inv_kernel_h(f, a), Hd = 1.0 / c.pairs.inv_drag_kernel_h(f, a);
      const double V = f.mass[a] / f.rho[a], vp = V * (f.P[a] - ph(f.z[a]));
      for (std::size_t j = 0; j < s.size(); ++j) {
        const double d[3] = {f.x[a] - s.x[j], f.y[a] - s.y[j], f.z[a] - s.z[j]};
        const double r2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
        if (r2 >= 4.0 * H * H) continue;
        const std::size_t o = owner(j);
        const double gf = kernel::grad_factor(r2, H);
        for (int k = 0; k < 3; ++k) Pg[k][o] += vp * gf * d[k];
        fluid_share[a] -= (f.P[a] - ph(f.z[a])) / f.rho[a] * s.volume(j) * gf * d[2];
        if (f.kind[a] != kFluid) continue;
        const double w = kernel::w(r2, Hd);
        S[o] += V * w;
        Se[o] += V * w * f.eps_drag[a];
        Su[o] += V * w * f.vx[a];
        Mt[o] += f.mass[a] * w * f.thz[a];
      }
    }
    std::vector<PairIsa> isas{PairIsa::kBaseline};
    if (best_pair_isa() == PairIsa::kAvx512) isas.push_back(PairIsa::kAvx512);
    for (PairIsa isa : isas) {
      interpolate_fluid_at_spheres(s, f, c.pairs, c.sh, c.scratch, nullptr, isa);
      int seen = 0;
      for (std::size_t j = 0; j < ns; ++j) {
        EXPECT_NEAR(s.shepard[j], S[j], 1e-13 * S[j]) << "sphere " << j;
        if (S[j] == 0.0) continue;
        ++seen;
        EXPECT_NEAR(s.eps[j], Se[j] / S[j], 1e-13) << "sphere " << j;
        EXPECT_NEAR(s.ufx[j], Su[j] / S[j], 1e-13) << "sphere " << j;
        EXPECT_NEAR(s.gz[j], Mt[j] / S[j], 1e-10) << "sphere " << j;  // |rho theta| < 1100
      }
      EXPECT_GE(seen, 30);
      std::fill(f.az.begin(), f.az.end(), 0.0);
      interpolate_fluid_at_spheres(s, f, c.pairs, c.sh, c.scratch, &ph, isa);
      for (std::size_t j = 0; j < ns; ++j) {
        const double scale = std::abs(Pg[0][j]) + std::abs(Pg[1][j]) + std::abs(Pg[2][j]) + 1.0;
        EXPECT_NEAR(s.gx[j], Pg[0][j], 1e-12 * scale) << "sphere " << j;
        EXPECT_NEAR(s.gy[j], Pg[1][j], 1e-12 * scale) << "sphere " << j;
        EXPECT_NEAR(s.gz[j], Pg[2][j] - ph.gradient_z(s.z[j]), 1e-12 * scale) << "sphere " << j;
      }
      for (std::size_t a = 0; a < f.n_owned; ++a) {
        if (f.kind[a] != kFluid) continue;
        const double want = fluid_share[a] - ph.gradient_z(f.z[a]) * f.eps[a] / f.rho[a];
        EXPECT_NEAR(f.az[a], want, 1e-12 * (std::abs(want) + 1.0)) << "fluid particle " << a;
      }
    }
  }
}
