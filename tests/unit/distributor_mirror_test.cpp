// The drag's weights of a bed on the distributor (coupling/distributor_mirror.hpp): a
// lattice bed standing on the plate of a column periodic in z reads, at the plate, the
// voidage and fluid velocity of its interior, the plenum across the plate reads no
// sphere, and the drag's momentum still balances.
#include "coupling/distributor_mirror.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "coupling/fluid_sphere_pairs.hpp"
#include "coupling/interpolation.hpp"
#include "coupling/reaction.hpp"
#include "coupling/voidage.hpp"
#include "domain/box.hpp"
#include "domain/cell_list.hpp"
#include "domain/halo.hpp"
#include "sph/kernel.hpp"

using namespace sphdem;

namespace {

constexpr double kDx = 2e-4, kRho0 = 1000.0;
constexpr int kNx = 6, kNz = 20, kBedLayers = 10;  // fluid layers; the bed fills the lower 10

// A fluid lattice filling a box periodic in x, y and z, and a simple-cubic bed of spheres
// (spacing dx/2, the first layer dx/4 over the plate at z = 0) up to kBedLayers dx: the
// bed mirrored in the plate is the same lattice continued, so with the mirror a fluid
// particle at dx/2 sees what one at dx/2 + k dx inside the bed sees.
struct Column {
  Box box;
  FluidParticles f;
  DemParticles s;
  Halo fh, sh;
  CellList fcells, scells;
  FluidSpherePairs pairs;
  PairAccumulator scratch;
  DistributorPlane plane;

  explicit Column(bool mirror) {
    box.lo = {0, 0, 0};
    box.hi = {kNx * kDx, kNx * kDx, kNz * kDx};
    box.periodic = {true, true, true};
    plane = mirror ? DistributorPlane{0.0, box.length(2)} : DistributorPlane{};
    f.resize(kNx * kNx * kNz);
    f.n_owned = f.size();
    std::size_t k = 0;
    for (int iz = 0; iz < kNz; ++iz)
      for (int iy = 0; iy < kNx; ++iy)
        for (int ix = 0; ix < kNx; ++ix, ++k) {
          f.x[k] = (ix + 0.5) * kDx;
          f.y[k] = (iy + 0.5) * kDx;
          f.z[k] = (iz + 0.5) * kDx;
          f.kind[k] = kFluid;
          f.rho[k] = kRho0;
          f.mass[k] = kRho0 * kDx * kDx * kDx;
          f.h[k] = 1.5 * kDx;
          f.inv_h[k] = 1.0 / f.h[k];
          f.vz[k] = iz < kBedLayers ? 2.0 : 1.0;  // faster through the bed, as U / eps
        }
    const double a = 0.5 * kDx;
    const int n_side = 2 * kNx, n_layers = 2 * kBedLayers;
    s.resize(n_side * n_side * n_layers);
    s.n_owned = s.size();
    k = 0;
    for (int iz = 0; iz < n_layers; ++iz)
      for (int iy = 0; iy < n_side; ++iy)
        for (int ix = 0; ix < n_side; ++ix, ++k) {
          s.x[k] = (ix + 0.5) * a;
          s.y[k] = (iy + 0.5) * a;
          s.z[k] = (iz + 0.5) * a;
          s.radius[k] = 0.45 * a;
          s.mass[k] = 2500.0 * s.volume(k);
        }
    const double cutoff = kernel::kSupport * 1.5 * kDx * 1.05;
    fh.build(box, cutoff, f.x.data(), f.y.data(), f.z.data(), f.n_owned);
    f.resize(f.n_owned + fh.n_ghost());
    fh.fill_positions(f.x.data(), f.y.data(), f.z.data());
    for (auto* v : {&f.vx, &f.vy, &f.vz, &f.mass, &f.h, &f.inv_h, &f.rho}) fh.fill(*v);
    fh.fill(f.kind);
    sh.build(box, cutoff, s.x.data(), s.y.data(), s.z.data(), s.n_owned);
    s.resize(s.n_owned + sh.n_ghost());
    sh.fill_positions(s.x.data(), s.y.data(), s.z.data());
    sh.fill(s.radius);
    sh.fill(s.mass);
    scells.build(s.x.data(), s.y.data(), s.z.data(), s.size(), cutoff, 2);
    pairs.keep_drag_weights = mirror;
    pairs.build(f, s, scells);
    continue_bed_below_distributor(pairs, f, s, plane);
    compute_fluid_voidage(f, s, pairs, 0.05);
    fh.fill(f.eps_drag);
    fh.fill(f.d_sauter);
    interpolate_fluid_at_spheres(s, f, pairs, sh, scratch);
  }

