// Bad scenes (issue 16): the loader reports every problem of a file at once, one line
// each naming the file and the key, and a misspelt key, section, choice or species name
// gets the closest allowed name ("did you mean"), also for keys given by --set.
#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "scene/did_you_mean.hpp"
#include "scene/scene.hpp"

using namespace sphdem;

namespace {

constexpr const char* kFile = "bad.yaml";

// A valid scene; the tests below break it in places.
const std::string kGood = R"(name: good
fluid: {viscosity: 1.0e-3, density: 1010}
species:
  - {name: glass, diameter: 1.0e-4, density: 2500}
particles:
  - {type: single, species: glass, position: [0.002, 0.002, 0.0048]}
drag: {law: di_felice}
time: {end: 0.01, cfl: 0.2}
)";

std::string replaced(std::string s, const std::string& from, const std::string& to) {
  const auto p = s.find(from);
  EXPECT_NE(p, std::string::npos) << from;
  if (p != std::string::npos) s.replace(p, from.size(), to);
  return s;
}

// The lines of the SceneError the scene raises (none when it loads).
std::vector<std::string> problems(const std::string& yaml,
                                  const std::vector<std::string>& overrides = {}) {
  try {
    load_scene_text(yaml, kFile, overrides);
  } catch (const SceneError& e) {
    std::vector<std::string> lines;
    std::istringstream in(e.what());
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
  }
  return {};
}

bool contains(const std::string& s, const std::string& part) {
  return s.find(part) != std::string::npos;
}

// The one line about `key`; fails the test unless there is exactly one.
std::string line_of(const std::vector<std::string>& lines, const std::string& key) {
  std::string found;
  int n = 0;
  for (const auto& l : lines)
    if (contains(l, "key '" + key + "'")) {
      found = l;
      ++n;
    }
  EXPECT_EQ(n, 1) << "lines about '" << key << "': " << n;
  return found;
}

}  // namespace

TEST(SceneErrorsAll, ThreeIndependentMistakesAreAllReported) {
  std::string bad = replaced(kGood, "viscosity: 1.0e-3", "viscosity: -1.0e-3");  // range
  bad = replaced(bad, "cfl: 0.2", "cfl: 0.2, ned: 1");                           // unknown
  bad = replaced(bad, "law: di_felice", "law: newton");                          // choice
  const auto lines = problems(bad);
  ASSERT_EQ(lines.size(), 3u) << ::testing::PrintToString(lines);
  for (const auto& l : lines) EXPECT_EQ(l.rfind(std::string(kFile) + ": key '", 0), 0u) << l;
  EXPECT_TRUE(contains(line_of(lines, "fluid.viscosity"), "(0, inf] (got -0.001)"));
  EXPECT_TRUE(contains(line_of(lines, "time.ned"), "unknown key"));
  EXPECT_TRUE(contains(line_of(lines, "drag.law"), "must be one of: stokes, di_felice"));
  // --set problems join those of the file
  const auto more = problems(bad, {"time.end=-1", "particles.7.rigid=true"});
  EXPECT_EQ(more.size(), 5u) << ::testing::PrintToString(more);
  EXPECT_TRUE(contains(line_of(more, "time.end"), "(from --set 'time.end=-1')"));
}

TEST(SceneErrorsAll, ACorrectSceneLoadsWithItsValues) {
  EXPECT_TRUE(problems(kGood).empty());
  const Scene sc = load_scene_text(kGood, kFile);
  EXPECT_EQ(sc.fluid.viscosity, 1.0e-3);
  EXPECT_EQ(sc.fluid.density, 1010);
  EXPECT_EQ(sc.time.cfl, 0.2);
  EXPECT_EQ(sc.time.end, 0.01);
  ASSERT_EQ(sc.species.size(), 1u);
  EXPECT_EQ(sc.species[0].diameter, 1.0e-4);
  ASSERT_EQ(sc.particles.size(), 1u);
  EXPECT_EQ(sc.particles[0].position[2], 0.0048);
}

