// Fidelity presets (scene/fidelity.hpp): a preset sets the keys a scene leaves unset; a
// key the scene sets wins; the resolution rounds to whole layers or is dropped with a note.
#include "scene/fidelity.hpp"

#include <gtest/gtest.h>

#include <string>

#include "scene/scene.hpp"
#include "scene/sound_speed_rule.hpp"

using namespace sphdem;

namespace {
// A suspension of 100 um glass at voidage 0.9 in a 2 x 2 x 3 mm water column, no key but
// the physics set (the default scene of sessions 14-15, before it took the fast preset).
const char* const kSuspension = R"(
name: sedimentation
domain: {size: [0.002, 0.002, 0.003]}
fluid: {density: 1000, viscosity: 8.9e-4, spacing: 2.0e-4}
species: [{name: glass, diameter: 1.0e-4, density: 2500}]
particles:
  - {type: random, species: glass, min: [0, 0, 0], max: [0.002, 0.002, 0.002], voidage: 0.9, seed: 1}
drag: {law: di_felice}
time: {end: 0.5}
)";
Scene sedimentation(std::vector<std::string> sets) {
  return load_scene_text(kSuspension, "sedimentation.yaml", sets);
}
}  // namespace

TEST(Fidelity, BalancedIsTheDefaults) {
  const Scene a = sedimentation({}), b = sedimentation({"fidelity=balanced"});
  EXPECT_EQ(a.fidelity, "balanced");
  EXPECT_EQ(a.fluid.spacing, b.fluid.spacing);
  EXPECT_EQ(a.fluid.sound_speed, b.fluid.sound_speed);
  EXPECT_EQ(a.time.cfl, 0.25);
  EXPECT_EQ(a.time.dem_steps_per_contact, 20);
  EXPECT_EQ(a.contact.max_overlap, 0.01);
}

TEST(Fidelity, PresetsSetWhatTheSceneLeavesUnset) {
  const Scene fast = sedimentation({"fidelity=fast"}), acc = sedimentation({"fidelity=accurate"});
  // 2 mm wide at dx = 0.2 mm: fast 0.25 mm (8 layers); accurate keeps 0.2 mm
  EXPECT_DOUBLE_EQ(fast.fluid.spacing, 2.5e-4);
  EXPECT_DOUBLE_EQ(acc.fluid.spacing, 2e-4);
  EXPECT_EQ(fast.fluid.resolution, 1.0);  // resolved: case.yaml loads back the same scene
  const Scene again = load_scene_text(scene_to_yaml(fast), "case.yaml");
  EXPECT_EQ(again.fluid.spacing, fast.fluid.spacing);
  EXPECT_EQ(again.fluid.sound_speed, fast.fluid.sound_speed);
  EXPECT_EQ(again.contact.normal.k, fast.contact.normal.k);
  EXPECT_EQ(again.fidelity, "fast");
  EXPECT_NE(fast.fidelity_note.find("0.00025"), std::string::npos) << fast.fidelity_note;
  // c0 = f sqrt(2 g H): the density error 1/(2 f^2)
  EXPECT_NEAR(sound_speed_report(fast).expected_density_error(), 1.0 / (2 * 8.0 * 8.0), 1e-12);
  EXPECT_NEAR(sound_speed_report(acc).expected_density_error(), 1.0 / (2 * 20.0 * 20.0), 1e-12);
  EXPECT_EQ(fast.time.cfl, 0.3);
  EXPECT_EQ(acc.time.dem_steps_per_contact, 40);
  EXPECT_EQ(acc.contact.max_overlap, 0.005);
  EXPECT_GT(acc.contact.normal.k, fast.contact.normal.k);  // the automatic spring follows
}

TEST(Fidelity, KeysTheSceneSetsWin) {
  const Scene s = sedimentation(
      {"fidelity=fast", "time.cfl=0.2", "fluid.resolution=1", "contact.max_overlap=0.01"});
  EXPECT_EQ(s.time.cfl, 0.2);
  EXPECT_DOUBLE_EQ(s.fluid.spacing, 2e-4);
  EXPECT_EQ(s.contact.max_overlap, 0.01);
  EXPECT_EQ(s.time.dem_steps_per_contact, 10);  // not set: the preset's
}

TEST(Fidelity, AResolutionTheBoxCannotTakeIsDroppedOrRefused) {
  // 2 mm x 1.6 mm: the fast preset's 0.25 mm divides 2 mm into 8 layers, not 1.6 mm
  const std::vector<std::string> narrow = {"domain.size=[0.002, 0.0016, 0.003]",
                                           "particles.0.max=[0.002, 0.0016, 0.002]"};
  auto sets = narrow;
  sets.push_back("fidelity=fast");
  const Scene s = sedimentation(sets);
  EXPECT_DOUBLE_EQ(s.fluid.spacing, 2e-4);
  EXPECT_NE(s.fidelity_note.find("not applied"), std::string::npos) << s.fidelity_note;
  sets.push_back("fluid.resolution=0.8");  // the scene's own: an error naming the key
  try {
    sedimentation(sets);
    FAIL() << "expected a SceneError";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("key 'fluid.resolution'"), std::string::npos) << e.what();
  }
  EXPECT_THROW(sedimentation({"fidelity=fastest"}), SceneError);
}
