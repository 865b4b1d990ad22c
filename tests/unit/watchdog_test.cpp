// The watchdog (analysis/watchdog.hpp): each cause provoked by a scene, named with its
// particle, quantity and key; a healthy run raises nothing; the runner stops a run with
// the message, a neighbourhood dump and the last good checkpoint.
#include "analysis/watchdog.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>

#include "analysis/watchdog_warnings.hpp"
#include "propagator/simulation.hpp"
#include "run/runner.hpp"
#include "scene/scene.hpp"
#include "scene/sound_speed_rule.hpp"

using namespace sphdem;

namespace {

// 100 um glass settling onto the wall in a 1.6 mm water column.
const char* const kSettling = R"(
name: settling
domain: {size: [0.0016, 0.0016, 0.0016]}
fluid: {density: 1000, viscosity: 8.9e-4, spacing: 2.0e-4}
species: [{name: glass, diameter: 1.0e-4, density: 2500}]
particles:
  - {type: random, species: glass, min: [0, 0, 0], max: [0.0016, 0.0016, 0.0008], voidage: 0.8, seed: 2}
startup: {relax_steps: 2}
)";
// A bed of 100 um spheres, 3 layers, resting on the wall (dry: no fluid).
const char* const kDryBed = R"(
name: dry_bed
domain: {size: [0.0016, 0.0016, 0.004]}
fluid: {enabled: false}
species: [{name: glass, diameter: 1.0e-4, density: 2500}]
particles:
  - {type: lattice, species: glass, min: [0, 0, 0], max: [0.0016, 0.0016, 0.0003001], voidage: 0.4765}
contact: {stiffness: 100, restitution: 0.5}
)";

// Steps until the watchdog raises an alarm (nullopt if none within max_steps).
std::optional<WatchdogAlarm> run_until_alarm(const Scene& scene, int max_steps) {
  Simulation sim(scene);
  sim.relax();
  for (int k = 0; k < max_steps; ++k) {
    sim.step();
    if (auto alarm = watchdog_check(sim, scene.watchdog)) return alarm;
  }
  return std::nullopt;
}

