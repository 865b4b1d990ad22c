#pragma once
// Normal contact: linear spring-dashpot (Luding 1998; thesis eq. 2.36)
//   force on i = (k delta + beta d(delta)/dt) n_ij,  n_ij from j to i, delta > 0 overlap,
// with the closed forms of the damped oscillator it produces (2.41-2.47).
#include <cmath>

namespace sphdem {

struct LinearSpringDashpot {
  double k = 0.0;                // spring stiffness (N/m)
  double beta = 0.0;             // dashpot (kg/s); used when restitution < 0
  double restitution = -1.0;     // if in (0,1]: beta chosen per contact from m12 (LIGGGHTS style)
  bool clip_attraction = false;  // true: normal force never pulls (LAMMPS gran/hooke)

  // With a restitution, beta = 2 m12 eta, eta = a omega0 / sqrt(1 + a^2), a = -ln(e)/pi
  // (2.46), omega0 = sqrt(k/m12): beta = beta_factor() sqrt(k m12). The factor is the
  // same for every contact, so a contact pass takes it once (a log and a square root)
  // and pays one square root per contact. Negative: the fixed dashpot 'beta'.
  double beta_factor() const {
    if (restitution <= 0.0) return -1.0;
    if (restitution >= 1.0) return 0.0;
    const double a = -std::log(restitution) / M_PI;  // eta/omega
    return 2.0 * a / std::sqrt(1.0 + a * a);
  }
  // Dashpot for a pair of reduced mass m12, given beta_factor().
  double beta_for(double m12, double factor) const {
    return factor < 0.0 ? beta : factor * std::sqrt(k * m12);
  }
  double beta_for(double m12) const { return beta_for(m12, beta_factor()); }
  // Scalar normal force (positive = repulsive) for overlap delta and overlap rate ddelta.
  double normal_force(double delta, double ddelta, double beta_pair) const {
    const double f = k * delta + beta_pair * ddelta;
    return (clip_attraction && f < 0.0) ? 0.0 : f;
  }
};

// Closed forms of one contact of reduced mass m12 (eq. 2.41-2.47).
struct ContactClosedForm {
  double omega0, eta, omega;
  ContactClosedForm(double k, double beta, double m12)
      : omega0(std::sqrt(k / m12)),
        eta(beta / (2.0 * m12)),
        omega(std::sqrt(omega0 * omega0 - eta * eta)) {}
  double contact_time() const { return M_PI / omega; }                  // (2.44)
  double restitution() const { return std::exp(-M_PI * eta / omega); }  // (2.46)
  double max_overlap(double v0) const {                                 // (2.47)
    return v0 / omega0 * std::exp(-eta / omega * std::asin(omega / omega0));
  }
};

}  // namespace sphdem
