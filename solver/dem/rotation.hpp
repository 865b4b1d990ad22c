#pragma once
// Rotation of the spheres (solid spheres, I = 2/5 m r^2): the half kick of the angular
// velocity in the DEM velocity-Verlet sub-step, w += h tau / I, alongside the
// translational kick. Used by Simulation::dem_half and by the DEM tests, so both
// integrate the same way. Rigid groups (constant-porosity blocks, thesis §4.5) stay
// translational: their spheres keep w = 0.
#include "dem/dem_particles.hpp"

namespace sphdem {

inline void kick_spin(DemParticles& s, double h) {
  const long n = static_cast<long>(s.n_owned);
#pragma omp parallel for schedule(static)
  for (long j = 0; j < n; ++j) {
    if (s.rigid_group[j] >= 0) continue;
    const double c = h / s.inertia(j);
    s.wx[j] += c * s.tx[j];
    s.wy[j] += c * s.ty[j];
    s.wz[j] += c * s.tz[j];
  }
}

}  // namespace sphdem