bool has(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

TEST(Watchdog, AHealthyRunRaisesNothing) {
  EXPECT_FALSE(run_until_alarm(load_scene_text(kSettling, "t"), 150));
  EXPECT_FALSE(run_until_alarm(load_scene_text(kDryBed, "t"), 4));  // 2430 sub-steps each
}

TEST(Watchdog, TooFewDemSubStepsPerContact) {
  Scene sc = load_scene_text(kDryBed, "t", {"particles.0.velocity=[0, 0, -0.3]"});
  sc.time.dem_steps_per_contact = 1.2;  // past the loader's range [5, 1000]: unstable springs
  const auto alarm = run_until_alarm(sc, 400);
  ASSERT_TRUE(alarm);
  EXPECT_TRUE(alarm->sphere);
  EXPECT_TRUE(has(alarm->cause, "dt_DEM too large for this k")) << alarm->cause;
  EXPECT_TRUE(has(alarm->cause, "time.dem_steps_per_contact")) << alarm->cause;
  EXPECT_EQ(alarm->kind, "glass");
}

TEST(Watchdog, ASpringTooSoftForTheLoad) {
  Scene sc = load_scene_text(kDryBed, "t", {"contact.stiffness=0.002"});
  const auto alarm = run_until_alarm(sc, 20000);
  ASSERT_TRUE(alarm);
  EXPECT_EQ(alarm->quantity, "overlap / d");
  EXPECT_GT(alarm->value, 0.1);  // the bound, watchdog.overlap
  EXPECT_TRUE(has(alarm->cause, "contact.stiffness")) << alarm->cause;
}

TEST(Watchdog, ASoundSpeedTooLowForTheColumn) {
  // g H / c0^2 = 9.81 * 1.6e-3 / 0.05^2 = 6: the column cannot be weakly compressible
  const auto alarm =
      run_until_alarm(load_scene_text(kSettling, "t", {"fluid.sound_speed=0.05"}), 200);
  ASSERT_TRUE(alarm);
  EXPECT_FALSE(alarm->sphere);
  EXPECT_TRUE(has(alarm->quantity, "density error")) << alarm->quantity;
  EXPECT_TRUE(has(alarm->cause, "raise fluid.sound_speed")) << alarm->cause;
}

TEST(Watchdog, AnSphStepPastItsStabilityNamesTheCfl) {
  Scene sc = load_scene_text(kSettling, "t");
  sc.time.cfl = 4.0;  // past the loader's range (0, 1)
  const auto alarm = run_until_alarm(sc, 200);
  ASSERT_TRUE(alarm);
  EXPECT_FALSE(alarm->sphere);
  EXPECT_TRUE(has(alarm->cause, "lower time.cfl")) << alarm->quantity << ": " << alarm->cause;
}

TEST(Watchdog, NonFiniteStateWithTheOtherBoundsOff) {
  Scene sc = load_scene_text(
      kSettling, "t",
      {"watchdog.density_error=1e300", "watchdog.overlap=1e300", "watchdog.safeguard_share=1"});
  sc.time.cfl = 4.0;
  const auto alarm = run_until_alarm(sc, 2000);
  ASSERT_TRUE(alarm);
  EXPECT_TRUE(has(alarm->quantity, "non-finite") || has(alarm->quantity, "wall") ||
              has(alarm->quantity, "domain"))
      << alarm->quantity;
  EXPECT_TRUE(has(alarm->cause, "time.cfl")) << alarm->quantity << ": " << alarm->cause;
}

TEST(Watchdog, ASurfaceParticleMayBobAKernelSupportAboveTheTop) {
  // the column fills the box: its surface layer sits dx/2 below the top (the reduced sand
  // column, seed 2017, stopped at 0.59 s with a surface particle at the top itself)
  const Scene sc = load_scene_text(kSettling, "t");
  Simulation sim(sc);
  sim.relax();
  const double top = sim.params().box.hi[2];
  const double support = kernel::kSupport * sc.fluid.lattice_h();
  FluidParticles& f = sim.fluid();
  std::size_t a = 0;
  for (std::size_t b = 0; b < f.n_owned; ++b)
    if (f.kind[b] == kFluid && f.z[b] > f.z[a]) a = b;
  f.z[a] = top + 0.9 * support;
  EXPECT_FALSE(watchdog_check(sim, sc.watchdog));
  f.z[a] = top + 1.1 * support;
  const auto alarm = watchdog_check(sim, sc.watchdog);
  ASSERT_TRUE(alarm);
  EXPECT_EQ(alarm->quantity, "left the domain");
  EXPECT_FALSE(alarm->sphere);
  EXPECT_DOUBLE_EQ(alarm->limit, top + support);
}

TEST(Watchdog, ASphereThrownOutOfTheBox) {
  const auto alarm = run_until_alarm(
      load_scene_text(kDryBed, "t", {"particles.0.velocity=[0, 0, 2]", "gravity=[0, 0, 0]"}), 2000);
  ASSERT_TRUE(alarm);
  EXPECT_EQ(alarm->quantity, "left the domain");
  EXPECT_TRUE(alarm->sphere);
  EXPECT_GT(alarm->z, 0.004);
  EXPECT_TRUE(has(alarm->cause, "domain.size")) << alarm->cause;
}

TEST(Watchdog, TheVoidageFloorHoldingTheFluid) {
  // a bed at eps 0.48 under a floor of 0.6: the floor replaces the voidage in the bed
  const auto alarm = run_until_alarm(
      load_scene_text(kSettling, "t",
                      {"particles.0={type: lattice, species: glass, min: [0, 0, 0], max: [0.0016, "
                       "0.0016, 0.0010001], voidage: 0.4765}",
                       "coupling.voidage_floor=0.7"}),
      5);
  ASSERT_TRUE(alarm);
  EXPECT_TRUE(has(alarm->quantity, "voidage floor")) << alarm->quantity;
  EXPECT_GT(alarm->value, 0.01);
  EXPECT_TRUE(has(alarm->cause, "coupling.voidage_floor")) << alarm->cause;
}

// No scene tried reached the Omega clamp (blow-ups at CFL 0.9-4, beds with d = dx, pairs of
// fluid particles collapsed onto each other): a step's state does it here, the top layers
// of a column expanded tenfold below the free surface (h grows by 10^(1/3) and the
// kernel reaches past the surface), with the density bound off so that the clamp speaks.
TEST(Watchdog, TheOmegaClampHoldingTheFluid) {
  const Scene sc = load_scene_text(
      "name: column\ndomain: {size: [0.0016, 0.0016, 0.0016]}\n"
      "fluid: {density: 1000, viscosity: 8.9e-4, spacing: 2.0e-4}\n"
      "startup: {relax_steps: 0}\nwatchdog: {density_error: 1e300}\n",
      "t");
  Simulation sim(sc);
  FluidParticles& f = sim.fluid();
  for (std::size_t a = 0; a < f.n_owned; ++a)
    if (f.kind[a] == kFluid && f.z[a] > 0.0013) f.rho[a] *= 0.1;
  sim.refresh();
  ASSERT_GT(sim.omega_bounded(), 0.01 * sim.fluid_count());
  const auto alarm = watchdog_check(sim, sc.watchdog);
  ASSERT_TRUE(alarm);
  EXPECT_TRUE(has(alarm->quantity, "Omega term clamped")) << alarm->quantity;
  EXPECT_GT(alarm->z, 0.0013);
  EXPECT_TRUE(has(alarm->cause, "h varies faster than the kernel resolves")) << alarm->cause;
}

TEST(Watchdog, TheRunnerStopsWithTheDumpAndTheLastCheckpoint) {
  namespace fs = std::filesystem;
  const std::string dir = (fs::temp_directory_path() / "sphdem_watchdog_test").string();
  fs::remove_all(dir);
  // thrown out of the box after a few checkpoints: the run passes the model's limits
  const Scene sc = load_scene_text(
      kDryBed, "t",
      {"domain.size=[0.0016, 0.0016, 0.01]", "particles.0.max=[0.0016, 0.0016, 0.0001001]",
       "particles.0.velocity=[0, 0, 0.08]", "gravity=[0, 0, 0]", "contact.stiffness=0.05",
       "time.end=0.2", "checkpoint.every=0.0005"});
  RunOptions opt;
  opt.out_dir = dir;
  try {
    run_scene(sc, opt);
    FAIL() << "the run was not stopped";
  } catch (const WatchdogError& e) {
    const std::string m = e.what();
    EXPECT_TRUE(has(m, "watchdog at step")) << m;
    EXPECT_TRUE(has(m, "sphere id")) << m;
    EXPECT_TRUE(has(m, "left the domain")) << m;
    EXPECT_TRUE(has(m, "the last good checkpoint is " + dir)) << m;
    EXPECT_TRUE(has(m, dir + "/watchdog/step_")) << m;
    const auto dumps = fs::directory_iterator(dir + "/watchdog");
    ASSERT_NE(dumps, fs::directory_iterator());
    std::ifstream in(dumps->path());
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_TRUE(has(text, "<VTKFile type=\"PolyData\"")) << text.substr(0, 200);
    EXPECT_TRUE(has(text, "Name=\"culprit\"")) << text.substr(0, 200);
  }
}

// The alarms' bounds: the density error at max(1 %, twice the expected of c0), so the fast
// preset (c0 = 8 sqrt(2 g H): 0.78 % expected) alarms at its own 1.56 % and the balanced
// one (0.5 %) at the weakly compressible 1 %; a number in the file as given; overlaps at 0.1 d.
TEST(Watchdog, TheDensityAlarmIsTwiceTheExpectedErrorOrTheWeaklyCompressibleLimit) {
  const Scene balanced = load_scene_text(kSettling, "t");
  const double e_balanced = sound_speed_report(balanced).expected_density_error();
  EXPECT_NEAR(e_balanced, 0.005, 1e-12);
  EXPECT_DOUBLE_EQ(balanced.watchdog.density_error, 0.01);
  const Scene fast = load_scene_text(kSettling, "t", {"fidelity=fast"});
  const double e_fast = sound_speed_report(fast).expected_density_error();
  EXPECT_NEAR(e_fast, 1.0 / (2 * 8.0 * 8.0), 1e-12);
  EXPECT_DOUBLE_EQ(fast.watchdog.density_error, 2 * e_fast);
  EXPECT_DOUBLE_EQ(
      load_scene_text(kSettling, "t", {"watchdog.density_error=0.03"}).watchdog.density_error,
      0.03);
  EXPECT_DOUBLE_EQ(balanced.watchdog.overlap, 0.1);
  // the resolved bound is what case.yaml records, and reads back as a number
  EXPECT_DOUBLE_EQ(load_scene_text(scene_to_yaml(fast), "case.yaml").watchdog.density_error,
                   2 * e_fast);
}

// The reading the warnings take: the worst density error and overlap of the state.
TEST(Watchdog, TheReadingIsTheStatesWorstDensityErrorAndOverlap) {
  const Scene sc = load_scene_text(kSettling, "t");
  Simulation sim(sc);
  sim.relax();
  for (int k = 0; k < 20; ++k) sim.step();
  WatchdogReading r;
  EXPECT_FALSE(watchdog_check(sim, sc.watchdog, &r));
  const FluidParticles& f = sim.fluid();
  double worst = 0;
  for (std::size_t a = 0; a < f.n_owned; ++a)
    if (f.kind[a] == kFluid)
      worst = std::max(worst, std::abs(f.rho[a] / (f.eps[a] * sim.eos().rho0) - 1.0));
  EXPECT_GT(worst, 0.0);
  EXPECT_EQ(r.density_error, worst);
  const DemParticles& s = sim.spheres();
  double overlap = 0;
  for (std::size_t j = 0; j < s.n_owned; ++j)
    overlap = std::max(overlap, s.overlap_max[j] / (2 * s.radius[j]));
  EXPECT_EQ(r.overlap, overlap);
}

// The warnings: each kind once a run; a safeguard only once it has bitten in every one of
// kPersistentSafeguardSteps steps in a row (a step without a hit starts the count again).
TEST(Watchdog, WarningsComeOncePastTheExpectedValuesAndForAPersistentSafeguard) {
  const Scene sc = load_scene_text(kSettling, "t");
  WatchdogWarnings w(sc);
  EXPECT_DOUBLE_EQ(w.density_warning(), 1.5 * 0.005);
  EXPECT_LE(w.expected_overlap(), sc.contact.max_overlap);  // stiffness: auto
  EXPECT_GT(w.expected_overlap(), 0.9 * sc.contact.max_overlap);
  WatchdogStepTally quiet;
  EXPECT_TRUE(w.observe(quiet, 1, 0.0).empty());
  WatchdogStepTally dense = quiet;
  dense.density_past_expected = true;
  auto out = w.observe(dense, 2, 0.1);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_TRUE(has(out[0], "density error passed 0.75 %")) << out[0];
  EXPECT_TRUE(has(out[0], "the alarm is at 1 %")) << out[0];
  EXPECT_TRUE(has(out[0], twice_the_sound_speed(sc))) << out[0];
  EXPECT_TRUE(w.observe(dense, 3, 0.2).empty());
  WatchdogStepTally pressed = quiet;
  pressed.overlap_past_expected = true;
  out = w.observe(pressed, 4, 0.3);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_TRUE(has(out[0], "largest overlap passed")) << out[0];
  WatchdogStepTally floor = quiet;
  floor.floor_hits = 3;
  for (long k = 1; k < kPersistentSafeguardSteps; ++k)
    EXPECT_TRUE(w.observe(floor, 10 + k, 0.0).empty()) << k;
  EXPECT_TRUE(w.observe(quiet, 200, 0.0).empty());  // one step without: the count starts again
  for (long k = 1; k < kPersistentSafeguardSteps; ++k)
    EXPECT_TRUE(w.observe(floor, 200 + k, 0.0).empty()) << k;
  out = w.observe(floor, 300, 0.0);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_TRUE(has(out[0], "voidage floor has held fluid particles in each of the last 100"))
      << out[0];
  EXPECT_TRUE(w.observe(floor, 301, 0.0).empty());
  WatchdogStepTally clamp = quiet;
  clamp.clamp_hits = 1;
  for (long k = 1; k < kPersistentSafeguardSteps; ++k) EXPECT_TRUE(w.observe(clamp, k, 0).empty());
  EXPECT_EQ(w.observe(clamp, 400, 0.0).size(), 1u);
  // no fluid, no spring: nothing to expect
  const WatchdogWarnings dry(load_scene_text(kDryBed, "t", {"particles.0.rigid=true"}));
  EXPECT_TRUE(std::isinf(dry.expected_density_error()));
  EXPECT_TRUE(std::isinf(dry.expected_overlap()));
}

// The coupling among the causes: a density alarm at a fluid particle among packed spheres
// (a bed at eps 0.48 under 0.6 mm of water) names the interpolated coupling's instability
// there, and with the variational coupling the Darcy pressure c0's rule does not count.
TEST(Watchdog, AnAlarmAmongPackedSpheresNamesTheCoupling) {
  const std::string bed =
      "particles.0={type: lattice, species: glass, min: [0, 0, 0], max: [0.0016, 0.0016, "
      "0.0010001], voidage: 0.4765}";
  for (const char* coupling : {"interpolated", "variational"}) {
    Scene sc = load_scene_text(kSettling, "t",
                               {bed, std::string("coupling.pressure_coupling=") + coupling});
    Simulation sim(sc);
    sim.relax();
    sim.step();
    WatchdogSpec tight = sc.watchdog;
    tight.density_error = 1e-9;  // the worst particle alarms
    const auto alarm = watchdog_check(sim, tight);
    ASSERT_TRUE(alarm);
    ASSERT_TRUE(has(alarm->quantity, "density error")) << alarm->quantity;
    ASSERT_LT(alarm->z, 0.001) << "the worst particle is in the bed";
    if (std::string(coupling) == "interpolated") {
      EXPECT_TRUE(has(alarm->cause, "interpolated pressure coupling is linearly unstable"))
          << alarm->cause;
    } else {
      EXPECT_TRUE(has(alarm->cause, "Darcy")) << alarm->cause;
      EXPECT_TRUE(has(alarm->cause, twice_the_sound_speed(sc))) << alarm->cause;
    }
  }
  // above the bed, the same bound names no coupling
  Scene clear = load_scene_text(kSettling, "t", {"particles=[]"});
  Simulation sim(clear);
  sim.relax();
  sim.step();
  WatchdogSpec tight = clear.watchdog;
  tight.density_error = 1e-9;
  const auto alarm = watchdog_check(sim, tight);
  ASSERT_TRUE(alarm);
  EXPECT_FALSE(has(alarm->cause, "coupling")) << alarm->cause;
  EXPECT_FALSE(has(alarm->cause, "Darcy")) << alarm->cause;
  // a density bound passed with the state finite is c0's, not an unstable step's
  EXPECT_TRUE(has(alarm->cause, twice_the_sound_speed(clear))) << alarm->cause;
  EXPECT_FALSE(has(alarm->cause, "lower time.cfl")) << alarm->cause;
}

// The advice for a density error the sound speed rule does not count: twice c0, in the key
// the user sets (scene/sound_speed_rule.hpp). The factor where it makes c0 and twice it is
// within the key's range (at most 100); else fluid.sound_speed, whose value is twice c0.
// Measured on the homogeneous suspensions at eps 0.6: doubling c0 took the largest density
// error from 1.14 to 0.56 % (100 um) and from 2.30 to 0.93 % (50 um).
TEST(Watchdog, TheSoundSpeedAdviceIsTwiceC0InTheKeyTheUserSets) {
  const Scene by_factor = load_scene_text(kSettling, "t", {"fluid.sound_speed_factor=20"});
  const double c0 = by_factor.fluid.sound_speed;
  EXPECT_EQ(twice_the_sound_speed(by_factor),
            fmt::format("raise fluid.sound_speed_factor from 20 to 40 (c0 {:.3g} -> {:.3g} m/s)",
                        c0, 2 * c0));
  const Scene past_max = load_scene_text(kSettling, "t", {"fluid.sound_speed_factor=60"});
  const std::string advice = twice_the_sound_speed(past_max);
  EXPECT_TRUE(has(advice, fmt::format("set fluid.sound_speed: {:.3g} ", 2 * 3 * c0))) << advice;
  EXPECT_TRUE(has(advice, "fluid.sound_speed_factor is at most 100")) << advice;
  const Scene given = load_scene_text(kSettling, "t", {"fluid.sound_speed=7"});
  EXPECT_EQ(twice_the_sound_speed(given), "set fluid.sound_speed: 14 (m/s; twice c0 = 7)");
  // the buoyancy bound makes c0 (spheres near neutral buoyancy): the factor would not move it
  const Scene buoyant = load_scene_text(kSettling, "t", {"species.0.density=1010"});
  ASSERT_GT(buoyant.fluid.sound_speed, 1.01 * buoyant.fluid.sound_speed_factor *
                                           std::sqrt(2 * 9.81 * buoyant.hydrostatic_height()));
  EXPECT_TRUE(has(twice_the_sound_speed(buoyant), "set fluid.sound_speed: "))
      << twice_the_sound_speed(buoyant);
}

}  // namespace
