#pragma once
// Tait equation of state with voidage (thesis eq. 2.58-2.59, 2.64):
//   P = B ((rho / (eps rho0))^gamma - 1),   c^2 = dP/drho.
// rho is the superficial density eps * rho_f carried by the SPH particle.
#include <cmath>

namespace sphdem {

struct TaitEquationOfState {
  double rho0 = 1000.0;  // reference fluid density
  double B = 0.0;        // pressure scale, B = rho0 c0^2 / gamma
  int gamma = 7;

  // B from the reference sound speed c0 (= 10 u_max, eq. 2.63-2.64).
  static TaitEquationOfState from_sound_speed(double rho0, double c0, int gamma) {
    return TaitEquationOfState{rho0, rho0 * c0 * c0 / gamma, gamma};
  }

  double ratio_pow(double ratio, int n) const {
    double r = 1.0;
    for (int k = 0; k < n; ++k) r *= ratio;
    return r;
  }
  double pressure(double rho, double eps) const {
    return B * (ratio_pow(rho / (eps * rho0), gamma) - 1.0);
  }
  double sound_speed(double rho, double eps) const {
    const double ref = eps * rho0;
    return std::sqrt(gamma * B / ref * ratio_pow(rho / ref, gamma - 1));
  }
  // Inverse: superficial density that gives pressure P at voidage eps.
  double density(double P, double eps) const {
    return eps * rho0 * std::pow(1.0 + P / B, 1.0 / gamma);
  }
};

}  // namespace sphdem