TEST(SceneErrorsAll, DidYouMeanAMisspeltKey) {
  const std::string l =
      line_of(problems(replaced(kGood, "viscosity:", "viscosty:")), "fluid.viscosty");
  EXPECT_TRUE(contains(l, "unknown key; did you mean 'viscosity'? allowed here: ")) << l;
  // nothing close: no guess, the allowed keys only
  const std::string far = line_of(problems(kGood + "output: {colour: red}\n"), "output.colour");
  EXPECT_FALSE(contains(far, "did you mean")) << far;
  EXPECT_TRUE(contains(far, "allowed here: log_interval, progress_interval, vtk")) << far;
}

TEST(SceneErrorsAll, DidYouMeanAMisspeltSection) {
  const auto lines = problems(replaced(kGood, "species:", "specis:"));
  EXPECT_TRUE(contains(line_of(lines, "specis"), "did you mean 'species'?"));
  // the group's species is then unknown, and is named too (nothing else)
  EXPECT_TRUE(contains(line_of(lines, "particles.0.species"), "'glass' is not a species"));
  EXPECT_EQ(lines.size(), 2u) << ::testing::PrintToString(lines);
  EXPECT_TRUE(contains(line_of(problems(replaced(kGood, "time:", "tmie:")), "tmie"),
                       "did you mean 'time'?"));
}

TEST(SceneErrorsAll, DidYouMeanAMisspeltChoice) {
  const std::string law =
      line_of(problems(replaced(kGood, "law: di_felice", "law: di_felise")), "drag.law");
  EXPECT_TRUE(contains(law, "(got 'di_felise'); did you mean 'di_felice'?")) << law;
  EXPECT_TRUE(contains(
      line_of(problems(replaced(kGood, "type: single", "type: lattise")), "particles.0.type"),
      "did you mean 'lattice'?"));
  // a species name is a choice among the file's species
  EXPECT_TRUE(contains(
      line_of(problems(replaced(kGood, "species: glass", "species: glas")), "particles.0.species"),
      "did you mean 'glass'?"));
}

TEST(SceneErrorsAll, AKeyInTheWrongSectionIsPointedToItsOwn) {
  EXPECT_TRUE(contains(line_of(problems(kGood + "cfl: 0.3\n"), "cfl"), "did you mean 'time.cfl'?"));
  EXPECT_TRUE(contains(
      line_of(problems(replaced(kGood, "density: 1010", "density: 1010, end: 1")), "fluid.end"),
      "did you mean 'time.end'?"));
  // a key of every species names the list, not one entry of it
  EXPECT_TRUE(
      contains(line_of(problems(replaced(kGood, "type: single", "type: single, diameter: 1")),
                       "particles.0.diameter"),
               "did you mean 'species.N.diameter'?"));
}

TEST(SceneErrorsAll, SetPathsGetTheSameHints) {
  const std::string l = line_of(problems(kGood, {"fluid.viscosty=2.0e-3"}), "fluid.viscosty");
  EXPECT_TRUE(contains(l, "(from --set 'fluid.viscosty=2.0e-3')")) << l;
  EXPECT_TRUE(contains(l, "did you mean 'viscosity'?")) << l;
  EXPECT_TRUE(
      contains(line_of(problems(kGood, {"flud.density=900"}), "flud"), "did you mean 'fluid'?"));
  EXPECT_TRUE(
      contains(line_of(problems(kGood, {"drag.law=stoks"}), "drag.law"), "did you mean 'stokes'?"));
}

// A bad value is replaced by its default, and a check that reads it is skipped: one
// mistake gives one line, not a cascade about values the file never gave.
TEST(SceneErrorsAll, OneMistakeOneLine) {
  // a bad box: the fluid lattice and the sphere's position are not checked against a default
  EXPECT_EQ(problems(kGood + "domain: {size: [0.01, 0.01, -1]}\n").size(), 1u);
  // a bad type: the group's keys are not reported as unknown for some other type
  EXPECT_EQ(problems(replaced(kGood, "type: single", "type: cloud, voidage: 0.9")).size(), 1u);
  // a bad diameter: the group using the species is not checked against a size of 0
  EXPECT_EQ(problems(replaced(kGood, "diameter: 1.0e-4", "diameter: big")).size(), 1u);
  // a bad tangential model: its keys are not unknown
  EXPECT_EQ(problems(kGood + "contact: {tangential: {model: coulomb, friction: 0.5}}\n").size(),
            1u);
  // a list with two bad entries names each
  const auto two = problems(kGood + "insitu: {pipelines: [interface, snapshot]}\n");
  ASSERT_EQ(two.size(), 2u) << ::testing::PrintToString(two);
  EXPECT_TRUE(contains(two[0], "'insitu.pipelines.0'") && contains(two[0], "'interfaces'"));
  EXPECT_TRUE(contains(two[1], "'insitu.pipelines.1'") && contains(two[1], "'snapshots'"));
}

