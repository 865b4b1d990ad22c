// Tait equation of state with voidage (solver/sph/equation_of_state.hpp; thesis eq. 2.58-2.64):
//   P = B ((rho/(eps rho0))^gamma - 1),  c^2 = dP/drho = gamma B/(eps rho0) (rho/(eps
//   rho0))^(gamma-1), B = rho0 c0^2 / gamma,  c0 = 10 u_max  =>  |delta rho|/rho ~ u^2/c^2 <= 1 %.
#include "sph/equation_of_state.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace {

using sphdem::TaitEquationOfState;

constexpr double kEpsMach = std::numeric_limits<double>::epsilon();
constexpr double kRho0 = 1000.0;
constexpr int kGamma = 7;

// eq. 2.58 written out with std::pow
double tait_pressure(double B, double rho, double eps) {
  return B * (std::pow(rho / (eps * kRho0), kGamma) - 1.0);
}

TaitEquationOfState water(double c0) {
  return TaitEquationOfState::from_sound_speed(kRho0, c0, kGamma);
}

const double kVoidages[] = {1.0, 0.9, 0.6, 0.35};

TEST(TaitEos, ZeroPressureAtReferenceSuperficialDensity) {
  const auto eos = water(1.0);
  for (double eps : kVoidages) {
    // rho/(eps rho0) is 1 up to one rounding: |P| <= gamma B eps_mach
    EXPECT_NEAR(eos.pressure(kRho0 * eps, eps), 0.0, kGamma * eos.B * kEpsMach) << "eps = " << eps;
  }
}

TEST(TaitEos, PressureMatchesStdPow) {
  const auto eos = water(2.4);
  for (double eps : kVoidages)
    for (double ratio : {0.95, 0.99, 1.001, 1.01, 1.05, 1.3}) {
      const double rho = ratio * eps * kRho0;
      const double expected = tait_pressure(eos.B, rho, eps);
      // repeated multiplication vs pow: ~7 roundings of ratio^7, each relative eps_mach
      const double scale = eos.B * std::pow(ratio, kGamma);
      EXPECT_NEAR(eos.pressure(rho, eps), expected, 16 * kEpsMach * scale)
          << "eps = " << eps << " ratio " << ratio;
    }
}

TEST(TaitEos, SoundSpeedSquaredIsPressureDerivative) {
  const auto eos = water(1.0);
  for (double eps : kVoidages)
    for (double ratio : {0.98, 1.0, 1.02, 1.2}) {
      const double rho = ratio * eps * kRho0, d = 1e-5 * rho;
      const double fd =
          (tait_pressure(eos.B, rho + d, eps) - tait_pressure(eos.B, rho - d, eps)) / (2 * d);
      const double c = eos.sound_speed(rho, eps);
      // central difference: truncation (d/rho)^2 gamma^2/6 ~ 1e-9; round-off eps_mach/1e-5 ~ 2e-11
      EXPECT_NEAR(c * c, fd, 1e-8 * fd) << "eps = " << eps << " ratio " << ratio;
      // and the closed form c^2 = gamma B/(eps rho0) ratio^(gamma-1), eq. 2.59
      const double c2 = kGamma * eos.B / (eps * kRho0) * std::pow(ratio, kGamma - 1);
      EXPECT_NEAR(c * c, c2, 32 * kEpsMach * c2);  // a handful of roundings
    }
}

TEST(TaitEos, DensityInvertsPressure) {
  const auto eos = water(1.7);
  for (double eps : kVoidages)
    for (double ratio : {0.97, 1.0, 1.004, 1.08}) {
      const double rho = ratio * eps * kRho0;
      const double P = eos.pressure(rho, eps);
      // drho/rho = dP/(gamma (P + B)): P's few-ulp error of B ratio^7 becomes < eps_mach,
      // plus the roundings of pow and the products: 16 eps_mach
      EXPECT_NEAR(eos.density(P, eps), rho, 16 * kEpsMach * rho)
          << "eps = " << eps << " ratio " << ratio;
    }
  // and the other way round, against the inverse written out independently
  for (double P : {-50.0, 0.0, 3.0, 58.9, 400.0}) {
    const double rho = eos.density(P, 0.8);
    EXPECT_NEAR(rho, 0.8 * kRho0 * std::pow(1.0 + P / eos.B, 1.0 / kGamma),
                4 * kEpsMach * rho);  // same formula
    // rho's relative error eps_mach becomes gamma eps_mach of (P + B) in P
    EXPECT_NEAR(eos.pressure(rho, 0.8), P, 32 * kEpsMach * (std::abs(P) + eos.B));
  }
}

TEST(TaitEos, FromSoundSpeed) {
  for (double c0 : {0.1, 1.0, 2.4, 30.0}) {
    const auto eos = water(c0);
    EXPECT_EQ(eos.rho0, kRho0);
    EXPECT_EQ(eos.gamma, kGamma);
    const double B = kRho0 * c0 * c0 / kGamma;
    EXPECT_NEAR(eos.B, B, 4 * kEpsMach * B);  // eq. 2.63-2.64, a few roundings
    EXPECT_NEAR(eos.sound_speed(kRho0, 1.0), c0, 4 * kEpsMach * c0);
    // at voidage eps the reference state is rho = eps rho0 and c^2 = gamma B/(eps rho0) = c0^2/eps
    EXPECT_NEAR(eos.sound_speed(0.6 * kRho0, 0.6), c0 / std::sqrt(0.6), 8 * kEpsMach * c0);
  }
}

// 1 % rule (eq. 2.60-2.64): with c0 = 10 u_m, a pressure rho0 u^2 (twice the dynamic
// pressure, an upper bound for stagnation) changes the density by ~u^2/c0^2 = 1 %.
TEST(TaitEos, OnePercentDensityRule) {
  const double u_m = 0.01;  // thesis settling-speed scale (m/s)
  const double c0 = 10.0 * u_m;
  const auto eos = water(c0);
  EXPECT_NEAR(eos.B, 100.0 * kRho0 * u_m * u_m / kGamma, 1e-12 * eos.B);  // eq. 2.64
  for (double u : {0.25 * u_m, 0.5 * u_m, u_m}) {
    const double P_dyn = 0.5 * kRho0 * u * u;  // Bernoulli
    for (double eps : {1.0, 0.85}) {
      const double rel = eos.density(P_dyn, eps) / (eps * kRho0) - 1.0;
      // linearised: delta rho/rho = P/(rho c^2) = u^2/(2 c0^2); the quadratic Taylor term of
      // (1+x)^(1/7), 3/49 x^2 with x = 7 u^2/(2 c0^2) <= 0.035, bounds the difference (7.5e-5).
      EXPECT_NEAR(rel, u * u / (2 * c0 * c0),
                  3.0 / 49.0 * std::pow(kGamma * u * u / (2 * c0 * c0), 2) * 1.01);
      EXPECT_GT(rel, 0.0);
    }
    const double rel_stag = eos.density(kRho0 * u * u, 1.0) / kRho0 - 1.0;
    EXPECT_LE(rel_stag, 0.01) << "u = " << u;  // the < 1 % promise of eq. 2.60
  }
  // a faster flow breaks the promise: u = 1.5 u_m gives > 2 %
  EXPECT_GT(eos.density(kRho0 * std::pow(1.5 * u_m, 2), 1.0) / kRho0 - 1.0, 0.02);
}

}  // namespace
