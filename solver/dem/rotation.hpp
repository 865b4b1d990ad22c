#pragma once
// Rotation of the spheres (solid spheres, I = 2/5 m r^2). Rigid groups (constant-porosity
// blocks, thesis §4.5) stay translational: their spheres keep w = 0.
//
// DemSubstepper integrates the spin exactly as the translation (physics.md §4):
//   predict_spin:  w <- w + h tau_old / I   (the predicted end-of-step spin, at which the
//                  tangential and rolling dashpots are evaluated), tau_old kept;
//   correct_spin:  w <- w + h/2 (tau_new - tau_old) / I, i.e. w_n + h (tau_old + tau_new) / 2I.
// kick_spin is the plain half kick w += h tau / I of a textbook velocity Verlet (unit tests).
#include <cstddef>
#include <vector>

#include "dem/dem_particles.hpp"

namespace sphdem {

inline void kick_spin(DemParticles& s, double h) {
  const long n = static_cast<long>(s.n_owned);
#pragma omp parallel for schedule(static) if (n > kMinParallelSpheres)
  for (long j = 0; j < n; ++j) {
    if (s.rigid_group[j] >= 0) continue;
    const double c = h / s.inertia(j);
    s.wx[j] += c * s.tx[j];
    s.wy[j] += c * s.ty[j];
    s.wz[j] += c * s.tz[j];
  }
}

struct OldTorque {
  std::vector<double> x, y, z;
};

// One sphere's spin predictor: w <- w + h tau / I (tau the torque it holds).
inline void kick_spin_of(DemParticles& s, std::size_t j, double h) {
  const double c = h / s.inertia(j);
  s.wx[j] += c * s.tx[j];
  s.wy[j] += c * s.ty[j];
  s.wz[j] += c * s.tz[j];
}

// ... keeping the torque it held as tau_old (the corrector's)
inline void predict_spin_of(DemParticles& s, std::size_t j, double h, double& tox, double& toy,
                            double& toz) {
  tox = s.tx[j];
  toy = s.ty[j];
  toz = s.tz[j];
  kick_spin_of(s, j, h);
}

// One sphere's spin corrector: w <- w + h/2 (tau - tau_old) / I.
inline void correct_spin_of(DemParticles& s, std::size_t j, double h, double tox, double toy,
                            double toz) {
  const double c = 0.5 * h / s.inertia(j);
  s.wx[j] += c * (s.tx[j] - tox);
  s.wy[j] += c * (s.ty[j] - toy);
  s.wz[j] += c * (s.tz[j] - toz);
}

inline void predict_spin(DemParticles& s, double h, OldTorque& old) {
  const long n = static_cast<long>(s.n_owned);
  old.x.resize(n);
  old.y.resize(n);
  old.z.resize(n);
#pragma omp parallel for schedule(static) if (n > kMinParallelSpheres)
  for (long j = 0; j < n; ++j) {
    old.x[j] = s.tx[j];
    old.y[j] = s.ty[j];
    old.z[j] = s.tz[j];
    if (s.rigid_group[j] < 0) kick_spin_of(s, j, h);
  }
}

inline void correct_spin(DemParticles& s, double h, const OldTorque& old) {
  const long n = static_cast<long>(s.n_owned);
#pragma omp parallel for schedule(static) if (n > kMinParallelSpheres)
  for (long j = 0; j < n; ++j)
    if (s.rigid_group[j] < 0) correct_spin_of(s, j, h, old.x[j], old.y[j], old.z[j]);
}

}  // namespace sphdem
