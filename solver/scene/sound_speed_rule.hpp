#pragma once
// What the sound speed c0 costs in compressibility (physics.md §1, 2.60-2.64): the
// weakly compressible fluid's density departs from rho0 by about Ma^2 in the flow
// (Ma = u_m / c0, u_m the largest expected speed) and by g H / c0^2 under its own weight
// at the base of a column of height H (Delta P = rho0 g H = rho0 c0^2 Delta rho / rho0).
// `sphdem check` prints both and the larger as the expected density error; a run's
// log.csv max_density_error is the measured one (weakly compressible limit: 1 %).
#include <algorithm>
#include <cmath>

#include "scene/scene.hpp"

namespace sphdem {

struct SoundSpeedReport {
  double c0 = 0, mach = 0;
  double flow = 0;         // Ma^2
  double hydrostatic = 0;  // g H / c0^2
  double expected_density_error() const { return std::max(flow, hydrostatic); }
};

inline SoundSpeedReport sound_speed_report(const Scene& sc) {
  SoundSpeedReport r;
  const double g = std::sqrt(sc.gravity[0] * sc.gravity[0] + sc.gravity[1] * sc.gravity[1] +
                             sc.gravity[2] * sc.gravity[2]);
  r.c0 = sc.fluid.sound_speed;
  if (!(r.c0 > 0.0)) return r;
  r.mach = sc.fluid.expected_speed / r.c0;
  r.flow = r.mach * r.mach;
  r.hydrostatic = g * sc.fill_height() / (r.c0 * r.c0);
  return r;
}

}  // namespace sphdem
