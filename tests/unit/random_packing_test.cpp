// Random suspensions (particle group `type: random`, random_packing.hpp): no overlap
// (across the periodic faces too, by brute force over all pairs), the achieved voidage,
// homogeneity, seeded reproducibility, mixture fractions; below voidage kRearrangeBelow
// the same by collective rearrangement, and its error near random close packing.
//
// Homogeneity bands: the centres of the spheres of one size are uniform over the
// region where they may lie, so the count in a part holding a share p of it is, for
// independent placement, binomial with variance N p (1 - p). RSA's exclusion makes the
// counts less variable than that (sub-Poissonian), so +-4 binomial standard deviations
// is a conservative band (P(exceeded) < 1e-4 per part even for independent points).
#include "scene/random_packing.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "scene/initial_state.hpp"
#include "scene/scene.hpp"

using namespace sphdem;

namespace {

constexpr double kPi = 3.14159265358979323846;

// 4 x 4 mm periodic column; the group text goes under `particles:`.
std::string scene_text(const std::string& species, const std::string& groups, double lz = 0.006) {
  return "domain: {size: [0.004, 0.004, " + std::to_string(lz) + "]}\nspecies:\n" + species +
         "particles:\n" + groups;
}
const std::string kGlass = "  - {name: glass, diameter: 1.0e-4, density: 2500}\n";

std::string random_group(double voidage, long seed, const std::string& zmin = "0",
                         const std::string& zmax = "0.0048", const std::string& species = "glass") {
  return "  - {type: random, species: " + species + ", min: [0, 0, " + zmin +
         "], max: [0.004, 0.004, " + zmax + "], voidage: " + std::to_string(voidage) +
         ", seed: " + std::to_string(seed) + "}\n";
}

RandomPacking pack(const Scene& sc, std::size_t group = 0) {
  return random_packing(sc, group, DemParticles{});
}

// Largest overlap (r_i + r_j - distance) over all pairs, minimum image in x and y.
double max_overlap(const std::vector<double>& x, const std::vector<double>& y,
                   const std::vector<double>& z, const std::vector<double>& r, double Lx,
                   double Ly) {
  double worst = -1.0;
  const std::size_t n = x.size();
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j) {
      double dx = x[i] - x[j], dy = y[i] - y[j];
      const double dz = z[i] - z[j];
      dx -= Lx * std::round(dx / Lx);
      dy -= Ly * std::round(dy / Ly);
      worst = std::max(worst, r[i] + r[j] - std::sqrt(dx * dx + dy * dy + dz * dz));
    }
  return worst;
}

bool bit_identical(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}

double solid_volume(const RandomPacking& P) {
  double v = 0;
  for (double r : P.radius) v += 4.0 / 3.0 * kPi * r * r * r;
  return v;
}

}  // namespace

TEST(RandomPacking, NoOverlapAcrossThePeriodicFacesAndInsideTheRegion) {
  // Dense for RSA (solid fraction 0.3) so that many pairs nearly touch.
  const Scene sc =
      load_scene_text(scene_text(kGlass, random_group(0.7, 11, "0", "0.0012")), "rsa.yaml");
  const RandomPacking P = pack(sc);
  ASSERT_GT(P.x.size(), 4000u);
  EXPECT_LE(max_overlap(P.x, P.y, P.z, P.radius, 0.004, 0.004), 1e-12 * 1e-4);
  std::size_t across = 0;  // spheres cut by a periodic face: the wrap is exercised
  for (std::size_t i = 0; i < P.x.size(); ++i) {
    const double r = P.radius[i];
    EXPECT_GE(P.x[i], 0.0);
    EXPECT_LT(P.x[i], 0.004);
    EXPECT_GE(P.y[i], 0.0);
    EXPECT_LT(P.y[i], 0.004);
    EXPECT_GE(P.z[i], r);  // inside the region in z, so above the wall
    EXPECT_LE(P.z[i], 0.0012 - r);
    across += P.x[i] < r || P.x[i] > 0.004 - r || P.y[i] < r || P.y[i] > 0.004 - r;
  }
  EXPECT_GT(across, 100u);
}

