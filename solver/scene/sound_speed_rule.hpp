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
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "scene/scene.hpp"
#include "scene/scene_keys.hpp"

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

// The automatic c0 (fluid.sound_speed 0): f max(u_m, sqrt(2 |g| H)), or the buoyancy
// bound where it is larger. Needs expected_speed and the fill height resolved.
inline double factor_sound_speed(const Scene& sc, double factor) {
  const double um = std::max(sc.fluid.expected_speed,
                             std::sqrt(2.0 * sc.gravity_magnitude() * sc.hydrostatic_height()));
  return factor * std::max(um, 1e-6);
}
inline double automatic_sound_speed(const Scene& sc) {
  return std::max(factor_sound_speed(sc, sc.fluid.sound_speed_factor), buoyancy_sound_speed(sc));
}

// What to change for twice the scene's c0, in the key a user sets: fluid.sound_speed_factor
// where the automatic c0 is the factor's and twice the factor is within the key's range,
// else fluid.sound_speed. A density error the sound speed rule does not count (a dense
// suspension's Darcy pressure, a periodic column's fluctuations) falls as 1/c0 to 1/c0^2,
// so doubling c0 at least halves it (validation/README.md, session 43); the SPH step's
// cost doubles with it.
inline std::string twice_the_sound_speed(const Scene& sc) {
  const double c0 = sc.fluid.sound_speed, f = sc.fluid.sound_speed_factor;
  const double f_max = scene_key("fluid.sound_speed_factor").range.hi;
  const bool by_factor = std::abs(c0 - factor_sound_speed(sc, f)) <= 1e-9 * c0;
  if (by_factor && 2.0 * f <= f_max)
    return fmt::format("raise fluid.sound_speed_factor from {:g} to {:g} (c0 {:.3g} -> {:.3g} m/s)",
                       f, 2.0 * f, c0, 2.0 * c0);
  return fmt::format(
      "set fluid.sound_speed: {:.3g} (m/s; twice c0 = {:.3g}{})", 2.0 * c0, c0,
      by_factor ? fmt::format(", and fluid.sound_speed_factor is at most {:g}", f_max) : "");
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
