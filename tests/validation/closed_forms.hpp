#pragma once
// Closed-form references of the validation scenes, written out independently of the
// solver's drag-law code so that a test compares two separate implementations.
#include <cmath>
#include <functional>

namespace sphdem::theory {

// Stokes settling of one sphere from rest (thesis eq. 4.1):
//   v(t) = (rho_p - rho_f) V g / b (1 - exp(-t/t_d)),  b = 3 pi mu d,  t_d = m / b.
struct StokesSettling {
  double v_terminal, t_relax;
  StokesSettling(double d, double rho_p, double rho_f, double mu, double g) {
    const double V = M_PI * d * d * d / 6.0, b = 3.0 * M_PI * mu * d;
    v_terminal = (rho_p - rho_f) * V * g / b;
    t_relax = rho_p * V / b;
  }
  double speed(double t) const { return v_terminal * (1.0 - std::exp(-t / t_relax)); }
};

// Root of f on [a, b] by bisection (f(a), f(b) of opposite sign).
inline double bisect(const std::function<double(double)>& f, double a, double b) {
  double fa = f(a);
  for (int k = 0; k < 200; ++k) {
    const double m = 0.5 * (a + b), fm = f(m);
    if ((fm < 0) == (fa < 0)) {
      a = m;
      fa = fm;
    } else {
      b = m;
    }
  }
  return 0.5 * (a + b);
}

// Terminal superficial slip of a constant-porosity block under Di Felice-Dallavalle
// drag (thesis eq. 4.2-4.4):
//   (rho_p - rho_av) V g = (1/8) C_d eps^-xi pi d^2 rho_f v^2,  rho_av = eps rho_f + (1-eps) rho_p,
//   C_d = (0.63 + 4.8/sqrt(Re))^2, xi = 3.7 - 0.65 exp(-(1.5 - log10 Re)^2 / 2), Re = rho_f v d / mu.
inline double di_felice_block_slip(double d, double rho_p, double rho_f, double mu, double g, double eps) {
  const double V = M_PI * d * d * d / 6.0;
  const double rho_av = eps * rho_f + (1.0 - eps) * rho_p;
  const double weight = (rho_p - rho_av) * V * g;
  auto balance = [&](double v) {
    const double re = rho_f * v * d / mu;
    const double cd = std::pow(0.63 + 4.8 / std::sqrt(re), 2);
    const double xi = 3.7 - 0.65 * std::exp(-0.5 * std::pow(1.5 - std::log10(re), 2));
    return 0.125 * cd * std::pow(eps, -xi) * M_PI * d * d * rho_f * v * v - weight;
  };
  return bisect(balance, 1e-9, 10.0);
}

// Peak excess pore pressure at the base of a settling suspension, normalised by the
// hydrostatic pressure rho_f g H (Zhao, Houlsby & Utili 2014, eq. 15): once the whole
// suspension of porosity n filling the column is carried by the fluid, the base carries
// its total weight, (n rho_f + (1 - n) rho_s) g H, so
//   u_max / (rho_f g H) = (1 - n)(rho_s / rho_f - 1).
inline double peak_excess_pore_pressure(double porosity, double rho_s, double rho_f) {
  return (1.0 - porosity) * (rho_s / rho_f - 1.0);
}

}  // namespace sphdem::theory
