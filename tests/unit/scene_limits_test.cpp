// The model's limits (scene/scene_limits.hpp): each breach names its key and the range;
// the shipped cases are within all of them.
#include "scene/scene_limits.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "scene/scene.hpp"
#include "scene/sound_speed_rule.hpp"

using namespace sphdem;

namespace {
std::vector<LimitBreach> breaches_of(std::vector<std::string> sets) {
  return scene_limit_breaches(load_scene(SPHDEM_CASES_DIR "/single_particle.yaml", sets));
}
bool names_key(const std::vector<LimitBreach>& b, const std::string& key) {
  for (const LimitBreach& x : b)
    if (x.key == key) return true;
  return false;
}
}  // namespace

TEST(SceneLimits, ShippedCasesAreWithinTheLimits) {
  for (const auto& e : std::filesystem::directory_iterator(SPHDEM_CASES_DIR)) {
    if (e.path().extension() != ".yaml") continue;
    const Scene sc = load_scene(e.path().string());
    EXPECT_TRUE(scene_limit_breaches(sc).empty())
        << describe_breaches(sc, scene_limit_breaches(sc));
  }
}

TEST(SceneLimits, SpheresLargeAgainstTheirKernelAreRefused) {
  // h = 300 um: V W(0) = 0.219 (d/h)^3 reaches 0.025 at d = 145.5 um
  EXPECT_FALSE(names_key(breaches_of({"species.0.diameter=1.4e-4"}), "fluid.spacing"));
  const auto b = breaches_of({"species.0.diameter=1.5e-4"});
  ASSERT_TRUE(names_key(b, "fluid.spacing"));
  EXPECT_NE(b[0].message.find("fills 0.0273 of its drag kernel"), std::string::npos)
      << b[0].message;
}

TEST(SceneLimits, StokesLawPastItsReynoldsNumberIsRefused) {
  // 100 um glass: Re_t = 1.03 (the thesis case); steel (7800): Re_t = 4.4
  EXPECT_TRUE(breaches_of({}).empty());
  EXPECT_TRUE(names_key(breaches_of({"species.0.density=7800"}), "drag.law"));
  EXPECT_TRUE(breaches_of({"species.0.density=7800", "drag.law=di_felice"}).empty());
}

TEST(SceneLimits, SpheresLighterThanTheFluidAreRefused) {
  EXPECT_TRUE(names_key(breaches_of({"species.0.density=950"}), "species.0.density"));
  EXPECT_TRUE(breaches_of({"species.0.density=1050"}).empty());
}

TEST(SceneLimits, ASoundSpeedPastTheWeaklyCompressibleLimitIsRefused) {
  // 6 mm of water: g H / c0^2 = 1 % at c0 = 2.43 m/s
  EXPECT_TRUE(names_key(breaches_of({"fluid.sound_speed=2.0"}), "fluid.sound_speed"));
  EXPECT_TRUE(breaches_of({"fluid.sound_speed=2.6"}).empty());
}

TEST(SceneLimits, ASoundSpeedThatBuoysANearlyNeutralSphereIsRefused) {
  // rho_p = 1050: the compression's share of the buoyant weight is 20 g H / c0^2, 2 % at
  // c0 = 7.67 m/s (the 2500 kg/m^3 glass above passes at 2.6 m/s)
  EXPECT_TRUE(names_key(breaches_of({"species.0.density=1050", "fluid.sound_speed=7.5"}),
                        "fluid.sound_speed"));
  EXPECT_TRUE(breaches_of({"species.0.density=1050", "fluid.sound_speed=7.8"}).empty());
  // the automatic c0 keeps it at 1 %
  const Scene sc = load_scene(SPHDEM_CASES_DIR "/single_particle.yaml",
                              {"species.0.density=1050", "fluid.sound_speed=0"});
  const SoundSpeedReport c = sound_speed_report(sc);
  EXPECT_NEAR(c.buoyancy, kBuoyancyErrorTarget, 1e-12);
  EXPECT_NEAR(c.c0, std::sqrt(9.81 * sc.fill_height() * 20 / 0.01), 1e-9 * c.c0);
}

TEST(SceneLimits, ASpringTooSoftForTheImpactIsRefused) {
  const auto b = breaches_of({"contact.stiffness=1e-4"});
  ASSERT_TRUE(names_key(b, "contact.stiffness"));
  EXPECT_NE(b[0].message.find("at impact"), std::string::npos) << b[0].message;
  EXPECT_TRUE(breaches_of({"contact.stiffness=10"}).empty());
  // every breach at once, each naming its key
  const auto all = breaches_of({"contact.stiffness=1e-4", "fluid.sound_speed=2.0"});
  EXPECT_EQ(all.size(), 2u);
  EXPECT_THROW(refuse_scene_past_limits(
                   load_scene(SPHDEM_CASES_DIR "/single_particle.yaml", {"fluid.sound_speed=2"})),
               SceneError);
}

namespace {
std::vector<LimitBreach> case_breaches(const std::string& name, std::vector<std::string> sets) {
  return scene_limit_breaches(load_scene(std::string(SPHDEM_CASES_DIR "/") + name, sets));
}
}  // namespace

TEST(SceneLimits, ALawWithoutAVoidageFunctionIsRefusedForASuspension) {
  // a random group at eps 0.9: Stokes' and Coulson-Richardson's drag do not rise with it
  for (const char* law : {"stokes", "coulson_richardson"}) {
    const std::string set = std::string("drag.law=") + law;
    const auto b = case_breaches("suspension_monodisperse.yaml", {set});
    ASSERT_TRUE(names_key(b, "drag.law")) << law;
    EXPECT_NE(b[0].message.find("particles.0 sits at voidage"), std::string::npos) << b[0].message;
    // a group of a few lone spheres keeps them
    EXPECT_FALSE(
        names_key(case_breaches("suspension_monodisperse.yaml", {set, "particles.0.voidage=0.995"}),
                  "drag.law"))
        << law;
  }
  EXPECT_FALSE(names_key(case_breaches("suspension_monodisperse.yaml", {}), "drag.law"));
}

TEST(SceneLimits, NoDragIsRefusedForSpheresFreeToMove) {
  const auto b = case_breaches("suspension_monodisperse.yaml", {"drag.law=none"});
  ASSERT_TRUE(names_key(b, "drag.law"));
  EXPECT_NE(b[0].message.find("particles.0 is free to move"), std::string::npos) << b[0].message;
  for (const char* held : {"particles.0.rigid=true", "particles.0.fixed=true"})
    EXPECT_FALSE(names_key(case_breaches("suspension_monodisperse.yaml", {"drag.law=none", held}),
                           "drag.law"))
        << held;
}

TEST(SceneLimits, DoubleSmoothingIsRefusedOverSpheresThatFormABed) {
  const std::string dbl = "coupling.voidage_smoothing=double";
  EXPECT_TRUE(
      names_key(case_breaches("suspension_bidisperse.yaml", {dbl}), "coupling.voidage_smoothing"));
  // the thesis's constant-porosity blocks move rigidly: no bed forms
  EXPECT_FALSE(names_key(case_breaches("block_bidisperse_150_100.yaml", {dbl}),
                         "coupling.voidage_smoothing"));
  EXPECT_FALSE(
      names_key(case_breaches("suspension_bidisperse.yaml", {}), "coupling.voidage_smoothing"));
}
