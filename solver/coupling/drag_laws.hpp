#pragma once
// Drag laws: force on a sphere of diameter d from the superficial slip velocity
// u_s = eps (u_f - v) (eq. 2.74), Re_p = rho_f |u_s| d / mu. Each law is a small
// struct with an inline evaluator; a pass is templated on the law and the runtime
// choice (DragLaw) is resolved once per pass, never per particle.
#include <algorithm>
#include <cmath>
#include <string>
#include <variant>

namespace sphdem::drag {

struct Fluid {
  double rho;  // fluid (not superficial) density
  double mu;   // dynamic viscosity
};

// Scalar c such that f_d = c * u_s. All laws reduce to this form.
inline double reynolds(double us_mag, double d, const Fluid& f) { return f.rho * us_mag * d / f.mu; }

// Di Felice (1994) voidage exponent, eq. 2.79.
inline double di_felice_xi(double re) {
  const double l = 1.5 - std::log10(re);
  return 3.7 - 0.65 * std::exp(-0.5 * l * l);
}
// Re floor: the laws below are finite as Re -> 0 but their pieces are not.
inline constexpr double kMinRe = 1e-12;

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
    const double re = std::max(reynolds(us, d, f), kMinRe);
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
    const double re = std::max(reynolds(us, d, f), kMinRe);
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
    const double re = std::max(reynolds(us, d, f), kMinRe);
    // |u_s| C_d = 24 mu/(rho d) (1 + 0.15 Re^0.681) + |u_s| 0.407/(1 + 8710/Re)
    const double us_cd = 24.0 * f.mu / (f.rho * d) * (1.0 + 0.150 * std::pow(re, 0.681)) +
                         us * 0.407 / (1.0 + 8710.0 / re);
    return 0.125 * us_cd * std::pow(eps, -di_felice_xi(re)) * M_PI * d * d * f.rho;
  }
};

using DragLaw = std::variant<Stokes, DiFeliceDallavalle, CoulsonRichardson, BrownLawler>;

// The one registry of drag-law names used by scene files.
inline const char* const kDragLawNames[] = {"stokes", "di_felice", "coulson_richardson",
                                            "brown_lawler"};
inline bool drag_law_from_name(const std::string& name, DragLaw& out) {
  if (name == "stokes") out = Stokes{};
  else if (name == "di_felice") out = DiFeliceDallavalle{};
  else if (name == "coulson_richardson") out = CoulsonRichardson{};
  else if (name == "brown_lawler") out = BrownLawler{};
  else return false;
  return true;
}
inline std::string drag_law_name(const DragLaw& law) { return kDragLawNames[law.index()]; }

}  // namespace sphdem::drag
