// Bidisperse voidage by double smoothing (thesis 3.8-3.10) through Simulation's start:
// a big sphere's solid fraction on the SPH particles is its volume times the
// convolution of its own kernel with the fluid kernel; the solid volume is kept; a mixed
// block has its lattice voidage inside with either smoothing.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>

#include "propagator/simulation.hpp"
#include "scene/initial_state.hpp"
#include "scene/scene.hpp"
#include "sph/kernel.hpp"

using namespace sphdem;

namespace {

const char* kOneBigSphere = R"(
name: one_big_sphere
domain: {size: [0.004, 0.004, 0.006]}
fluid: {spacing: 2.0e-4}
species:
  - {name: big, diameter: 2.0e-4, density: 2500}
  - {name: small, diameter: 1.0e-4, density: 2500}
particles: [{type: single, species: big, position: [0.002, 0.002, 0.003]}]
startup: {relax_steps: 0}
)";

// (W(., h1) * W(., h2))(r): the 3-D convolution of two Wendland kernels, by quadrature in
// spherical coordinates about the first kernel's centre (midpoint rule, 2000 x 400).
double kernel_convolution(double r, double h1, double h2) {
  const int nr = 2000, nm = 400;
  const double R = kernel::kSupport * h1, dr = R / nr, dm = 2.0 / nm;
  double sum = 0;
  for (int i = 0; i < nr; ++i) {
    const double rho = (i + 0.5) * dr;
    double inner = 0;
    for (int k = 0; k < nm; ++k) {
      const double mu = -1.0 + (k + 0.5) * dm;
      inner += kernel::w(rho * rho + r * r - 2.0 * rho * r * mu, h2) * dm;
    }
    sum += 2.0 * M_PI * rho * rho * kernel::w(rho * rho, h1) * inner * dr;
  }
  return sum;
}

struct Profile {
  double deficit = 0;  // sum_a V_a (1 - eps_a) / V_sphere
  double peak = 0;     // max_a (1 - eps_a)
  double worst = 0;    // max_a |(1 - eps_a) - V C(r_a)| / (V C(0))
};

Profile profile(const Simulation& sim, double h_big) {
  const FluidParticles& f = sim.fluid();
  const DemParticles& s = sim.spheres();
  const double V = s.volume(0), hs = f.h[0];
  const double c0 = kernel_convolution(0.0, hs, h_big);
  // The convolution by distance, each distance once (the lattice has few about the
  // sphere); it is exactly 0 past the two supports.
  std::map<long long, double> convolution_at;
  const auto convolution = [&](double r) {
    if (r >= kernel::kSupport * (hs + h_big)) return 0.0;
    const long long key = std::llround(r * 1e9);
    const auto it = convolution_at.find(key);
    if (it != convolution_at.end()) return it->second;
    return convolution_at[key] = kernel_convolution(r, hs, h_big);
  };
  Profile p;
  for (std::size_t a = 0; a < f.n_owned; ++a) {
    const double solid = 1.0 - f.eps[a];
    p.deficit += f.mass[a] / f.rho[a] * solid / V;
    p.peak = std::max(p.peak, solid);
    if (h_big > 0) {
      EXPECT_DOUBLE_EQ(f.h[a], hs);  // one h: the convolution is tabulated at it
      const double r = std::hypot(f.x[a] - s.x[0], f.y[a] - s.y[0], f.z[a] - s.z[0]);
      p.worst = std::max(p.worst, std::abs(solid - V * convolution(r)) / (V * c0));
    }
  }
  return p;
}

}  // namespace

