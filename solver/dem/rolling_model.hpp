#pragma once
// Rolling resistance laws (the third part of a contact, contact_registry.hpp).
//
// NoRolling: none (the default).
//
// EpsdRolling: the elastic-plastic spring-dashpot (EPSD) model, rolling resistance model
// type C of Ai, Chen, Rotter & Ooi (2011, "Assessment of rolling resistance models in
// discrete element simulations", Powder Technol. 206:269), which builds on Iwashita & Oda
// (1998, J. Eng. Mech. 124:285); it is LIGGGHTS' `rolling_friction epsd` (not `epsd2`,
// whose k_r = 2 k_t R_eff^2 and which has no dashpot):
//   w_r  = (w_a - w_b) minus its component along n          relative rolling velocity
//   M_k <- M_k rotated into the current tangent plane (projected, length kept)
//   M_k <- M_k - k_r w_r dt,   k_r = 2.25 k_n mu_r^2 R_eff^2 (Ai et al., 3-D)
//   |M_k| <= M_m = mu_r R_eff |F_n|                          (full mobilisation)
//   M_d  = -C_r w_r while |M_k| < M_m, 0 once fully mobilised (Ai et al.'s f = 0)
//   C_r  = eta_r 2 sqrt(I_r k_r),  1/I_r = 1/(I_a + m_a r_a^2) + 1/(I_b + m_b r_b^2)
//   |M_k + M_d| <= M_m                                       (see below)
// Torque on a: M_k + M_d; on b the opposite. R_eff = r_a r_b/(r_a + r_b); at a wall
// R_eff = r and I_r = I + m r^2. Two differences from LIGGGHTS' epsd:
//  - the stored spring torque is rotated with the contact, as the tangential spring is;
//  - the total torque is capped at M_m, as the tangential spring + damper force is capped
//    at mu |F_n|. Uncapped, a sphere that arrives rolling at w_r gets C_r w_r (100 M_m
//    for a 100 um sphere rolling at 1 cm/s on the wall) for the one or two steps its
//    spring takes to mobilise: an impulse that depends on dt (it took 1 % of the spin
//    at dt = t_c/40 in tangential_contact_test) and is not in Ai et al.'s analysis.
// A sphere rolling on a flat wall at mobilisation decelerates at 5/7 mu_r g (solid
// sphere), so it stops after 7 v0^2 / (10 mu_r g).
#include <cmath>

namespace sphdem {

// What a scene gives for the rolling part (contact.rolling).
struct RollingParams {
  enum class Model { kNone, kEpsd };
  Model model = Model::kNone;
  double friction = 0.0;       // mu_r (dimensionless; M_m = mu_r R_eff |F_n|)
  double damping_ratio = 0.3;  // eta_r (Ai et al. use 0.3)
};

struct NoRolling {
  static constexpr bool kEnabled = false;
};

struct EpsdRolling {
  static constexpr bool kEnabled = true;
  static constexpr double kStiffnessFactor = 2.25;  // Ai et al. (2011), 3-D
  double mu_r = 0.0, eta_r = 0.0, k_n = 0.0;

  EpsdRolling() = default;
  EpsdRolling(const RollingParams& p, double k_n_)
      : mu_r(p.friction), eta_r(p.damping_ratio), k_n(k_n_) {}

  // One step of the rolling spring for a contact with normal n, relative angular
  // velocity w = w_a - w_b, effective radius reff, rolling inertia I_r and |F_n|.
  // Updates the spring torque mk and returns the torque m on the first sphere.
  void torque(const double n[3], const double w[3], double reff, double inertia_r, double fn_abs,
              double dt, double mk[3], double m[3]) const {
    const double wn = w[0] * n[0] + w[1] * n[1] + w[2] * n[2];
    const double wr[3] = {w[0] - wn * n[0], w[1] - wn * n[1], w[2] - wn * n[2]};
    const double kr = kStiffnessFactor * k_n * mu_r * mu_r * reff * reff;
    const double mm = mk[0] * mk[0] + mk[1] * mk[1] + mk[2] * mk[2];
    if (mm > 0.0) {
      const double mn = mk[0] * n[0] + mk[1] * n[1] + mk[2] * n[2];
      double px = mk[0] - mn * n[0], py = mk[1] - mn * n[1], pz = mk[2] - mn * n[2];
      const double pp = px * px + py * py + pz * pz;
      if (pp > 0.0) {
        const double scale = std::sqrt(mm / pp);
        px *= scale;
        py *= scale;
        pz *= scale;
      }
      mk[0] = px;
      mk[1] = py;
      mk[2] = pz;
    }
    for (int d = 0; d < 3; ++d) mk[d] -= kr * wr[d] * dt;
    const double m2 = mk[0] * mk[0] + mk[1] * mk[1] + mk[2] * mk[2];
    const double limit = mu_r * reff * fn_abs;
    if (m2 > limit * limit) {  // fully mobilised: spring at the limit, no dashpot
      const double scale = limit / std::sqrt(m2);
      for (int d = 0; d < 3; ++d) m[d] = mk[d] *= scale;
    } else {
      const double c_r = eta_r * 2.0 * std::sqrt(inertia_r * kr);
      for (int d = 0; d < 3; ++d) m[d] = mk[d] - c_r * wr[d];
      const double t2 = m[0] * m[0] + m[1] * m[1] + m[2] * m[2];
      if (t2 > limit * limit) {
        const double scale = limit / std::sqrt(t2);
        for (int d = 0; d < 3; ++d) m[d] *= scale;
      }
    }
  }
};

}  // namespace sphdem