TEST(SceneErrorsAll, NotYamlStopsAtOnce) {
  const auto lines = problems("fluid: {density: [1,\n");
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_TRUE(contains(lines[0], "not valid YAML")) << lines[0];
  const auto list = problems("- 1\n- 2\n");
  ASSERT_EQ(list.size(), 1u);
  EXPECT_TRUE(contains(list[0], "key '<top>': must be a map of keys")) << list[0];
}

// std::stoul took "0x" and "-1" as list indices ("0x" as 0).
TEST(SceneErrorsAll, SetListIndexIsDigitsOnly) {
  for (const char* path : {"particles.0x.rigid=true", "particles.-1.rigid=true",
                           "particles.+0.rigid=true", "particles.99999999999999999999.rigid=true"})
    EXPECT_TRUE(contains(problems(kGood, {path}).at(0), "must be an index in [0, 1)")) << path;
  EXPECT_TRUE(contains(problems(kGood, {"fluid..density=1"}).at(0), "empty part"));
  EXPECT_TRUE(problems(kGood, {"particles.0.rigid=true"}).empty());
}

// Found by tests/fuzz (corpus: huge_density.yaml): a density of 1e300 loaded with the
// automatic contact.stiffness NaN (the impact's m v^2 overflows), which case.yaml wrote
// as .nan and could not load back, and `sphdem check` blamed contact.damping for.
TEST(SceneErrorsAll, AnAutomaticValueThatIsNotFiniteIsRefused) {
  const std::string huge = replaced(kGood, "density: 2500", "density: 1e300");
  const auto lines = problems(huge);
  ASSERT_EQ(lines.size(), 1u) << ::testing::PrintToString(lines);
  const std::string k = line_of(lines, "contact.stiffness");
  EXPECT_TRUE(contains(k, "its automatic value is") && contains(k, "nan")) << k;
  // given, the spring is the file's, and the scene loads
  EXPECT_TRUE(problems(huge + "contact: {stiffness: 100}\n").empty());
  // a viscosity of 1e-300 (a terminal speed of 2.5e235 m/s) the same
  EXPECT_TRUE(contains(line_of(problems(replaced(kGood, "viscosity: 1.0e-3", "viscosity: 1e-300")),
                               "contact.stiffness"),
                       "its automatic value is"));
}

TEST(DidYouMean, EditDistanceAndTheRule) {
  EXPECT_EQ(edit_distance("viscosty", "viscosity"), 1u);
  EXPECT_EQ(edit_distance("ned", "end"), 1u);  // two neighbours swapped
  EXPECT_EQ(edit_distance("Fluid", "fluid"), 0u);
  EXPECT_EQ(edit_distance("", "abc"), 3u);
  EXPECT_EQ(edit_distance("kitten", "sitting"), 3u);
  const std::vector<std::string> names = {"end", "cfl", "dem_steps_per_contact", "max_dt_sph"};
  EXPECT_EQ(closest_name("ned", names), "end");
  EXPECT_EQ(closest_name("cf", names), "cfl");
  EXPECT_EQ(closest_name("x", names), "");       // 1 edit, 1 character: no
  EXPECT_EQ(closest_name("fcl", names), "cfl");  // a swap is one edit
  EXPECT_EQ(closest_name("ab", {"cd"}), "");     // 2 edits on a short name
  EXPECT_EQ(closest_name("dem_step_per_contact", names), "dem_steps_per_contact");
  EXPECT_EQ(closest_name("max_dt_fluid", names), "");  // 5 edits
  EXPECT_EQ(did_you_mean("Cfl", names), "; did you mean 'cfl'?");
  EXPECT_EQ(did_you_mean("zzz", names), "");
}

