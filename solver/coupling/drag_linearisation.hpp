#pragma once
// The drag's linearised rate. A law's f = c(|u_s|) u_s is linear in the slip only in the
// Stokes limit; along the slip it changes by
//   d|f|/d|u_s| = c (1 + d ln c / d ln |u_s|)
// which is c at Re -> 0 and up to 2c in Newton's regime (Di Felice's at Re = 1000: 1.9 c).
// A step bounded by the secant rate c eps / m would be that much past its margin there,
// so the fluid's drag exchange (coupling/drag_exchange.hpp) takes this rate, per law,
// by a central difference in |u_s| (the laws are smooth in Re; no law carries its own
// derivative).
#include <cmath>

#include "coupling/drag_laws.hpp"

namespace sphdem::drag {

// Relative step of the central difference: its truncation error is O(1e-6) of the rate,
// its round-off O(1e-13 / 1e-3).
inline constexpr double kLinearisationStep = 1e-3;

// d|f|/d|u_s| of sphere d (local Sauter mean d_sauter) at voidage eps and slip |u_s| = us;
// at us = 0 the law's own coefficient (the Stokes limit, where f is linear).
template <class Law>
inline double linearised_coefficient(const Law& law, double eps, double us, double d,
                                     double d_sauter, const Fluid& fl) {
  if (!(us > 0.0)) return drag_coefficient(law, eps, us, d, d_sauter, fl);
  const double up = us * (1.0 + kLinearisationStep), down = us * (1.0 - kLinearisationStep);
  const double f_up = drag_coefficient(law, eps, up, d, d_sauter, fl) * up;
  const double f_down = drag_coefficient(law, eps, down, d, d_sauter, fl) * down;
  return (f_up - f_down) / (up - down);
}

}  // namespace sphdem::drag
