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

// Terminal speed of one sphere in clear fluid under Brown & Lawler's (2003) C_d:
//   (rho_p - rho_f) V g = (1/8) C_d pi d^2 rho_f v^2,
//   C_d = 24/Re (1 + 0.150 Re^0.681) + 0.407 / (1 + 8710/Re),  Re = rho_f v d / mu.
inline double brown_lawler_terminal(double d, double rho_p, double rho_f, double mu, double g) {
  const double weight = (rho_p - rho_f) * M_PI * d * d * d / 6.0 * g;
  auto f = [&](double v) {
    const double re = rho_f * v * d / mu;
    const double cd = 24.0 / re * (1.0 + 0.150 * std::pow(re, 0.681)) + 0.407 / (1.0 + 8710.0 / re);
    return 0.125 * cd * M_PI * d * d * rho_f * v * v - weight;
  };
  return bisect(f, 1e-9, 100.0);
}

// Terminal superficial slip of a constant-porosity block under Di Felice-Dallavalle
// drag (thesis eq. 4.2-4.4):
//   (rho_p - rho_av) V g = (1/8) C_d eps^-xi pi d^2 rho_f v^2,  rho_av = eps rho_f + (1-eps) rho_p,
//   C_d = (0.63 + 4.8/sqrt(Re))^2, xi = 3.7 - 0.65 exp(-(1.5 - log10 Re)^2 / 2), Re = rho_f v d /
//   mu.
inline double di_felice_block_slip(double d, double rho_p, double rho_f, double mu, double g,
                                   double eps) {
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

// Beetstra, van der Hoef & Kuipers (2007) monodisperse drag factor (thesis 2.85-2.86),
// F = f_mono 3 pi mu d u_s, at voidage eps and Reynolds number Re = rho_f d |u_s| / mu.
// Richardson & Zaki (1954): hindered settling and liquid fluidisation u = u_t eps^n with
// their exponent for a column much wider than the spheres (d/D -> 0),
//   n = 4.65 (Re_t < 0.2), 4.4 Re_t^-0.03 (< 1), 4.4 Re_t^-0.1 (< 500), 2.4 above,
// and Garside & Al-Dibouni's (1977), (5.1 - n)/(n - 2.7) = 0.1 Re_t^0.9. The two bound the
// experiments' band; Re_t = rho_f u_t d / mu of one sphere at its terminal speed u_t.
inline double richardson_zaki_n(double re_t) {
  if (re_t < 0.2) return 4.65;
  if (re_t < 1.0) return 4.4 * std::pow(re_t, -0.03);
  if (re_t < 500.0) return 4.4 * std::pow(re_t, -0.1);
  return 2.4;
}
inline double garside_al_dibouni_n(double re_t) {
  const double x = 0.1 * std::pow(re_t, 0.9);
  return (5.1 + 2.7 * x) / (1.0 + x);
}

inline double beetstra_f_mono(double eps, double re) {
  const double phi = 1.0 - eps;
  const double stokes = 10.0 * phi / (eps * eps) + eps * eps * (1.0 + 1.5 * std::sqrt(phi));
  const double inertial =
      0.413 * re / (24.0 * eps * eps) * (1.0 / eps + 3.0 * eps * phi + 8.4 * std::pow(re, -0.343)) /
      (1.0 + std::pow(10.0, 3.0 * phi) * std::pow(re, -(1.0 + 4.0 * phi) / 2.0));
  return stokes + inertial;
}

// Terminal superficial slip of a bidisperse constant-porosity block (thesis eq. 4.5):
//   u_T = (rho_p - rho_f) g <d>^2 / (18 mu [f_mono(eps, <Re>)/eps + (Sigma - 1)/eps^2]),
//   Sigma = sum_i x_i / y_i^2,  y_i = d_i / <d>,  <d> = 1 / sum_i (x_i / d_i) (Sauter),
// x_i the volume fractions (from the number fractions n_i: x_i ~ n_i d_i^3). It is the
// block's force balance, sum_i N_i eps (rho_p - rho_f) V_i g = sum_i N_i F_i, with
// F_i = beta_i f_mono 3 pi mu d_i u of (2.88): sum_i x_i/y_i = 1 collapses the sum to (4.5).
inline double bidisperse_block_slip(double d1, double d2, double n1, double rho_p, double rho_f,
                                    double mu, double g, double eps) {
  const double n2 = 1.0 - n1;
  const double v1 = n1 * d1 * d1 * d1, v2 = n2 * d2 * d2 * d2;
  const double x1 = v1 / (v1 + v2), x2 = v2 / (v1 + v2);
  const double dm = 1.0 / (x1 / d1 + x2 / d2);
  const double y1 = d1 / dm, y2 = d2 / dm;
  const double sigma = x1 / (y1 * y1) + x2 / (y2 * y2);
  auto residual = [&](double u) {
    const double re = rho_f * dm * u / mu;
    return u - (rho_p - rho_f) * g * dm * dm /
                   (18.0 * mu * (beetstra_f_mono(eps, re) / eps + (sigma - 1.0) / (eps * eps)));
  };
  return bisect(residual, 1e-9, 1.0);
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
