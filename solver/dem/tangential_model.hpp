#pragma once
// Tangential contact laws (the second part of a contact, contact_registry.hpp).
//
// NoTangential: frictionless (the default; no history, no rotation).
//
// LinearHistoryTangential: a linear spring on the elastic tangential displacement xi,
// with a viscous damper and the Coulomb limit, as Luding (2008, "Cohesive, frictional
// powders: contact models for tension", Granular Matter 10:235, §2.2) and LAMMPS
// gran/hooke/history / LIGGGHTS `tangential history`:
//   xi  <- xi rotated into the current tangent plane (projected, length kept)
//   xi  <- xi + v_t dt                                   v_t: tangential contact velocity
//   F_t  = -k_t xi - gamma_t v_t                         (force on the first sphere)
//   if |F_t| > mu |F_n|:  F_t <- mu |F_n| F_t/|F_t|,  xi <- -(F_t + gamma_t v_t)/k_t
// so |F_t| <= mu |F_n| always, and a sliding contact keeps its spring at the limit
// (it sticks again as soon as the spring alone can carry the load).
// k_t = stiffness_ratio k_n; the default 2/7 makes a sticking contact of two solid
// spheres oscillate at the normal frequency (its tangential mass is 2/7 m12).
#include <cmath>

namespace sphdem {

// What a scene gives for the tangential part (contact.tangential).
struct TangentialParams {
  enum class Model { kNone, kLinearHistory };
  Model model = Model::kNone;
  double stiffness_ratio = 2.0 / 7.0;  // k_t / k_n
  double damping = 0.0;                // gamma_t (kg/s); used when restitution <= 0
  double restitution = -1.0;           // if in (0,1]: gamma_t per contact from m12 (see below)
  double friction = 0.0;               // Coulomb coefficient mu
};

struct NoTangential {
  static constexpr bool kEnabled = false;
};

struct LinearHistoryTangential {
  static constexpr bool kEnabled = true;
  double k_t = 0.0;  // N/m
  double mu = 0.0;
  double gamma = 0.0;              // kg/s, when not restitution-based
  double gamma_per_sqrt_m = -1.0;  // >= 0: gamma_t = this * sqrt(m12) (restitution given)

  LinearHistoryTangential() = default;
  LinearHistoryTangential(const TangentialParams& p, double k_n)
      : k_t(p.stiffness_ratio * k_n), mu(p.friction), gamma(p.damping) {
    if (p.restitution > 0.0) {
      // A sticking contact is a damped oscillator of mass m_t = 2/7 m12 (solid spheres,
      // lever arms = radii): gamma_t = 2 m_t eta_t with e_t = exp(-pi eta_t/omega_t), as the
      // normal restitution (2.46) with k_t and m_t in place of k and m12.
      const double a = p.restitution >= 1.0 ? 0.0 : -std::log(p.restitution) / M_PI;
      gamma_per_sqrt_m = 2.0 * a / std::sqrt(1.0 + a * a) * std::sqrt(k_t * 2.0 / 7.0);
    }
  }
  // Tangential dashpot for a contact of reduced mass m12 (the wall: m12 = m).
  double gamma_for(double m12) const {
    return gamma_per_sqrt_m >= 0.0 ? gamma_per_sqrt_m * std::sqrt(m12) : gamma;
  }

  // One step of the spring: rotates xi into the plane normal to n, adds v_t dt, and
  // returns the force ft on the first sphere; xi is left at the sliding limit if the
  // contact slides. fn_abs = |F_n|.
  void force(const double n[3], const double vt[3], double gamma_t, double fn_abs, double dt,
             double xi[3], double ft[3]) const {
    const double xx = xi[0] * xi[0] + xi[1] * xi[1] + xi[2] * xi[2];
    if (xx > 0.0) {
      const double xn = xi[0] * n[0] + xi[1] * n[1] + xi[2] * n[2];
      double px = xi[0] - xn * n[0], py = xi[1] - xn * n[1], pz = xi[2] - xn * n[2];
      const double pp = px * px + py * py + pz * pz;
      if (pp > 0.0) {
        const double scale = std::sqrt(xx / pp);
        px *= scale;
        py *= scale;
        pz *= scale;
      }
      xi[0] = px;
      xi[1] = py;
      xi[2] = pz;
    }
    xi[0] += vt[0] * dt;
    xi[1] += vt[1] * dt;
    xi[2] += vt[2] * dt;
    ft[0] = -k_t * xi[0] - gamma_t * vt[0];
    ft[1] = -k_t * xi[1] - gamma_t * vt[1];
    ft[2] = -k_t * xi[2] - gamma_t * vt[2];
    const double ff = ft[0] * ft[0] + ft[1] * ft[1] + ft[2] * ft[2];
    const double limit = mu * fn_abs;
    if (ff > limit * limit) {  // slides: F_t at the Coulomb limit, spring reset to match
      const double scale = limit / std::sqrt(ff);
      for (int d = 0; d < 3; ++d) {
        ft[d] *= scale;
        xi[d] = -(ft[d] + gamma_t * vt[d]) / k_t;
      }
    }
  }
};

}  // namespace sphdem
