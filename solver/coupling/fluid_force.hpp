#pragma once
// Fluid force on one sphere (2.68): f_j = V_j (-grad P + div tau)_j + f_d(eps_j, u_s),
// with the superficial slip u_s = eps_j (u_f - v_j) (2.74). The interpolated fluid
// fields are held fixed over the DEM sub-steps; the drag follows the sphere's velocity.
#include "coupling/drag_laws.hpp"
#include "dem/dem_particles.hpp"

namespace sphdem {

template <class Law>
inline void fluid_force_on_sphere(const DemParticles& s, std::size_t j, const Law& law,
                                  const drag::Fluid& fluid, double& fx, double& fy, double& fz) {
  if (s.shepard[j] <= 0.0) {
    fx = fy = fz = 0.0;
    return;
  }
  const double eps = s.eps[j];
  const double usx = eps * (s.ufx[j] - s.vx[j]);
  const double usy = eps * (s.ufy[j] - s.vy[j]);
  const double usz = eps * (s.ufz[j] - s.vz[j]);
  const double us = std::sqrt(usx * usx + usy * usy + usz * usz);
  const double c = drag::drag_coefficient(law, eps, us, 2.0 * s.radius[j], s.d_sauter[j], fluid);
  const double V = s.volume(j);
  fx = V * s.gx[j] + c * usx;
  fy = V * s.gy[j] + c * usy;
  fz = V * s.gz[j] + c * usz;
}

}  // namespace sphdem
