// The Verlet lists stay complete between rebuilds: in a suspension whose particles are
// thrown in random directions and cross the skin every few steps, after every step at which a list
// still has skin left (Simulation::verlet_margins >= 0, i.e. it would be used again without a
// rebuild), each fluid pair within 2 max(h_a, h_b) (minimum image, brute force over the
// owned particles) is in the half list, and each fluid-sphere pair within the fluid
// particle's 2 H_a is in its row of the fluid-sphere list; the lists are reused on most
// steps.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <set>
#include <string>
#include <utility>

#include "propagator/simulation.hpp"
#include "scene/scene.hpp"
#include "sph/kernel.hpp"

using namespace sphdem;

namespace {

const char* kShearedSuspension = R"(
name: sheared_suspension
domain: {size: [0.002, 0.002, 0.003]}
fluid: {spacing: 2.0e-4, sound_speed: 10}
species: [{name: glass, diameter: 1.0e-4, density: 2500}]
particles:
  - {type: random, species: [glass], min: [0, 0, 0.0002], max: [0.002, 0.002, 0.0026], voidage: 0.97, seed: 3}
coupling: {sphere_kernel_scale: 1.5}
contact: {skin: 2.0}  # sphere lists rebuilt rarely: the fluid-sphere criterion decides
startup: {relax_steps: 0}
)";

double min_image(const Box& box, int d, double v) {
  if (!box.periodic[d]) return v;
  const double L = box.length(d);
  return v - L * std::round(v / L);
}

double distance2(const Box& box, double dx, double dy, double dz) {
  dx = min_image(box, 0, dx);
  dy = min_image(box, 1, dy);
  dz = min_image(box, 2, dz);
  return dx * dx + dy * dy + dz * dz;
}

using IdPair = std::pair<std::uint32_t, std::uint32_t>;
IdPair ordered(std::uint32_t a, std::uint32_t b) {
  return a < b ? IdPair{a, b} : IdPair{b, a};
}

// Fluid pairs within reach that the half list misses (each unordered pair of ids once;
// halo copies carry their owner's id).
int missing_fluid_pairs(const Simulation& sim) {
  const FluidParticles& f = sim.fluid();
  const NeighbourList& list = sim.fluid_pairs();
  std::set<IdPair> listed;
  for (std::size_t a = 0; a < f.n_owned; ++a)
    for (std::uint32_t k = list.begin(a); k < list.end(a); ++k)
      listed.insert(ordered(f.id[a], f.id[list.neighbour[k]]));
  const Box& box = sim.params().box;
  int missing = 0;
  for (std::size_t a = 0; a < f.n_owned; ++a)
    for (std::size_t b = a + 1; b < f.n_owned; ++b) {
      const double reach = kernel::kSupport * std::max(f.h[a], f.h[b]);
      if (distance2(box, f.x[a] - f.x[b], f.y[a] - f.y[b], f.z[a] - f.z[b]) < reach * reach)
        missing += !listed.count(ordered(f.id[a], f.id[b]));
    }
  return missing;
}

// Fluid-sphere pairs within the fluid particle's 2 H_a missing from its list row.
int missing_sphere_pairs(const Simulation& sim) {
  const FluidParticles& f = sim.fluid();
  const DemParticles& s = sim.spheres();
  const FluidSpherePairs& pairs = sim.sphere_pairs();
  const Box& box = sim.params().box;
  int missing = 0;
  for (std::size_t a = 0; a < f.n_owned; ++a) {
    std::set<std::uint32_t> listed;
    for (std::uint32_t k = pairs.list.begin(a); k < pairs.list.end(a); ++k)
      listed.insert(s.id[pairs.list.neighbour[k]]);
    const double reach = kernel::kSupport / pairs.inv_kernel_h(f, a);
    for (std::size_t j = 0; j < s.n_owned; ++j)
      if (distance2(box, f.x[a] - s.x[j], f.y[a] - s.y[j], f.z[a] - s.z[j]) < reach * reach)
        missing += !listed.count(s.id[j]);
  }
  return missing;
}

}  // namespace

TEST(VerletLists, CompleteBetweenRebuildsInAStirredSuspension) {
  Simulation sim(load_scene_text(kShearedSuspension, "sheared_suspension.yaml"));
  sim.set_sort_interval(1 << 30);  // no re-sort: only the skin criteria rebuild
  // Every particle thrown at up to U in a random direction, so that neighbours move apart
  // and together (a shear flow would carry them along together), the spheres at up to 3 U
  // so that the fluid-sphere criterion fires before the fluid one.
  const double U = 0.3;
  std::uint64_t state = 12345;
  auto uniform = [&state] {  // in [-1, 1): splitmix64, the same sequence on every platform
    std::uint64_t z = (state += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return static_cast<double>((z ^ (z >> 31)) >> 11) * 0x1.0p-52 - 1.0;
  };
  FluidParticles& f = sim.fluid();
  for (std::size_t a = 0; a < f.n_owned; ++a)
    if (f.kind[a] == kFluid) {
      f.vx[a] = U * uniform();
      f.vy[a] = U * uniform();
      f.vz[a] = U * uniform();
    }
  DemParticles& s = sim.spheres();
  for (std::size_t j = 0; j < s.n_owned; ++j) {
    s.vx[j] = 3 * U * uniform();
    s.vy[j] = 3 * U * uniform();
    s.vz[j] = 3 * U * uniform();
  }
  ASSERT_GT(s.n_owned, 100u);
  const int steps = 60;
  const long builds_before = sim.neighbour_builds();
  double moved = 0;  // the largest fluid displacement over the run, in units of the skin
  const std::vector<double> x0(f.x.begin(), f.x.begin() + f.n_owned);
  int checked_fluid = 0, checked_sphere = 0;  // steps at which a list had skin left
  for (int n = 0; n < steps; ++n) {
    sim.step();
    const Simulation::VerletMargins margin = sim.verlet_margins();
    if (margin.fluid >= 0) {
      ++checked_fluid;
      ASSERT_EQ(missing_fluid_pairs(sim), 0) << "step " << n;
    }
    if (margin.sphere >= 0) {
      ++checked_sphere;
      ASSERT_EQ(missing_sphere_pairs(sim), 0) << "step " << n;
    }
  }
  for (std::size_t a = 0; a < f.n_owned; ++a)  // (no re-sort, so index a is the same particle)
    moved = std::max(moved,
                     std::abs(min_image(sim.params().box, 0, f.x[a] - x0[a])) / sim.fluid_skin());
  const long builds = sim.neighbour_builds() - builds_before;
  RecordProperty("fluid_list_builds", static_cast<int>(builds));
  RecordProperty("steps_checked", checked_fluid);
  // The particles crossed the skin several times, and the lists were reused in between.
  EXPECT_GT(moved, 1.5);  // the fluid criterion fires at half the skin
  EXPECT_GE(builds, 3);
  EXPECT_LE(builds, steps / 3);
  EXPECT_GE(checked_fluid, steps / 2);
  EXPECT_GE(checked_sphere, steps / 2);
}
