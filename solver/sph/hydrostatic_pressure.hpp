#pragma once
// The hydrostatic pressure of the fluid at rest, P_h(z) = rho0 g_z (z - z_s), with z_s the
// free surface and g_z < 0. The variational pressure coupling can take it out of the pair
// forces (coupling/pressure_coupling.hpp): a default-constructed one (rho0 = 0) is zero.
namespace sphdem {

struct HydrostaticPressure {
  double rho0 = 0.0;     // reference fluid density (0: no split)
  double gz = 0.0;       // gravity along z (negative)
  double surface = 0.0;  // free-surface height z_s
  double operator()(double z) const { return rho0 * gz * (z - surface); }
  double gradient_z() const { return rho0 * gz; }  // dP_h/dz
};

}  // namespace sphdem
