#pragma once
// The spheres' velocity Verlet (physics.md §4), one sphere at a time, as every sub-step
// scheme takes it (the spin likewise: rotation.hpp):
//   predictor  x += h (v + h a_old / 2), v += h a_old: the predicted end-of-step velocity,
//              at which the velocity-dependent forces (dashpot, drag) are evaluated (second
//              order, where the half-step velocity would make the dashpot first order);
//   corrector  v += h/2 (a_new - a_old), i.e. v_n + h (a_old + a_new) / 2.
#include <cstddef>
#include <vector>

#include "dem/dem_particles.hpp"

namespace sphdem {

// One vector per sphere as three arrays (the accelerations a sub-step started from, for
// its corrector).
struct SphereVectors {
  std::vector<double> x, y, z;
  void resize(std::size_t n) {
    x.resize(n);
    y.resize(n);
    z.resize(n);
  }
};

// The predictor of sphere j over h; returns the step's length squared.
inline double predict(DemParticles& s, std::size_t j, double h) {
  const double dx = h * (s.vx[j] + 0.5 * h * s.ax[j]);
  const double dy = h * (s.vy[j] + 0.5 * h * s.ay[j]);
  const double dz = h * (s.vz[j] + 0.5 * h * s.az[j]);
  s.x[j] += dx;
  s.y[j] += dy;
  s.z[j] += dz;
  s.vx[j] += h * s.ax[j];
  s.vy[j] += h * s.ay[j];
  s.vz[j] += h * s.az[j];
  return dx * dx + dy * dy + dz * dz;
}

// The corrector of sphere j (finish = h/2) from the acceleration (aox, aoy, aoz) its step
// started from to the one it holds.
inline void correct(DemParticles& s, std::size_t j, double finish, double aox, double aoy,
                    double aoz) {
  s.vx[j] += finish * (s.ax[j] - aox);
  s.vy[j] += finish * (s.ay[j] - aoy);
  s.vz[j] += finish * (s.az[j] - aoz);
}

// The sub-step before's corrector (finish = h/2; 0 before the first), then this one's
// predictor; the old acceleration takes the one the step starts from.
inline double correct_and_predict(DemParticles& s, std::size_t j, double finish, double h,
                                  double& aox, double& aoy, double& aoz) {
  correct(s, j, finish, aox, aoy, aoz);
  const double step2 = predict(s, j, h);
  aox = s.ax[j];
  aoy = s.ay[j];
  aoz = s.az[j];
  return step2;
}

}  // namespace sphdem
