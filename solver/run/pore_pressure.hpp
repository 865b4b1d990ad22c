#pragma once
// Excess pore pressure at the base (Zhao, Houlsby & Utili 2014, Fig. 11 and eq. 15):
// the pore pressure P minus the hydrostatic pressure of clear water, normalised by the
// hydrostatic pressure at the base,
//   u_base / (rho_f |g| H) = mean over a in the first fluid layer of
//                            (P_a - rho_f |g| (H - z_a)) / (rho_f |g| H),
// with P the Tait gauge pressure (2.58, zero at the free surface) and H the free-surface
// height (`fluid.fill_height`; the mixture's height does not change as the grains
// settle). The first layer is the mobile fluid particles with z < dx (the lattice puts
// them at dx/2). Zero for water at rest; (1 - n)(rho_s/rho_f - 1) once a suspension of
// porosity n filling the column is carried by the fluid (eq. 15).
#include "dem/dem_particles.hpp"
#include "sph/fluid_particles.hpp"

namespace sphdem {

struct BasePorePressure {
  double rho_f = 1000.0;  // fluid density (kg/m^3)
  double g = 9.81;        // |g| (m/s^2)
  double H = 1.0;         // free-surface height (m)
  double dx = 1e-3;       // lattice spacing: the first layer is z < dx (m)
};

// NaN when the first layer holds no fluid particle.
double excess_pore_pressure_base(const FluidParticles& f, const BasePorePressure& b);

// The spheres' load on the bottom wall (z = 0) in the same unit: the elastic normal
// force sum_i k max(0, r_i - z_i) over (area rho_f |g| H). It closes the column's
// vertical momentum balance (solid + fluid, periodic sides): u_base + wall_load =
// (1 - n)(rho_s/rho_f - 1) - (dM/dt) / (area rho_f |g| H), M the downward momentum of
// the column, so a suspension in steady settling puts eq. 15 into u_base and a bed at
// rest into wall_load. k is the normal stiffness of the linear contact law.
double wall_load_base(const DemParticles& s, double k, double area, const BasePorePressure& b);

}  // namespace sphdem
