// sphdem check's forecast of a forming sediment (run/sediment_forecast.*): the Kynch time,
// the SPH step at the bed's top and the steps' integral, each against its closed form.
#include "run/sediment_forecast.hpp"

#include <gtest/gtest.h>

#include <algorithm>
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

TEST(SedimentForecast, KynchTimeAndStepInClosedForm) {
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
}

TEST(SedimentForecast, NoBedWithoutMobileSettlingSpheres) {
  EXPECT_FALSE(forecast_sediment(suspension(", rigid: true"), 1e-5).forms);
  Scene floating = suspension();
  floating.species[0].density = 900;
  EXPECT_FALSE(forecast_sediment(floating, 1e-5).forms);
}

// The steps per second grow linearly over the Kynch time, then stay: in units of step / dt0,
// T + b T^2 / (2 t_s) before t_s, t_s (1 + b/2) + (T - t_s)(1 + b) after, b = 1/ratio - 1;
// evaluated against a fine midpoint sum of the same rate.
TEST(SedimentForecast, WallTimeIsTheIntegralOfTheGrowingStepRate) {
  SedimentForecast f;
  const double step = 0.004, dt0 = 4e-5;
  EXPECT_DOUBLE_EQ(forecast_wall(f, step, dt0, 0.8), step * 0.8 / dt0);
  f.forms = true;
  f.settle_time = 0.5;
  f.step_ratio = 0.8;
  for (double T : {0.1, 0.5, 0.8}) {
    double sum = 0.0;
    const int n = 100000;
    for (int k = 0; k < n; ++k) {
      const double t = (k + 0.5) * T / n;
      sum += (1.0 + (1.0 / f.step_ratio - 1.0) * std::min(1.0, t / f.settle_time)) * T / n;
    }
    EXPECT_NEAR(forecast_wall(f, step, dt0, T), step * sum / dt0, 1e-6 * step * sum / dt0)
        << "T " << T;
  }
  EXPECT_NEAR(forecast_wall(f, step, dt0, 0.8), step / dt0 * (0.5 * 1.125 + 0.3 * 1.25), 1e-9);
}
