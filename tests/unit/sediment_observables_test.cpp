// The observables of a settling column (Zhao, Houlsby & Utili 2014) against closed forms:
// the excess pore pressure at the base as a first-layer mean (water at rest: in
// hydrostatic_test.cpp), the contact-force network of
// spheres at rest (F_n = k delta, each pair once, periodic images), the size
// distribution of the thirds, and the bulk density rho_b = eps rho_f + (1 - eps) rho_s.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "analysis/bulk_density.hpp"
#include "analysis/contact_network.hpp"
#include "analysis/pore_pressure.hpp"
#include "analysis/size_thirds.hpp"
#include "propagator/simulation.hpp"
#include "scene/scene.hpp"

using namespace sphdem;

namespace {
// Spheres at rest, d = 100 um, k = 10 N/m, no dashpot: A on the wall (overlap 10 um),
// B on A (10 um; the loader refuses a sphere cutting the wall, so A and B are placed
// 10 um higher and moved down), C and D touching across the periodic face x = 0 (20 um).
const char* kTouching = R"(
name: touching
domain: {size: [0.002, 0.002, 0.002]}
fluid: {enabled: false}
species: [{name: glass, diameter: 1.0e-4, density: 2500}]
particles:
  - {type: single, species: glass, position: [0.001, 0.001, 0.00005]}
  - {type: single, species: glass, position: [0.001, 0.001, 0.00014]}
  - {type: single, species: glass, position: [0.00003, 0.0005, 0.001]}
  - {type: single, species: glass, position: [0.00195, 0.0005, 0.001]}
contact: {stiffness: 10, damping: 0}
startup: {relax_steps: 0}
)";

DemParticles spheres(const std::vector<double>& z, const std::vector<double>& d) {
  DemParticles s;
  s.resize(z.size());
  for (std::size_t i = 0; i < z.size(); ++i) {
    s.z[i] = z[i];
    s.radius[i] = 0.5 * d[i];
    s.id[i] = static_cast<std::int64_t>(i);
  }
  s.n_owned = z.size();
  return s;
}
}  // namespace

TEST(ExcessPorePressure, IsTheMeanOverTheFirstLayer) {
  FluidParticles f;
  f.resize(3);
  f.n_owned = 3;
  const BasePorePressure b{1000.0, 10.0, 1.0, 0.01};
  f.kind = {kFluid, kFluid, kFluid};
  f.z = {0.005, 0.004, 0.5};  // the third is not in the first layer
  f.P = {1000.0 * 10.0 * 0.995 + 500.0, 1000.0 * 10.0 * 0.996 + 1500.0, 1e9};
  EXPECT_NEAR(excess_pore_pressure_base(f, b), 1000.0 / 1e4, 1e-12);
  f.kind[1] = kWall;  // walls never count
  EXPECT_NEAR(excess_pore_pressure_base(f, b), 500.0 / 1e4, 1e-12);
}

TEST(WallLoad, IsTheSpringForceOfTheSpheresTouchingTheWall) {
  // overlaps 1 um and 3 um with the wall; the third sphere is clear of it
  const DemParticles s = spheres({0.999e-3, 1.497e-3, 5e-3}, {2e-3, 3e-3, 2e-3});
  const BasePorePressure b{1000.0, 10.0, 0.5, 0.01};
  const double k = 200.0, area = 0.02 * 0.03;
  EXPECT_NEAR(wall_load_base(s, k, area, b), k * 4e-6 / (area * 1000.0 * 10.0 * 0.5), 1e-15);
}

TEST(ContactNetwork, SpheresAtRestCarryKDeltaOncePerPair) {
  const Scene sc = load_scene_text(kTouching, "touching.yaml");
  Simulation sim(sc);
  DemParticles& s = sim.spheres();
  for (std::size_t i = 0; i < s.n_owned; ++i)
    if (s.id[i] == 0 || s.id[i] == 1) s.z[i] -= 1e-5;
  sim.refresh();  // lists and halo images at the new positions
  const ContactNetwork net = contact_network(sim.spheres(), sim.contact_list(), sc.contact.normal);
  ASSERT_EQ(net.size(), 3u);
  int wall = 0, stacked = 0, periodic = 0;
  for (std::size_t c = 0; c < net.size(); ++c) {
    EXPECT_LT(net.id_a[c], net.id_b[c] < 0 ? INT64_MAX : net.id_b[c]);
    if (net.id_b[c] == -1) {  // A on the wall: delta = r - z = 10 um
      ++wall;
      EXPECT_NEAR(net.overlap[c], 1e-5, 1e-15);
      EXPECT_NEAR(net.normal_force[c], 10.0 * 1e-5, 1e-15);
      EXPECT_EQ(net.zb[c], 0.0);
    } else if (std::abs(net.za[c] - 0.001) < 1e-12) {  // C-D across x = 0: 20 um
      ++periodic;
      EXPECT_NEAR(net.normal_force[c], 10.0 * 2e-5, 1e-15);
      // the partner is the image the contact sees: a line of length 80 um
      EXPECT_NEAR(std::abs(net.xa[c] - net.xb[c]), 8e-5, 1e-15);
    } else {  // A-B: 10 um
      ++stacked;
      EXPECT_NEAR(net.normal_force[c], 10.0 * 1e-5, 1e-15);
    }
  }
  EXPECT_EQ(wall, 1);
  EXPECT_EQ(stacked, 1);
  EXPECT_EQ(periodic, 1);
}

