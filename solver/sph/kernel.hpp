#pragma once
// Wendland C2 kernel in 3-D with support 2h (physics.md §1; the thesis' eq. 2.11
// writes the same function with support h):
//   W(r,h) = 21/(16 pi h^3) (1 - q/2)^4 (2q + 1),  q = r/h <= 2.
// The *_q forms take q = r/h and 1/h (one square root per pair, shared by callers);
// the r2 forms are the convenient versions. Branch-free: beyond the support the factor
// (1 - q/2) is clamped to 0, so the pair loops that call them vectorise.
#include <algorithm>
#include <cmath>

namespace sphdem::kernel {

inline constexpr double kNorm = 21.0 / (16.0 * M_PI);
inline constexpr double kSupport = 2.0;  // support radius in units of h

// max(1 - q/2, 0): zero at and beyond the support.
inline double support_factor(double q) {
  return std::max(1.0 - 0.5 * q, 0.0);
}

inline double w_q(double q, double inv_h) {
  const double t = support_factor(q), t2 = t * t;
  return kNorm * inv_h * inv_h * inv_h * t2 * t2 * (2.0 * q + 1.0);
}
// grad_a W(r_a - r_b, h) = grad_factor * (r_a - r_b);  dW/dr = -5 C q (1-q/2)^3 / h^4.
inline double grad_factor_q(double q, double inv_h) {
  const double t = support_factor(q), ih2 = inv_h * inv_h;
  return -5.0 * kNorm * t * t * t * ih2 * ih2 * inv_h;
}
// dW/dh at fixed r: -(1/h) (3 W + r dW/dr)  (the grad-h term Omega, eq. 2.54).
inline double dw_dh_q(double q, double inv_h) {
  const double t = support_factor(q), t3 = t * t * t, ih2 = inv_h * inv_h;
  return -kNorm * ih2 * ih2 * (3.0 * t3 * t * (2.0 * q + 1.0) - 5.0 * q * q * t3);
}

inline double w(double r2, double h) {
  return w_q(std::sqrt(r2) / h, 1.0 / h);
}
inline double grad_factor(double r2, double h) {
  return grad_factor_q(std::sqrt(r2) / h, 1.0 / h);
}
inline double dw_dh(double r2, double h) {
  return dw_dh_q(std::sqrt(r2) / h, 1.0 / h);
}

}  // namespace sphdem::kernel