  // Owned fluid particle at lattice (ix, iy, iz).
  static std::size_t at(int ix, int iy, int iz) { return (iz * kNx + iy) * kNx + ix; }
  // Owned sphere at lattice (ix, iy, iz).
  static std::size_t sphere_at(int ix, int iy, int iz) {
    return (iz * 2 * kNx + iy) * 2 * kNx + ix;
  }
};

}  // namespace

// At the plate the drag's voidage is the bed's interior value (to round-off), where the
// plain kernel, half in the plenum, reads it a quarter of the way to clear fluid.
TEST(DistributorMirror, BedReadsItsInteriorVoidageAtThePlate) {
  const Column mirrored(true), plain(false);
  const std::size_t bottom = Column::at(2, 3, 0), inside = Column::at(2, 3, 4);
  EXPECT_NEAR(mirrored.f.eps_drag[bottom], mirrored.f.eps_drag[inside], 1e-12);
  EXPECT_GT(plain.f.eps_drag[bottom] - plain.f.eps_drag[inside], 0.05);  // the test can tell
  // the plain voidage of the fluid's equation of state is left as it was
  EXPECT_EQ(mirrored.f.eps[bottom], plain.f.eps[bottom]);
  EXPECT_NEAR(plain.f.eps_drag[inside], mirrored.f.eps_drag[inside], 1e-14);  // far from it
}

// The plenum just under the plate (the column's top, through the periodic face) holds no
// sphere: its drag's voidage is 1 exactly, where the plain kernel reaches the bed.
TEST(DistributorMirror, PlenumSeesNoSphereAcrossThePlate) {
  const Column mirrored(true), plain(false);
  const std::size_t top = Column::at(1, 1, kNz - 1);
  EXPECT_EQ(mirrored.f.eps_drag[top], 1.0);
  EXPECT_LT(plain.f.eps_drag[top], 0.95);
}

// The bottom layer of spheres gathers the interior's voidage and fluid velocity.
TEST(DistributorMirror, BottomSpheresGatherTheInterior) {
  const Column mirrored(true), plain(false);
  const std::size_t bottom = Column::sphere_at(3, 5, 0), inside = Column::sphere_at(3, 5, 8);
  EXPECT_NEAR(mirrored.s.eps[bottom], mirrored.s.eps[inside], 1e-12);
  EXPECT_NEAR(mirrored.s.ufz[bottom], 2.0, 1e-12);  // only the bed's fluid, at 2 m/s
  EXPECT_LT(plain.s.ufz[bottom], 1.9);              // the plenum's 1 m/s mixed in
  EXPECT_GT(plain.s.eps[bottom] - plain.s.eps[inside], 0.05);
}

// The reaction returns the spheres' fluid force to the fluid whole: a conservation check,
// true of any weights the interpolation and the reaction share.
TEST(DistributorMirror, ReactionBalancesTheSpheresForce) {
  Column c(true);
  for (std::size_t j = 0; j < c.s.size(); ++j) {
    c.s.fmx[j] = 0.0;
    c.s.fmy[j] = 0.0;
    c.s.fmz[j] = j < c.s.n_owned ? 1e-6 * (1.0 + 0.01 * (j % 7)) : 0.0;
  }
  c.sh.fill(c.s.fmz);
  c.sh.fill(c.s.shepard);
  std::fill(c.f.az.begin(), c.f.az.end(), 0.0);
  add_reaction_on_fluid(c.f, c.s, c.pairs, c.scratch, nullptr);
  double on_spheres = 0.0, on_fluid = 0.0;
  for (std::size_t j = 0; j < c.s.n_owned; ++j) on_spheres += c.s.fmz[j];
  for (std::size_t a = 0; a < c.f.n_owned; ++a) on_fluid += c.f.mass[a] * c.f.az[a];
  EXPECT_NEAR(on_fluid / on_spheres, -1.0, 1e-12);
}
