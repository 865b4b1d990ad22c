// contact.stiffness: auto (scene/contact_stiffness_rule.hpp): the softest spring whose
// overlaps stay under contact.max_overlap d. The impact rule is checked by dropping a
// sphere on the wall at a known speed (the overlap it reaches must be just under the
// limit: the rule is the softest such k, rounded up to two digits, so within 5 % of the
// limit); the terminal
// speed and the static load by their closed forms (the largest overlap of a sediment at
// rest, with its force chains, is measured on the default scene: bench/TRADEOFF.md).
#include "scene/contact_stiffness_rule.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "propagator/simulation.hpp"
#include "scene/scene.hpp"

using namespace sphdem;

namespace {

// A sphere released 1 um above the wall at 0.1 m/s, no gravity: it hits at that speed.
const char* kImpact = R"(
name: impact
domain: {size: [0.002, 0.002, 0.002]}
gravity: [0, 0, 0]
fluid: {enabled: false}
species: [{name: glass, diameter: 1.0e-4, density: 2500}]
particles: [{type: single, species: glass, position: [0.001, 0.001, 5.1e-5], velocity: [0, 0, -0.1]}]
startup: {relax_steps: 0}
time: {max_dt_sph: 1.0e-8}
)";

// Largest overlap / d of the sphere over its impact (sampled every 1e-8 s, t_c / 700 or less).
double impact_overlap(const Scene& sc) {
  Simulation sim(sc);
  const double r = 0.5e-4;
  double lowest = 1.0;
  while (sim.time() < 1e-5 + 3 * sim.contact_time()) {
    sim.step();
    lowest = std::min(lowest, sim.spheres().z[0]);
  }
  return (r - lowest) / (2 * r);
}

}  // namespace

TEST(ContactStiffnessRule, DropReachesJustUnderTheOverlapLimit) {
  for (const char* contact : {"contact={restitution: 1}", "contact={restitution: 0.5}"}) {
    for (double limit : {0.01, 0.002}) {
      const Scene sc = load_scene_text(kImpact, "impact.yaml",
                                       {contact, "contact.max_overlap=" + std::to_string(limit)});
      ASSERT_FALSE(sc.contact.stiffness_reason.empty());
      const double overlap = impact_overlap(sc);
      std::printf("%s, max_overlap %.3g: k = %.4g N/m, overlap %.4g d\n", contact, limit,
                  sc.contact.normal.k, overlap);
      EXPECT_LE(overlap, limit);
      EXPECT_GE(overlap, 0.9 * limit);  // the softest such spring, not merely a stiff one
    }
  }
}

// In a fluid: the impact speed is the drag law's terminal speed (Stokes: the closed form),
// the static load the buoyant weight of the solid per floor area on d^2.
TEST(ContactStiffnessRule, TerminalSpeedAndSedimentWeight) {
  const char* kSuspension = R"(
name: suspension
domain: {size: [0.002, 0.002, 0.004]}
fluid: {spacing: 2.0e-4}
species: [{name: glass, diameter: 1.0e-4, density: 2500}]
particles: [{type: lattice, species: glass, voidage: 0.9, min: [0, 0, 0.0005], max: [0.002, 0.002, 0.0035]}]
drag: {law: stokes}
contact: {damping: 0}
)";
  const Scene sc = load_scene_text(kSuspension, "suspension.yaml");
  const StiffnessChoice c = choose_contact_stiffness(sc);
  const double d = 1e-4, m = 2500 * M_PI * d * d * d / 6, g = 9.81, f = 0.01;
  const double v = 1500 * g * d * d / (18 * 8.9e-4);
  EXPECT_NEAR(c.impact_speed, v, 1e-9 * v);
  const double k_impact = m * std::pow(v / (f * d), 2);
  const double p = 1500 * g * 0.002 * 0.002 * 0.003 * 0.1 / (0.002 * 0.002);
  const double k_static = 4 * p * d / f;  // force chains: 4 times the mean load
  const double k = std::max(k_impact, k_static);
  EXPECT_GE(c.k, k);
  EXPECT_LT(c.k, 1.1 * k);
  EXPECT_EQ(sc.contact.normal.k, c.k);
  EXPECT_NEAR(c.impact_overlap, f * std::sqrt(k_impact / c.k), 1e-12);
  EXPECT_NEAR(c.static_overlap, f * k_static / c.k, 1e-12);
  // a stiffness given in the file is kept
  const Scene given = load_scene_text(kSuspension, "suspension.yaml", {"contact.stiffness=100"});
  EXPECT_EQ(given.contact.normal.k, 100.0);
  EXPECT_TRUE(given.contact.stiffness_reason.empty());
}
