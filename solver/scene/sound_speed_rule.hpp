#pragma once
// What the sound speed c0 costs in compressibility (physics.md §1, 2.60-2.64): the
// weakly compressible fluid's density departs from rho0 by about Ma^2 in the flow
// (Ma = u_m / c0, u_m the largest expected speed) and by g H / c0^2 under its own weight
// at the base of a column of height H (Delta P = rho0 g H = rho0 c0^2 Delta rho / rho0).
// `sphdem check` prints both and the larger as the expected density error; a run's
// log.csv max_density_error is the measured one (weakly compressible limit: 1 %).
//
// The compressed fluid also buoys a sphere more: the pressure gradient a sphere feels is
// rho g with the fluid's own (compressed) density, so its buoyant weight (rho_p - rho_f) g V
// falls short by rho_f g H / c0^2 at the base, relative to (rho_p - rho_f). Near neutral
// buoyancy that share is the settling speed's error (Stokes: v ~ rho_p - rho_f): at
// rho_p/rho_f = 1.05 twenty times the density error. The automatic c0 keeps it under
// kBuoyancyErrorTarget for the lightest species (scene_loader.cpp).
#include <algorithm>
#include <cmath>

#include "scene/scene.hpp"

namespace sphdem {

inline constexpr double kBuoyancyErrorTarget = 0.01;  // the automatic c0's share
inline constexpr double kBuoyancyErrorLimit = 0.02;   // beyond it `check` refuses a given c0

struct SoundSpeedReport {
  double c0 = 0, mach = 0;
  double flow = 0;         // Ma^2
  double hydrostatic = 0;  // g H / c0^2
  double buoyancy = 0;     // g H / c0^2 rho_f / (rho_p - rho_f) of the lightest species
  double expected_density_error() const { return std::max(flow, hydrostatic); }
};

// rho_f / (rho_p - rho_f) of the species closest to neutral buoyancy (0: no heavier species)
inline double neutral_buoyancy_factor(const Scene& sc) {
  double f = 0;
  for (const SpeciesSpec& sp : sc.species)
    if (sp.density > sc.fluid.density)
      f = std::max(f, sc.fluid.density / (sp.density - sc.fluid.density));
  return f;
}

// The smallest c0 whose compression error on the buoyant weight stays within `share`.
// (A walled column's: in one periodic in z the spheres' buoyancy is the mean gradient's.)
inline double buoyancy_sound_speed(const Scene& sc, double share = kBuoyancyErrorTarget) {
  if (sc.periodic_z()) return 0.0;
  return std::sqrt(sc.gravity_magnitude() * sc.hydrostatic_height() * neutral_buoyancy_factor(sc) /
                   share);
}

inline SoundSpeedReport sound_speed_report(const Scene& sc) {
  SoundSpeedReport r;
  r.c0 = sc.fluid.sound_speed;
  if (!(r.c0 > 0.0)) return r;
  r.mach = sc.fluid.expected_speed / r.c0;
  r.flow = r.mach * r.mach;
  r.hydrostatic = sc.gravity_magnitude() * sc.hydrostatic_height() / (r.c0 * r.c0);
  r.buoyancy = sc.periodic_z() ? 0.0 : r.hydrostatic * neutral_buoyancy_factor(sc);
  return r;
}

}  // namespace sphdem
