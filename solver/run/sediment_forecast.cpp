#include "run/sediment_forecast.hpp"

#include <algorithm>
#include <cmath>

#include "scene/kernel_width_rule.hpp"

namespace sphdem {

namespace {

// The group's slowest sphere's hindered settling speed at the group's voidage.
double slowest_speed(const Scene& sc, const ParticleGroupSpec& g) {
  std::vector<std::string> names = g.mixture;
  if (names.empty()) names.push_back(g.species);
  double u = HUGE_VAL;
  for (const std::string& name : names) {
    const int k = sc.species_index(name);
    if (k < 0) continue;
    const SpeciesSpec& sp = sc.species[static_cast<std::size_t>(k)];
    if (sp.density <= sc.fluid.density) return HUGE_VAL;  // floats or hangs: no bed
    u = std::min(u, settling_speed(sc.drag, sp.d_min(), sp.density, sc.fluid.density,
                                   sc.fluid.viscosity, sc.gravity_magnitude(), g.voidage));
  }
  return u;
}

}  // namespace

SedimentForecast forecast_sediment(const Scene& sc, double dt0) {
  SedimentForecast f;
  if (!sc.fluid.enabled || sc.gravity_magnitude() <= 0.0 || !(dt0 > 0.0)) return f;
  for (const ParticleGroupSpec& g : sc.particles) {
    if (g.rigid || g.kind == ParticleGroupSpec::Kind::kSingle || g.voidage <= kBedVoidage) continue;
    const double u = slowest_speed(sc, g);
    if (!(u > 0.0) || !std::isfinite(u)) continue;
    const double height = g.hi[2] - g.lo[2];
    const double t = height * (1.0 - (1.0 - g.voidage) / (1.0 - kBedVoidage)) / u;
    f.forms = true;
    f.settle_time = std::max(f.settle_time, t);
    f.suspension_voidage = std::max(f.suspension_voidage, g.voidage);
  }
  if (!f.forms) return f;
  const double eps0 = f.suspension_voidage, eb = kBedVoidage;
  const double c0 = sc.fluid.sound_speed, h0 = sc.fluid.lattice_h(), cfl = sc.time.cfl;
  const double c_bed = c0 / std::sqrt(eb);  // (2.59) at rho = eps rho0
  const double h_clear = h0 * std::cbrt(eps0), h_bed = h0 * std::cbrt(eps0 / eb);
  double dt = dt0;
  dt = std::min(dt, cfl * h_clear / (0.5 * (c0 + c_bed)));  // the bed's top (3.5)
  dt = std::min(dt, cfl * h_bed / c_bed);                   // inside the bed
  const double nu = sc.fluid.viscosity / sc.fluid.density;  // (2.55, 2.57) in the bed
  dt = std::min(
      dt, 0.125 * h_bed * h_bed / (nu / eb + 0.1 * sc.fluid.alpha_artificial * h_bed * c_bed));
  f.step_ratio = dt / dt0;
  return f;
}

double forecast_steps(const SedimentForecast& f, double dt0, double t_end) {
  if (!(t_end > 0.0) || !(dt0 > 0.0)) return 0.0;
  const double T = t_end, ts = f.settle_time;
  if (!f.forms || !(ts > 0.0)) return T / dt0;
  // steps per second 1/dt0 (1 + b min(1, t/t_s)), b = 1/step_ratio - 1: its integral
  const double b = 1.0 / f.step_ratio - 1.0;
  const double ramp =
      T <= ts ? T + 0.5 * b * T * T / ts : ts * (1.0 + 0.5 * b) + (T - ts) * (1.0 + b);
  return ramp / dt0;
}

}  // namespace sphdem
