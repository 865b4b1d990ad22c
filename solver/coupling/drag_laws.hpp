#pragma once
// Drag laws: force on a sphere of diameter d from the superficial slip velocity
// u_s = eps (u_f - v) (eq. 2.74), Re_p = rho_f |u_s| d / mu. Each law is a small
// struct with an inline evaluator; a pass is templated on the law and the runtime
// choice (DragLaw, coupling/drag_law_table.hpp) is resolved once per pass, never per
// particle.
#include <algorithm>
#include <cmath>

namespace sphdem::drag {

struct Fluid {
  double rho;  // fluid (not superficial) density
  double mu;   // dynamic viscosity
};

// Scalar c such that f_d = c * u_s. All laws reduce to this form.
inline double reynolds(double us_mag, double d, const Fluid& f) {
  return f.rho * us_mag * d / f.mu;
}

// Di Felice (1994) voidage exponent, eq. 2.79.
inline double di_felice_xi(double re) {
  const double l = 1.5 - std::log10(re);
  return 3.7 - 0.65 * std::exp(-0.5 * l * l);
}
// Re floor: the laws below are finite as Re -> 0 but their pieces are not. (By value, as
// std::max would be with a NaN: a reference to the constant keeps a loop out of lanes.)
inline constexpr double kMinRe = 1e-12;
inline double floored_reynolds(double re) {
  return re < kMinRe ? kMinRe : re;
}

// Stokes, eq. 2.73: f = 3 pi mu d u_s.
struct Stokes {
  double coefficient(double /*eps*/, double /*us*/, double d, const Fluid& f) const {
    return 3.0 * M_PI * f.mu * d;
  }
};

// Di Felice with Dallavalle's C_d, eq. 2.76-2.79:
//   f = (1/8) C_d eps^-xi pi d^2 rho |u_s| u_s,  C_d = (0.63 + 4.8/sqrt(Re))^2.
struct DiFeliceDallavalle {
  static double cd(double re) {
    const double s = 0.63 + 4.8 / std::sqrt(re);
    return s * s;
  }
  double coefficient(double eps, double us, double d, const Fluid& f) const {
    const double re = floored_reynolds(reynolds(us, d, f));
    // |u_s| C_d written as (0.63 sqrt|u_s| + 4.8 sqrt(mu/(rho d)))^2 stays finite at u_s = 0.
    const double s = 0.63 * std::sqrt(us) + 4.8 * std::sqrt(f.mu / (f.rho * d));
    return 0.125 * s * s * std::pow(eps, -di_felice_xi(re)) * M_PI * d * d * f.rho;
  }
};

// Coulson & Richardson, single sphere over a wide Re range (thesis 2.75, with the
// |u_s| u_s the thesis drops): f = (pi/4) d^2 rho |u_s| u_s (1.84 Re^-0.31 + 0.293 Re^0.06)^3.45.
// The bracket^3.45 is R'/(rho u^2) = C_d/2; at Re -> 0 it gives 8.2 Re^-1.07, i.e. it
// falls 6 % below Stokes at Re = 0.01 (a property of the correlation, not a bug).
struct CoulsonRichardson {
  double coefficient(double /*eps*/, double us, double d, const Fluid& f) const {
    const double re = floored_reynolds(reynolds(us, d, f));
    const double b = std::pow(1.84 * std::pow(re, -0.31) + 0.293 * std::pow(re, 0.06), 3.45);
    // |u_s| = Re mu/(rho d) keeps the product finite as u_s -> 0.
    return 0.25 * M_PI * d * d * f.rho * (re * f.mu / (f.rho * d)) * b;
  }
};

// Brown & Lawler (2003) C_d with Di Felice's voidage function (Zhao et al. 2014):
//   C_d = 24/Re (1 + 0.150 Re^0.681) + 0.407 / (1 + 8710/Re).
struct BrownLawler {
  static double cd(double re) {
    return 24.0 / re * (1.0 + 0.150 * std::pow(re, 0.681)) + 0.407 / (1.0 + 8710.0 / re);
  }
  double coefficient(double eps, double us, double d, const Fluid& f) const {
    const double re = floored_reynolds(reynolds(us, d, f));
    // |u_s| C_d = 24 mu/(rho d) (1 + 0.15 Re^0.681) + |u_s| 0.407/(1 + 8710/Re)
    const double us_cd = 24.0 * f.mu / (f.rho * d) * (1.0 + 0.150 * std::pow(re, 0.681)) +
                         us * 0.407 / (1.0 + 8710.0 / re);
    return 0.125 * us_cd * std::pow(eps, -di_felice_xi(re)) * M_PI * d * d * f.rho;
  }
};

// Polydisperse drag of Beetstra, van der Hoef & Kuipers (2007) with the size correction
// of the thesis (2.80-2.88), written for sphere i of diameter d in a mixture whose local
// Sauter mean diameter is <d> (2.80):
//   <Re> = rho <d> |u_s| / mu (2.81),  y = d / <d> (2.82),  phi = 1 - eps,
//   f_mono = 10 phi/eps^2 + eps^2 (1 + 1.5 sqrt(phi))
//            + 0.413 <Re> / (24 eps^2) (1/eps + 3 eps phi + 8.4 <Re>^-0.343)
//                                     / (1 + 10^(3 phi) <Re>^(-(1 + 4 phi)/2))   (2.85-2.86)
//   beta = (1/eps) [1/f_mono + ((3 eps - 1)/2 - 1/f_mono) y + (1 - eps) y^2 / 2]  (2.88)
//   f_d = beta f_mono 3 pi mu d u_s                                              (2.83-2.87)
// beta = 1 for a monodisperse suspension (y = 1), and f_d -> Stokes as eps -> 1, Re -> 0.
struct BeetstraPolydisperse {
  static double f_mono(double eps, double re) {
    const double phi = 1.0 - eps, e2 = eps * eps;
    const double low = 10.0 * phi / e2 + e2 * (1.0 + 1.5 * std::sqrt(phi));
    const double num = 1.0 / eps + 3.0 * eps * phi + 8.4 * std::pow(re, -0.343);
    const double den = 1.0 + std::pow(10.0, 3.0 * phi) * std::pow(re, -0.5 * (1.0 + 4.0 * phi));
    return low + 0.413 * re / (24.0 * e2) * num / den;
  }
  static double beta(double eps, double f, double y) {
    return ((1.0 / f) + ((3.0 * eps - 1.0) / 2.0 - 1.0 / f) * y + 0.5 * (1.0 - eps) * y * y) / eps;
  }
  double coefficient(double eps, double us, double d, double d_sauter, const Fluid& fl) const {
    const double re = floored_reynolds(reynolds(us, d_sauter, fl));
    const double f = f_mono(eps, re);
    return beta(eps, f, d / d_sauter) * f * 3.0 * M_PI * fl.mu * d;
  }
  // a sphere in a monodisperse suspension: <d> = d
  double coefficient(double eps, double us, double d, const Fluid& fl) const {
    return coefficient(eps, us, d, d, fl);
  }
};

// Rong, Dong & Yu (2013), from lattice-Boltzmann flow through packed beds: Di Felice's
// form with a voidage exponent that depends on the voidage too,
//   f = (1/8) C_d eps^-beta pi d^2 rho |u_s| u_s,  C_d = (0.63 + 4.8/sqrt(Re))^2,
//   beta = 2.65 (eps + 1) - (5.3 - 3.5 eps) eps^2 exp(-(1.5 - log10 Re)^2 / 2).
struct RongDongYu {
  static double beta(double eps, double re) {
    const double l = 1.5 - std::log10(re);
    return 2.65 * (eps + 1.0) - (5.3 - 3.5 * eps) * eps * eps * std::exp(-0.5 * l * l);
  }
  double coefficient(double eps, double us, double d, const Fluid& f) const {
    const double re = floored_reynolds(reynolds(us, d, f));
    const double s = 0.63 * std::sqrt(us) + 4.8 * std::sqrt(f.mu / (f.rho * d));
    return 0.125 * s * s * std::pow(eps, -beta(eps, re)) * M_PI * d * d * f.rho;
  }
};

// Tenneti, Garg & Subramaniam (2011), from particle-resolved simulation of fixed random
// arrays (phi = 1 - eps in 0.1-0.5, Re 0.01-300). Their F is the whole fluid force over
// 3 pi mu d u_s, the mean pressure gradient's share included; the drag proper, which the
// solver adds to -V grad p, is eps F of it (in a periodic array n F_tot = -grad p and
// eps (-grad p) = n f_drag):
//   F = (1 + 0.15 Re^0.687)/eps^3 + 5.81 phi/eps^3 + 0.48 phi^(1/3)/eps^4
//       + phi^3 Re (0.95 + 0.61 phi^3/eps^2),   f = eps F 3 pi mu d u_s.
struct TennetiGargSubramaniam {
  static double total_force(double eps, double re) {
    const double phi = 1.0 - eps, e3 = eps * eps * eps, p3 = phi * phi * phi;
    return (1.0 + 0.15 * std::pow(re, 0.687)) / e3 + 5.81 * phi / e3 +
           0.48 * std::cbrt(phi) / (e3 * eps) + p3 * re * (0.95 + 0.61 * p3 / (eps * eps));
  }
  double coefficient(double eps, double us, double d, const Fluid& f) const {
    const double re = floored_reynolds(reynolds(us, d, f));
    return eps * total_force(eps, re) * 3.0 * M_PI * f.mu * d;
  }
};

// Koch & Hill (Hill, Koch & Ladd 2001, lattice-Boltzmann random arrays) as Benyahia,
// Syamlal & O'Brien (2006) extended it to every phi and Re (MFiX's form). Re_h = Re/2 is
// their radius-based number, phi = 1 - eps, w = exp(-10 (0.4 - phi)/phi):
//   F0 = (1 - w) (1 + 3 sqrt(phi/2) + (135/64) phi ln phi + 17.14 phi)
//                / (1 + 0.681 phi - 8.48 phi^2 + 8.16 phi^3) + w 10 phi/eps^3   (phi < 0.4)
//   F1 = sqrt(2/phi)/40 (phi <= 0.1), 0.11 + 5.1e-4 exp(11.6 phi) (phi > 0.1)
//   F2 = as F0 with 17.89, 11.03, 15.41                                           (phi < 0.4)
//   F0 = F2 = 10 phi/eps^3                                                        (phi >= 0.4)
//   F3 = 0.9351 phi + 0.03667 (phi < 0.0953), 0.0673 + 0.212 phi + 0.0232/eps^5
//   F = 1 + 3 Re_h/8 (phi <= 0.01, Re_h <= (F2 - 1)/(3/8 - F3)), F0 + F1 Re_h^2
//       (phi > 0.01, Re_h up to where it meets F2 + F3 Re_h), else F2 + F3 Re_h;
// F is the whole force over 3 pi mu d u_s, as Tenneti's: f = eps F 3 pi mu d u_s.
struct KochHill {
  static double blend(double phi, double a, double b, double c) {  // F0 (a, b, c) or F2
    const double w = std::exp(-10.0 * (0.4 - phi) / phi),
                 dense = 10.0 * phi / std::pow(1.0 - phi, 3);
    if (phi >= 0.4) return dense;
    const double phi_ln_phi = phi > 0.0 ? phi * std::log(phi) : 0.0;
    const double dilute = (1.0 + 3.0 * std::sqrt(0.5 * phi) + 135.0 / 64.0 * phi_ln_phi + a * phi) /
                          (1.0 + 0.681 * phi - b * phi * phi + c * phi * phi * phi);
    return (1.0 - w) * dilute + w * dense;
  }
  static double total_force(double eps, double re) {
    const double phi = 1.0 - eps, re_h = 0.5 * re;
    const double f0 = blend(phi, 17.14, 8.48, 8.16), f2 = blend(phi, 17.89, 11.03, 15.41);
    const double f3 =
        phi < 0.0953 ? 0.9351 * phi + 0.03667 : 0.0673 + 0.212 * phi + 0.0232 / std::pow(eps, 5);
    if (phi <= 0.01) return re_h <= (f2 - 1.0) / (0.375 - f3) ? 1.0 + 0.375 * re_h : f2 + f3 * re_h;
    const double f1 =
        phi <= 0.1 ? std::sqrt(2.0 / phi) / 40.0 : 0.11 + 5.1e-4 * std::exp(11.6 * phi);
    const double re_meet = (f3 + std::sqrt(f3 * f3 - 4.0 * f1 * (f0 - f2))) / (2.0 * f1);
    return re_h <= re_meet ? f0 + f1 * re_h * re_h : f2 + f3 * re_h;
  }
  double coefficient(double eps, double us, double d, const Fluid& f) const {
    const double re = floored_reynolds(reynolds(us, d, f));
    return eps * total_force(eps, re) * 3.0 * M_PI * f.mu * d;
  }
};

// No drag: the fluid and the spheres exchange only the pressure (and, interpolated, the
// viscous) forces. A measuring device, not a physical law: the fluid's own viscous
// operator at eps < 1 among fixed spheres (viscosity_validation), which the drag of a
// packed bed would otherwise swamp by three orders of magnitude.
struct NoDrag {
  double coefficient(double /*eps*/, double /*us*/, double /*d*/, const Fluid& /*f*/) const {
    return 0.0;
  }
};

// Drag coefficient of sphere of diameter d where the local Sauter mean is d_sauter: the
// polydisperse law uses it, the single-sphere laws do not.
template <class Law>
inline double drag_coefficient(const Law& law, double eps, double us, double d, double /*d_sauter*/,
                               const Fluid& fl) {
  return law.coefficient(eps, us, d, fl);
}
inline double drag_coefficient(const BeetstraPolydisperse& law, double eps, double us, double d,
                               double d_sauter, const Fluid& fl) {
  return law.coefficient(eps, us, d, d_sauter > 0.0 ? d_sauter : d, fl);
}
}  // namespace sphdem::drag