TEST(RandomPacking, NoOverlapWithEarlierGroupsAndInsideAPartialRegion) {
  // A lattice block, a single sphere, then a polydisperse random group over them, in a
  // region that does not span the periodic width (so each sphere lies inside it).
  const std::string species =
      kGlass +
      "  - {name: sand, density: 2650, size_distribution: {law: uniform, min: 6.0e-5, max: "
      "1.6e-4}}\n";
  const std::string groups =
      "  - {type: lattice, species: glass, min: [0, 0, 0.001], max: [0.004, 0.004, 0.0015], "
      "voidage: 0.8}\n"
      "  - {type: single, species: glass, position: [0.0034, 0.002, 0.0018]}\n"
      "  - {type: random, species: sand, min: [0.0005, 0, 0.0005], max: [0.0035, 0.004, 0.002], "
      "voidage: 0.75, "
      "seed: 5}\n";
  const Scene sc = load_scene_text(scene_text(species, groups), "rsa.yaml");
  FluidParticles f;
  DemParticles s;
  place_particles(sc, f, s);
  ASSERT_GT(s.size(), 5000u);
  EXPECT_LE(max_overlap(s.x, s.y, s.z, s.radius, 0.004, 0.004), 1e-12 * 1e-4);
  std::size_t n_random = 0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (s.species[i] != 1) continue;
    ++n_random;
    const double r = s.radius[i];
    EXPECT_GE(s.x[i], 0.0005 + r);
    EXPECT_LE(s.x[i], 0.0035 - r);
    EXPECT_GE(s.z[i], 0.0005 + r);
    EXPECT_LE(s.z[i], 0.002 - r);
    EXPECT_DOUBLE_EQ(s.mass[i], 2650 * kPi * std::pow(2 * r, 3) / 6.0);
  }
  EXPECT_GT(n_random, 1000u);
}

TEST(RandomPacking, AchievedVoidageIsTheTargetUpToHalfASphere) {
  // Equal spheres: N = round((1 - eps) V / V_p), so |eps_N - eps| <= V_p / (2 V).
  const double V = 0.004 * 0.004 * 0.0048, Vp = kPi * 1e-12 / 6.0;
  for (double eps : {0.9, 0.85, 0.77}) {
    const RandomPacking P =
        pack(load_scene_text(scene_text(kGlass, random_group(eps, 1)), "rsa.yaml"));
    EXPECT_EQ(P.x.size(), static_cast<std::size_t>(std::lround((1 - eps) * V / Vp))) << eps;
    EXPECT_LE(std::abs(P.voidage - eps), 0.5 * Vp / V) << eps;
    EXPECT_NEAR(P.voidage, 1 - solid_volume(P) / V, 1e-12);
  }
  // A size law: within half the largest sphere's volume.
  const std::string psd =
      "  - {name: sand, density: 2650, size_distribution: {law: lognormal, median: 1.0e-4, "
      "sigma_ln: 0.25, "
      "min: 5.0e-5, max: 2.0e-4}}\n";
  const RandomPacking P = pack(
      load_scene_text(scene_text(psd, random_group(0.88, 2, "0", "0.0048", "sand")), "r.yaml"));
  EXPECT_LE(std::abs(P.voidage - 0.88), 0.5 * kPi * 8e-12 / 6.0 / V);
}

TEST(RandomPacking, HomogeneousInSlabsAndOctants) {
  // The thesis suspension: 100 um spheres at eps = 0.9 from z = 0 to 4.8 mm (14668 spheres).
  const RandomPacking P =
      pack(load_scene_text(scene_text(kGlass, random_group(0.9, 42)), "rsa.yaml"));
  const double N = static_cast<double>(P.x.size()), r = 0.5e-4;
  const double z0 = r, z1 = 0.0048 - r;  // where centres may lie
  // 12 horizontal slabs (0.4 mm, 4 diameters each) of the centre range.
  const int slabs = 12;
  std::vector<double> n(slabs, 0);
  for (double z : P.z) n[std::min(slabs - 1, static_cast<int>((z - z0) / (z1 - z0) * slabs))] += 1;
  const double p = 1.0 / slabs, band = 4 * std::sqrt(N * p * (1 - p));
  for (int k = 0; k < slabs; ++k) EXPECT_NEAR(n[k], N * p, band) << "slab " << k;
  // Octants: halves in x, y and of the centre range in z.
  std::vector<double> o(8, 0);
  for (std::size_t i = 0; i < P.x.size(); ++i)
    o[(P.x[i] >= 0.002) + 2 * (P.y[i] >= 0.002) + 4 * (P.z[i] >= 0.5 * (z0 + z1))] += 1;
  const double band8 = 4 * std::sqrt(N / 8 * (1 - 1.0 / 8));
  for (int k = 0; k < 8; ++k) EXPECT_NEAR(o[k], N / 8, band8) << "octant " << k;
  // In solid fraction: every slab within 4 sigma of 1 - eps = 0.1 (the same test, scaled).
  const double Vp = kPi * 1e-12 / 6.0, v_slab = 0.004 * 0.004 * (z1 - z0) / slabs;
  const double phi = N * Vp / (0.004 * 0.004 * (z1 - z0));  // centre-range solid fraction
  for (int k = 0; k < slabs; ++k) EXPECT_NEAR(n[k] * Vp / v_slab, phi, band * Vp / v_slab);
}