// A column periodic in z (issue 37): the keys of a wall or free surface, a flow without
// the periodic column, and a schedule whose times go back are each refused, naming the key
// and what is allowed; the periodic column itself loads.
TEST(SceneErrorsFlow, APeriodicColumnRefusesWhatNeedsAWallOrSurface) {
  const std::string periodic = R"(domain: {size: [0.002, 0.002, 0.002], periodic_z: true}
fluid: {spacing: 2.0e-4}
species:
  - {name: glass, diameter: 1.0e-4, density: 2500}
particles:
  - {type: random, species: glass, min: [0, 0, 0], max: [0.002, 0.002, 0.002], voidage: 0.9, seed: 1}
flow: {times: [0, 0.1], superficial_velocity: [0, 1.0e-3]}
time: {end: 0.01}
)";
  EXPECT_TRUE(problems(periodic).empty());
  EXPECT_TRUE(
      contains(line_of(problems(periodic, {"fluid.fill_height=0.001"}), "fluid.fill_height"),
               "periodic in z"));
  EXPECT_TRUE(contains(line_of(problems(periodic, {"fluid.wall_layers=3"}), "fluid.wall_layers"),
                       "no wall"));
  EXPECT_TRUE(contains(line_of(problems(periodic, {"coupling.pressure_coupling=variational",
                                                   "coupling.hydrostatic_split=true"}),
                               "coupling.hydrostatic_split"),
                       "free surface"));
  EXPECT_TRUE(contains(line_of(problems(periodic, {"flow.times=[0.1, 0]"}), "flow.times"),
                       "must increase"));
  EXPECT_TRUE(contains(
      line_of(problems(periodic, {"flow.times=[0, 0.1, 0.2]"}), "flow.superficial_velocity"),
      "one value per entry"));
  EXPECT_TRUE(
      contains(line_of(problems(periodic, {"domain.size=[0.002, 0.002, 0.0021]"}), "fluid.spacing"),
               "whole number"));
  EXPECT_TRUE(contains(line_of(problems(periodic, {"domain.periodic_z=false"}), "flow"),
                       "periodic_z: true"));
}

// The distributor and the top plane (issue 37): a group across the distributor, a plane
// below a group or within a diameter of the periodic face, U past the terminal speed with
// no plane to hold what it lifts, and a fixed group given a velocity are refused.
TEST(SceneErrorsFlow, PlanesAndSpeedsAgainstTheGroups) {
  const std::string bed = R"(domain: {size: [0.002, 0.002, 0.004], periodic_z: true}
fluid: {spacing: 2.0e-4}
species:
  - {name: glass, diameter: 1.0e-4, density: 2500}
particles:
  - {type: random, species: glass, min: [0, 0, 0], max: [0.002, 0.002, 0.002], voidage: 0.7, seed: 1}
flow: {times: [0, 0.1], superficial_velocity: [0, 1.0e-3], distributor: true, top_plane: 0.003}
time: {end: 0.01}
)";
  EXPECT_TRUE(problems(bed).empty());
  EXPECT_TRUE(
      contains(line_of(problems(bed, {"particles.0.max=[0.002, 0.002, 0.004]"}), "particles.0.max"),
               "across the distributor"));
  EXPECT_TRUE(contains(line_of(problems(bed, {"flow.top_plane=0.0015"}), "flow.top_plane"),
                       "above every group"));
  EXPECT_TRUE(contains(line_of(problems(bed, {"flow.top_plane=0.00395"}), "flow.top_plane"),
                       "largest diameter"));
  // 100 um glass settles at 7.6 mm/s in clear water (Dallavalle): 1 cm/s would carry it
  EXPECT_TRUE(contains(line_of(problems(bed, {"flow.top_plane=0",
                                              "flow.superficial_velocity=[0, "
                                              "0.01]"}),
                               "flow.superficial_velocity"),
                       "terminal speed"));
  EXPECT_TRUE(problems(bed, {"flow.superficial_velocity=[0, 0.01]"}).empty());  // held
  EXPECT_TRUE(contains(
      line_of(problems(bed, {"particles.0.fixed=true", "particles.0.velocity=[0, 0, 0.1]"}),
              "particles.0.fixed"),
      "never moves"));
}
