// The flow controller of a column periodic in z (propagator/flow_controller.hpp).
#include "propagator/flow_controller.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

#include "scene/scene.hpp"

using namespace sphdem;

// U(t) of the schedule: linear between the points, held outside them.
TEST(FlowSchedule, LinearBetweenItsPointsAndHeldOutside) {
  const FlowSchedule s({0.0, 1.0, 3.0}, {0.0, 2.0, -2.0});
  EXPECT_EQ(s.at(-1.0), 0.0);
  EXPECT_DOUBLE_EQ(s.at(0.25), 0.5);
  EXPECT_DOUBLE_EQ(s.at(1.0), 2.0);
  EXPECT_DOUBLE_EQ(s.at(2.0), 0.0);
  EXPECT_DOUBLE_EQ(s.at(2.5), -1.0);
  EXPECT_EQ(s.at(5.0), -2.0);
  EXPECT_THROW(FlowSchedule({0.0, 0.0}, {1.0, 2.0}), std::invalid_argument);
}

// One correction puts the fluid's momentum on rho_f V_box U(t) and adds the impulse per
// unit volume over dt to G; a fluid already on target changes nothing.
TEST(FlowController, OneCorrectionPutsTheMeanOnTargetAndTheImpulseIntoG) {
  Box box;
  box.hi = {0.001, 0.002, 0.004};
  box.periodic = {true, true, true};
  FlowSpec spec;
  spec.times = {0.0, 1.0};
  spec.superficial_velocity = {0.0, 0.01};
  const double rho = 1000.0, volume = 8e-9, mass = 0.8 * rho * volume, dt = 1e-4;
  FlowController c(spec, box, rho);
  ASSERT_TRUE(c.on());
  const std::array<double, 3> p{1e-9, 0.0, -2e-9};  // momentum of the fluid
  const std::array<double, 3> du = c.correct(p, mass, 0.5, dt);
  for (int k = 0; k < 3; ++k) {
    const double target = k == 2 ? 0.005 : 0.0;
    EXPECT_NEAR((p[k] + mass * du[k]) / (rho * volume), target, 1e-15);
    EXPECT_NEAR(c.pressure_gradient()[k], rho * du[k] / dt, 1e-12 * std::abs(rho * du[k] / dt));
  }
  EXPECT_DOUBLE_EQ(c.measured_velocity(), p[2] / (rho * volume));
  const std::array<double, 3> G = c.pressure_gradient();
  const std::array<double, 3> none = c.correct({0.0, 0.0, 0.005 * rho * volume}, mass, 0.5, dt);
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(none[k], 0.0, 1e-16);  // round-off of 0.005 rho V / (rho V)
    EXPECT_NEAR(c.pressure_gradient()[k], G[k], 1e-9 * std::abs(G[k]) + 1e-15);
  }
  // the frictional drop: G_z + rho_f g_z over the height
  EXPECT_DOUBLE_EQ(c.pressure_drop(-9.81), (c.pressure_gradient()[2] - rho * 9.81) * 0.004);
  EXPECT_FALSE(FlowController().on());
}