TEST(RandomPacking, MixtureFractionsAndPerSpeciesHomogeneity) {
  // Two species (the thesis' two densities and sizes) by number 30 / 70.
  const std::string species =
      "  - {name: big, diameter: 1.2e-4, density: 2450}\n"
      "  - {name: small, diameter: 1.0e-4, density: 1500}\n";
  const std::string group =
      "  - {type: random, species: [big, small], fractions: [0.3, 0.7], min: [0, 0, 0], "
      "max: [0.004, 0.004, 0.0048], voidage: 0.87, seed: 9}\n";
  const Scene sc = load_scene_text(scene_text(species, group), "rsa.yaml");
  const RandomPacking P = pack(sc);
  std::vector<double> count(2, 0);
  for (auto s : P.species) count[s] += 1;
  const double N = count[0] + count[1];
  EXPECT_LE(std::abs(count[0] - 0.3 * N), 1.0);  // dealt exactly
  EXPECT_LE(std::abs(count[1] - 0.7 * N), 1.0);
  // Largest first: the big spheres come first in insertion order.
  EXPECT_EQ(P.species.front(), 0);
  EXPECT_EQ(P.species.back(), 1);
  EXPECT_TRUE(std::is_sorted(P.radius.rbegin(), P.radius.rend()));
  // Each species homogeneous over its own centre range (6 slabs).
  for (int s = 0; s < 2; ++s) {
    const double r = s == 0 ? 0.6e-4 : 0.5e-4, z0 = r, z1 = 0.0048 - r;
    std::vector<double> n(6, 0);
    for (std::size_t i = 0; i < P.z.size(); ++i)
      if (P.species[i] == s) n[std::min(5, static_cast<int>((P.z[i] - z0) / (z1 - z0) * 6))] += 1;
    for (int k = 0; k < 6; ++k)
      EXPECT_NEAR(n[k], count[s] / 6, 4 * std::sqrt(count[s] / 6 * (5.0 / 6)))
          << "species " << s << " slab " << k;
  }
  EXPECT_LE(max_overlap(P.x, P.y, P.z, P.radius, 0.004, 0.004), 1e-16);
}

TEST(RandomPacking, SameSeedIsBitIdenticalOtherSeedDiffers) {
  const std::string psd =
      "  - {name: sand, density: 2650, size_distribution: {law: normal, mean: 1.0e-4, std: 2.0e-5, "
      "min: 6.0e-5, "
      "max: 1.4e-4}}\n";
  auto at = [&](long seed) {
    return pack(load_scene_text(scene_text(psd, random_group(0.9, seed, "0", "0.002", "sand")),
                                "rsa.yaml"));
  };
  const RandomPacking a = at(123), b = at(123), c = at(124);
  EXPECT_TRUE(bit_identical(a.x, b.x));
  EXPECT_TRUE(bit_identical(a.y, b.y));
  EXPECT_TRUE(bit_identical(a.z, b.z));
  EXPECT_TRUE(bit_identical(a.radius, b.radius));
  EXPECT_EQ(a.attempts, b.attempts);
  ASSERT_GT(c.x.size(), 100u);
  std::size_t same = 0;
  for (std::size_t i = 0; i < std::min(a.x.size(), c.x.size()); ++i) same += a.x[i] == c.x[i];
  EXPECT_EQ(same, 0u);
  EXPECT_FALSE(bit_identical(a.radius, c.radius));
}

