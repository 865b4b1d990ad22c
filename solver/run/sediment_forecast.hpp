#pragma once
// What a forming sediment does to a run's cost, for `sphdem check`, whose steps are timed
// at t = 0 (run/step_timing.hpp). As the spheres settle into a bed:
//  - the SPH step shortens: the sound speed of the averaged equations is c0 / sqrt(eps)
//    (2.59), so at the bed's top a clear-liquid particle (h = h0 eps0^(1/3): its mass is
//    eps0 rho0 dx^3) meets the bed's c0 / sqrt(eps_bed) (3.5 with v_sig the pair mean);
//  - a step costs more: the fluid's lists are cut at the largest h, which in the bed is
//    h0 (eps0 / eps_bed)^(1/3), so the passes over them (voidage, density rate, momentum,
//    the builds) visit eps0 / eps_bed times the entries.
// The bed forms over the Kynch time of the slowest sphere, H (1 - phi0 / phi_bed) / u(eps0)
// (u the hindered settling speed, 4.4; the interface meets the rising sediment then),
// and both effects are taken to grow linearly over it.
// Not included: the bed's contacts (the DEM sub-steps in a bed of frictional spheres cost
// several times those of a suspension; bench/RESULTS.md).
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
  double list_growth = 1;         // entries of the fluid's lists with the bed over at t = 0
};

// From the scene and the SPH step measured at t = 0.
SedimentForecast forecast_sediment(const Scene& sc, double dt0);

// The wall time of the steps from t = 0 to t_end: a step of `step` s at dt0 at first, of
// step (1 + list_share (growth - 1)) at dt0 step_ratio once the bed has formed, linear
// in between (list_share: the share of the step in the passes over the fluid's lists).
double forecast_wall(const SedimentForecast& f, double step, double list_share, double dt0,
                     double t_end);

}  // namespace sphdem
