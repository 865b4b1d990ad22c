// sphdem check's forecast of a forming sediment (run/sediment_forecast.*): the Kynch time,
// the SPH step at the bed's top and the wall time's integral, each against its closed form.
#include "run/sediment_forecast.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "coupling/hindered_settling.hpp"
#include "scene/kernel_width_rule.hpp"

using namespace sphdem;

namespace {

// The default scene's suspension: 100 um glass at eps 0.85 in water, 3 mm tall.
Scene suspension(const char* extra = "") {
  return load_scene_text(std::string(R"(
name: t
domain: {size: [0.002, 0.002, 0.0045]}
fluid: {density: 1000, viscosity: 8.9e-4, spacing: 2.0e-4}
species: [{name: glass, diameter: 1.0e-4, density: 2500}]
drag: {law: di_felice}
particles:
  - {type: random, species: glass, min: [0, 0, 0], max: [0.002, 0.002, 0.003], voidage: 0.85, seed: 1)") +
                             extra + "}\n",
                         "suspension");
}

}  // namespace

// The generic bisection against the Di Felice closed form's own (4.4): a different
// discretisation of the same balance.
TEST(SedimentForecast, SettlingSpeedIsTheDiFeliceHinderedSpeed) {
  const Scene sc = suspension();
  for (double eps : {0.5, 0.7, 0.85, 1.0}) {
    const double u = settling_speed(sc.drag, 1e-4, 2500, 1000, 8.9e-4, 9.81, eps);
    EXPECT_NEAR(u, di_felice_hindered_settling(1e-4, 2500, 1000, 8.9e-4, 9.81, eps), 1e-9 * u)
        << "eps " << eps;
  }
}

TEST(SedimentForecast, KynchTimeStepAndListsInClosedForm) {
  const Scene sc = suspension();
  const double eps0 = 0.85, eb = kBedVoidage;
  const double c0 = sc.fluid.sound_speed, h0 = sc.fluid.lattice_h(), cfl = sc.time.cfl;
  const double dt0 = cfl * h0 * std::sqrt(eps0) / c0;  // the suspension's CFL bound (3.5)
  const SedimentForecast f = forecast_sediment(sc, dt0);
  ASSERT_TRUE(f.forms);
  const double u =
      di_felice_hindered_settling(1e-4, 2500, 1000, 8.9e-4, sc.gravity_magnitude(), eps0);
  EXPECT_NEAR(f.settle_time, 0.003 * (1.0 - 0.15 / 0.6) / u, 1e-9);
  // the bed's top binds: clear liquid's h over the pair's mean sound speed
  const double top = cfl * h0 * std::cbrt(eps0) / (0.5 * c0 * (1.0 + 1.0 / std::sqrt(eb)));
  EXPECT_NEAR(f.step_ratio, top / dt0, 1e-12);
  EXPECT_LT(f.step_ratio, 1.0);
  EXPECT_NEAR(f.list_growth, eps0 / eb, 1e-12);
}

TEST(SedimentForecast, NoBedWithoutMobileSettlingSpheres) {
  EXPECT_FALSE(forecast_sediment(suspension(", rigid: true"), 1e-5).forms);
  Scene floating = suspension();
  floating.species[0].density = 900;
  EXPECT_FALSE(forecast_sediment(floating, 1e-5).forms);
}

// Linear growth over the Kynch time, then constant: the integral in closed form,
// t_s (1 + (a + b)/2 + ab/3) + (T - t_s)(1 + a)(1 + b) in units of step / dt0.
TEST(SedimentForecast, WallTimeIsTheIntegralOfTheGrowingRate) {
  SedimentForecast f;
  const double step = 0.004, dt0 = 4e-5, share = 0.3;
  EXPECT_DOUBLE_EQ(forecast_wall(f, step, share, dt0, 0.8), step * 0.8 / dt0);
  f.forms = true;
  f.settle_time = 0.5;
  f.step_ratio = 0.8;
  f.list_growth = 2.0;
  const double a = share * (f.list_growth - 1.0), b = 1.0 / f.step_ratio - 1.0;
  const double ts = f.settle_time, T = 0.8;
  const double exact =
      step / dt0 * (ts * (1.0 + 0.5 * (a + b) + a * b / 3.0) + (T - ts) * (1.0 + a) * (1.0 + b));
  EXPECT_NEAR(forecast_wall(f, step, share, dt0, T), exact, 1e-6 * exact);
  // before the bed forms: only the ramp's start
  const double early =
      step / dt0 * (0.1 + 0.5 * (a + b) * 0.01 / ts + a * b * 0.001 / (3 * ts * ts));
  EXPECT_NEAR(forecast_wall(f, step, share, dt0, 0.1), early, 1e-6 * early);
}