TEST(SizeThirds, PercentilesAndThirdsByHeight) {
  EXPECT_DOUBLE_EQ(number_percentile({1, 2, 3, 4, 5}, 0.1), 1.4);
  EXPECT_DOUBLE_EQ(number_percentile({1, 2, 3, 4, 5}, 0.5), 3.0);
  EXPECT_DOUBLE_EQ(number_percentile({1, 2, 3, 4, 5}, 1.0), 5.0);
  // 10 spheres, given out of height order: the coarse ones low. Thirds of 4, 3, 3.
  const DemParticles s =
      spheres({9, 1, 8, 2, 7, 3, 6, 4, 5, 10},
              {1.1e-3, 3.9e-3, 1.2e-3, 3.7e-3, 1.3e-3, 3.5e-3, 2.1e-3, 3.3e-3, 2.2e-3, 1.0e-3});
  const SizeThirds t = size_thirds(s, 1.0e-3, 4.0e-3, 3);
  ASSERT_EQ(t.bin_edges.size(), 4u);
  EXPECT_EQ(t.third[0].count, 4u);
  EXPECT_EQ(t.third[1].count, 3u);
  EXPECT_EQ(t.third[2].count, 3u);
  EXPECT_NEAR(t.third[0].mean_d, (3.9e-3 + 3.7e-3 + 3.5e-3 + 3.3e-3) / 4, 1e-15);  // z = 1..4
  EXPECT_NEAR(t.third[1].mean_d, (2.2e-3 + 2.1e-3 + 1.3e-3) / 3, 1e-15);           // z = 5..7
  EXPECT_NEAR(t.third[2].mean_d, (1.2e-3 + 1.1e-3 + 1.0e-3) / 3, 1e-15);           // z = 8..10
  EXPECT_NEAR(t.third[1].d50, 2.1e-3, 1e-15);
  EXPECT_EQ(t.third[0].z_min, 1.0);
  EXPECT_EQ(t.third[0].z_max, 4.0);
  EXPECT_EQ(t.third[0].bin_count, (std::vector<std::size_t>{0, 0, 4}));  // [1,2) [2,3) [3,4] mm
  EXPECT_EQ(t.third[1].bin_count, (std::vector<std::size_t>{1, 2, 0}));
  EXPECT_EQ(t.third[2].bin_count, (std::vector<std::size_t>{3, 0, 0}));
}

TEST(BulkDensity, EqualsVoidageWeightedDensities) {
  GridSpec g;
  g.origin = {0.5, 0.5, -1.0};
  g.spacing = {1.0, 1.0, 1.0};
  g.extent = {0, 1, 0, 1, 0, 3};  // layers at z = -1, 0, 1, 2
  // layer z = 0: eps 0.5 and 0.3 (mean 0.4); z = 1: 0.9; z = 2: 1
  const std::vector<double> eps = {0.2, 0.2, 0.2, 0.2, 0.5, 0.3, 0.5, 0.3,
                                   0.9, 0.9, 0.9, 0.9, 1,   1,   1,   1};
  const BulkDensityProfile p = bulk_density_profile(eps, g, 1000.0, 2650.0, 1.5);
  ASSERT_EQ(p.z.size(), 2u);  // z = -1 (below the wall) and z = 2 (above z_top) left out
  EXPECT_DOUBLE_EQ(p.z[0], 0.0);
  EXPECT_NEAR(p.voidage[0], 0.4, 1e-15);
  EXPECT_NEAR(p.bulk_density[0], 0.4 * 1000 + 0.6 * 2650, 1e-9);  // 1990 kg/m^3
  EXPECT_NEAR(p.bulk_density[1], 0.9 * 1000 + 0.1 * 2650, 1e-9);
}
