// The spheres' kernel width rule (scene/kernel_width_rule.hpp, coupling.sphere_kernel_scale:
// auto): the drag law's terminal speed against closed forms, the extra-drag ratio R
// against the formula by hand, the widths the rule gives on the measured scenes
// (bench/TRADEOFF.md) and the loader's keys.
#include "scene/kernel_width_rule.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace {

using namespace sphdem;

const char* kSphere = R"(
name: sphere
domain: {size: [0.004, 0.004, 0.0058]}
fluid: {density: 1000, viscosity: 8.9e-4, spacing: 2.0e-4, smoothing_factor: 1.5}
species: [{name: glass, diameter: 1.0e-4, density: 2500}]
particles: [{type: single, species: glass, position: [0.002, 0.002, 0.0048]}]
drag: {law: stokes}
coupling: {pressure_coupling: variational, hydrostatic_split: true}
)";

const char* kGrain = R"(
name: grain
domain: {size: [0.05, 0.05, 0.15]}
fluid: {density: 1000, viscosity: 1.0e-3, spacing: 5.5555555555555556e-3, smoothing_factor: 1.5,
        sound_speed: 44}
species: [{name: sand, diameter: 2.8e-3, density: 2650}]
particles: [{type: single, species: sand, position: [0.025, 0.025, 0.14]}]
drag: {law: brown_lawler}
coupling: {pressure_coupling: variational, hydrostatic_split: true}
)";

}  // namespace

TEST(KernelWidthRule, TerminalSpeedOfTheDragLaws) {
  // Stokes: (rho_p - rho_f) g d^2 / (18 mu) exactly
  const double d = 1e-4, mu = 8.9e-4;
  EXPECT_NEAR(terminal_speed(drag::Stokes{}, d, 2500, 1000, mu, 9.81),
              1500 * 9.81 * d * d / (18 * mu), 1e-12);
  // Brown-Lawler, 2.8 mm sand: 0.3617 m/s (validation/theory.py's own bisection)
  EXPECT_NEAR(terminal_speed(drag::BrownLawler{}, 2.8e-3, 2650, 1000, 1e-3, 9.81), 0.36168, 1e-4);
}

TEST(KernelWidthRule, RatioIsTheFormula) {
  const Scene sc = load_scene_text(kSphere, "sphere.yaml");
  const double d = 1e-4, v = 1500 * 9.81 * d * d / (18 * 8.9e-4), V = M_PI * d * d * d / 6;
  const double h = 1.5 * 2e-4, c0 = sc.fluid.sound_speed;
  EXPECT_NEAR(extra_drag_ratio(sc), 1000 * c0 * v * V / (1500 * 9.81 * std::pow(h, 4)),
              1e-9 * extra_drag_ratio(sc));
}

// The measured scenes: the shallow sphere R = 0.14 -> h; 7 and 30 mm deep (c0 from the
// column) 0.19 and 0.33 -> 1.25 h; the grain at c0 = 44 m/s 2.34 -> 1.5 h; the drag at h.
TEST(KernelWidthRule, WidthsOfTheMeasuredScenes) {
  struct Case {
    std::string text;
    std::vector<std::string> sets;
    double scale;
  };
  const Case cases[] = {{kSphere, {}, 1.0},
                        {kSphere, {"domain.size=[0.004,0.004,0.0118]"}, 1.25},
                        {kSphere, {"domain.size=[0.004,0.004,0.0348]"}, 1.25},
                        {kGrain, {}, 1.5}};
  for (const Case& c : cases) {
    const Scene sc = load_scene_text(c.text, "scene.yaml", c.sets);
    EXPECT_EQ(sc.sphere_kernel_scale, c.scale) << sc.sphere_kernel_reason;
    EXPECT_EQ(sc.drag_kernel_scale, 1.0);
    EXPECT_NE(sc.sphere_kernel_reason.find("auto: variational"), std::string::npos);
  }
}

TEST(KernelWidthRule, InterpolatedCouplingKeepsH) {
  const Scene sc = load_scene_text(
      kGrain, "grain.yaml",
      {"coupling.pressure_coupling=interpolated", "coupling.hydrostatic_split=false"});
  EXPECT_EQ(sc.sphere_kernel_scale, 1.0);
  EXPECT_EQ(sc.drag_kernel_scale, 1.0);
}

TEST(KernelWidthRule, GivenNumbersAreKept) {
  const Scene sc = load_scene_text(kGrain, "grain.yaml", {"coupling.sphere_kernel_scale=2"});
  EXPECT_EQ(sc.sphere_kernel_scale, 2.0);
  EXPECT_EQ(sc.drag_kernel_scale, 2.0);  // a given width: the drag's follows it
  EXPECT_TRUE(sc.sphere_kernel_reason.empty());
  const Scene a = load_scene_text(kGrain, "grain.yaml", {"coupling.sphere_kernel_scale=auto"});
  EXPECT_EQ(a.sphere_kernel_scale, 1.5);
  try {
    load_scene_text(kGrain, "grain.yaml",
                    {"coupling.sphere_kernel_scale=1.25", "coupling.drag_kernel_scale=1.5"});
    ADD_FAILURE() << "a drag kernel wider than the spheres' was accepted";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("coupling.drag_kernel_scale"), std::string::npos)
        << e.what();
  }
}
