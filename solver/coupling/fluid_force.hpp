#pragma once
// Fluid force on one sphere (2.68): f_j = V_j (-grad P + div tau)_j + f_d(eps_j, u_s),
// with the superficial slip u_s = eps_j (u_f - v_j) (2.74) and the drag coefficient c_j of
// the sphere's law at that slip (drag_coefficients.hpp). The interpolated fluid fields are
// held fixed over the DEM sub-steps; the drag follows the sphere's velocity.
#include "dem/dem_particles.hpp"

namespace sphdem {

inline void fluid_force_on_sphere(const DemParticles& s, std::size_t j, double c, double& fx,
                                  double& fy, double& fz) {
  if (s.shepard[j] <= 0.0) {
    fx = fy = fz = 0.0;
    return;
  }
  const double eps = s.eps[j];
  const double usx = eps * (s.ufx[j] - s.vx[j]);
  const double usy = eps * (s.ufy[j] - s.vy[j]);
  const double usz = eps * (s.ufz[j] - s.vz[j]);
  const double V = s.volume(j);
  fx = V * s.gx[j] + c * usx;
  fy = V * s.gy[j] + c * usy;
  fz = V * s.gz[j] + c * usz;
}

}  // namespace sphdem
