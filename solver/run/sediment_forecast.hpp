#pragma once
// What a forming sediment does to a run's cost, for `sphdem check`, whose steps are timed
// at t = 0 (run/step_timing.hpp). As the spheres settle into a bed the SPH step shortens:
// the sound speed of the averaged equations is c0 / sqrt(eps) (2.59), so at the bed's top
// a clear-liquid particle (h = h0 eps0^(1/3): its mass is eps0 rho0 dx^3) meets the bed's
// c0 / sqrt(eps_bed) (3.5, v_sig the pair's mean). The bed forms over the Kynch time of the
// slowest sphere, H (1 - phi0 / phi_bed) / u(eps0) (u the hindered settling speed, 4.4; the
// interface meets the rising sediment then), and the step is taken to shorten linearly
// over it. The pairs per step stay: each list holds a particle's pairs within its own h's
// reach (Simulation::rebuild_neighbours). Not included: the bed's contacts (the DEM
// sub-steps in a bed of frictional spheres cost several times a suspension's;
// bench/RESULTS.md).
#include <string>

#include "scene/scene.hpp"

namespace sphdem {

// The bed's voidage: a frictional random packing, solid fraction 0.6 (between random
// loose, 0.555, and random close, 0.64; Onoda & Liniger 1990).
inline constexpr double kBedVoidage = 0.4;

struct SedimentForecast {
  bool forms = false;             // some group of mobile spheres settles into a bed
  double settle_time = 0;         // s, the Kynch time of the slowest group
  double suspension_voidage = 0;  // eps0, the loosest settling group's
  double step_ratio = 1;          // dt_SPH with the bed over dt_SPH at t = 0 (<= 1)
};

// From the scene and the SPH step measured at t = 0.
SedimentForecast forecast_sediment(const Scene& sc, double dt0);

// The SPH steps from t = 0 to t_end: at dt0 at first, at dt0 step_ratio once the bed has
// formed, the steps per second linear in between.
double forecast_steps(const SedimentForecast& f, double dt0, double t_end);

// Their wall time, each taking `step` s.
inline double forecast_wall(const SedimentForecast& f, double step, double dt0, double t_end) {
  return step * forecast_steps(f, dt0, t_end);
}

}  // namespace sphdem