// One 200 um sphere at dx = 200 um (h/d_big = 1, the resolution the small spheres set).
// Single smoothing puts V W(0, h_s) = 0.065 of solid on the nearest particle; double
// smoothing spreads it over V (W_hs * W_hb)(r), a wider and lower bump, with the same
// integral. The SPH sum approximates the convolution integral on the lattice (the first
// smoothing is evaluated exactly, the second is a Shepard sum at h = 1.5 dx): measured
// 6e-4 of the peak; the deficit integrates to V within the lattice's partition-of-unity
// error (1.4e-3 for either smoothing).
TEST(DoubleSmoothing, BigSphereIsTheConvolutionOfTwoKernels) {
  // single smoothing at the fluid's own h (the width rule would widen it for this sphere)
  const Simulation single(
      load_scene_text(kOneBigSphere, "one_big_sphere.yaml", {"coupling.sphere_kernel_scale=1"}));
  const Simulation twice(
      load_scene_text(kOneBigSphere, "one_big_sphere.yaml",
                      {"coupling.voidage_smoothing=double", "coupling.big_species=[big]",
                       "coupling.big_h_over_d=1.5"}));
  const double h_big = 1.5 * 2.0e-4;
  const Profile p1 = profile(single, 0.0), p2 = profile(twice, h_big);
  const double V = single.spheres().volume(0), hs = single.fluid().h[0];
  std::printf(
      "single: peak %.5f (V W(0,h) = %.5f), deficit/V %.6f; double: peak %.5f (V C(0) = %.5f), "
      "deficit/V %.6f, worst |solid - V C(r)| %.4f of V C(0)\n",
      p1.peak, V * kernel::w(0.0, hs), p1.deficit, p2.peak, V * kernel_convolution(0.0, hs, h_big),
      p2.deficit, p2.worst);
  EXPECT_NEAR(p1.deficit, 1.0, 2e-3);
  EXPECT_NEAR(p2.deficit, 1.0, 2e-3);
  EXPECT_LT(p2.peak,
            0.5 * p1.peak);  // the point of the method: no near-zero voidage next to a big sphere
  EXPECT_LT(p2.worst, 0.005);
}

// A bidisperse constant-porosity block (200 and 100 um, half each by number, eps 0.9):
// inside, the kernel voidage is the lattice voidage with either smoothing.
TEST(DoubleSmoothing, MixedBlockHasItsLatticeVoidageInside) {
  const std::string block = R"(
name: mixed_block
domain: {size: [0.004, 0.004, 0.006]}
fluid: {spacing: 2.0e-4}
species:
  - {name: big, diameter: 2.0e-4, density: 2500}
  - {name: small, diameter: 1.0e-4, density: 2500}
particles:
  - {type: lattice, species: [big, small], fractions: [0.5, 0.5], seed: 3, voidage: 0.9,
     min: [0, 0, 0.0015], max: [0.004, 0.004, 0.0045], rigid: true}
startup: {relax_steps: 0}
)";
  for (const char* mode : {"single", "double"}) {
    const Scene sc = load_scene_text(block, "mixed_block.yaml",
                                     {std::string("coupling.voidage_smoothing=") + mode});
    const double eps_lattice = block_lattice(sc, sc.particles[0]).voidage;
    const Simulation sim(sc);
    const DemParticles& s = sim.spheres();
    // species dealt by quota (exact to one sphere) and shuffled by the seed
    const auto n_big = std::count(s.species.begin(), s.species.begin() + s.n_owned, 0);
    EXPECT_LE(std::abs(2 * n_big - static_cast<long>(s.n_owned)), 1);
    const Simulation again(sc);
    EXPECT_TRUE(std::equal(s.species.begin(), s.species.begin() + s.n_owned,
                           again.spheres().species.begin()));
    const FluidParticles& f = sim.fluid();
    double sum = 0, lo = 1, hi = 0;
    int n = 0;
    for (std::size_t a = 0; a < f.n_owned; ++a) {
      if (f.z[a] < 0.0022 || f.z[a] > 0.0038)
        continue;  // 0.7 mm (> one support) inside the block faces
      sum += f.eps[a];
      lo = std::min(lo, f.eps[a]);
      hi = std::max(hi, f.eps[a]);
      ++n;
    }
    std::printf(
        "%s smoothing: lattice eps %.4f, kernel eps inside mean %.4f, range [%.4f, %.4f] over %d "
        "particles\n",
        mode, eps_lattice, sum / n, lo, hi, n);
    EXPECT_NEAR(sum / n, eps_lattice, 0.003);
  }
}