TEST(RandomPacking, DenseByCollectiveRearrangementWithoutOverlapEvenlyAndSeeded) {
  // eps = 0.5 (solid fraction 0.5 > RSA's saturation 0.384), 6112 spheres in a 0.4 mm
  // layer: placed by collective rearrangement, none overlapping (by brute force, across
  // the periodic faces too), inside the region, the count of the target voidage.
  const Scene sc =
      load_scene_text(scene_text(kGlass, random_group(0.5, 1, "0", "0.0004")), "dense.yaml");
  const RandomPacking P = pack(sc);
  const double V = 0.004 * 0.004 * 0.0004, Vp = kPi * 1e-12 / 6.0, r = 0.5e-4;
  ASSERT_EQ(P.x.size(), static_cast<std::size_t>(std::lround(0.5 * V / Vp)));
  EXPECT_GT(P.sweeps, 0u);
  EXPECT_LE(std::abs(P.voidage - 0.5), 0.5 * Vp / V);
  EXPECT_LE(max_overlap(P.x, P.y, P.z, P.radius, 0.004, 0.004), 1e-12 * 1e-4);
  for (std::size_t i = 0; i < P.x.size(); ++i) {
    EXPECT_GE(P.x[i], 0.0);
    EXPECT_LT(P.x[i], 0.004);
    EXPECT_GE(P.z[i], r * (1 - 1e-12));
    EXPECT_LE(P.z[i], (0.0004 - r) * (1 + 1e-12));
  }
  // Even over the periodic axes: counts in the quarters of x and of y within 4 binomial
  // standard deviations (a packing is sub-Poissonian, so this band is conservative).
  const double N = static_cast<double>(P.x.size()), band = 4.0 * std::sqrt(N * 0.25 * 0.75);
  for (const auto* c : {&P.x, &P.y}) {
    std::vector<double> n(4, 0);
    for (double v : *c) n[std::min(3, static_cast<int>(v / 0.001))] += 1;
    for (double k : n) EXPECT_LE(std::abs(k - 0.25 * N), band) << k;
  }
  // The same seed gives the same packing, bit for bit; another seed another one.
  const RandomPacking again = pack(sc);
  EXPECT_TRUE(bit_identical(P.x, again.x) && bit_identical(P.z, again.z));
  const RandomPacking other =
      pack(load_scene_text(scene_text(kGlass, random_group(0.5, 2, "0", "0.0004")), "d.yaml"));
  EXPECT_FALSE(bit_identical(P.x, other.x));
}

TEST(RandomPacking, DenseGroupAvoidsEarlierGroups) {
  // A dense random group (eps 0.55, below RSA's reach) in a region that does not span the
  // periodic width, over a lattice bed whose top layer reaches into it and around a single
  // sphere inside it: no overlap, each of its spheres inside the region.
  const std::string groups =
      "  - {type: lattice, species: glass, min: [0, 0, 0], max: [0.004, 0.004, 0.00052], "
      "voidage: 0.6}\n"
      "  - {type: single, species: glass, position: [0.002, 0.002, 0.0009]}\n"
      "  - {type: random, species: glass, min: [0.0005, 0, 0.0005], max: [0.0035, 0.004, "
      "0.0013], voidage: 0.55, seed: 3}\n";
  const Scene sc = load_scene_text(scene_text(kGlass, groups), "dense.yaml");
  FluidParticles f;
  DemParticles s;
  place_particles(sc, f, s);
  EXPECT_LE(max_overlap(s.x, s.y, s.z, s.radius, 0.004, 0.004), 1e-12 * 1e-4);
  const std::size_t earlier = static_cast<std::size_t>(
      std::count_if(s.z.begin(), s.z.end(), [](double z) { return z < 0.00052; }) + 1);
  ASSERT_GT(s.size(), earlier + 3000);
  const double r = 0.5e-4;
  for (std::size_t i = earlier; i < s.size(); ++i) {
    EXPECT_GE(s.x[i], (0.0005 + r) * (1 - 1e-12));
    EXPECT_LE(s.x[i], (0.0035 - r) * (1 + 1e-12));
    EXPECT_GE(s.z[i], (0.0005 + r) * (1 - 1e-12));
    EXPECT_LE(s.z[i], (0.0013 - r) * (1 + 1e-12));
  }
}

TEST(RandomPacking, StopsShortOfRandomClosePackingWithAClearError) {
  // Equal spheres at eps = 0.37 (solid fraction 0.63, near random close packing).
  const Scene sc = load_scene_text(
      "domain: {size: [0.001, 0.001, 0.001]}\nfluid: {enabled: false}\nspecies:\n" + kGlass +
          "particles:\n  - {type: random, species: glass, voidage: 0.37, seed: 1}\n",
      "jam.yaml");
  try {
    pack(sc);
    FAIL() << "eps = 0.37 was reached";
  } catch (const SceneError& e) {
    const std::string m = e.what();
    for (const char* part : {"jam.yaml", "'particles.0.voidage'", "collective rearrangement",
                             "overlapping", "0.58", "raise the voidage"})
      EXPECT_NE(m.find(part), std::string::npos) << part << " missing in: " << m;
  }
}

TEST(RandomPacking, RegionErrors) {
  // Thinner than a sphere in z.
  const Scene thin =
      load_scene_text(scene_text(kGlass, random_group(0.9, 1, "0.001", "0.00105")), "r.yaml");
  try {
    pack(thin);
    FAIL();
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("'particles.0.max'"), std::string::npos) << e.what();
  }
  // Less than half a sphere of solid at this voidage.
  const std::string tiny =
      "  - {type: random, species: glass, min: [0, 0, 0], max: [0.0001, 0.0001, 0.0001], voidage: "
      "0.9}\n";
  try {
    pack(load_scene_text(scene_text(kGlass, tiny), "r.yaml"));
    FAIL();
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("'particles.0.voidage'"), std::string::npos) << e.what();
  }
}
