#pragma once
// The hydrostatic pressure of the fluid at rest that the variational pressure coupling can
// take out of the pair forces (coupling/pressure_coupling.hpp): P_h(z) = rho0 |g_z| q(z)
// with q the depth below the fill height z_s, and zero above it, where a particle lifted
// off the free surface then feels its whole gravity (with the depth continued above z_s,
// -grad P_h cancelled it and the clear liquid rose out of the box). No taper below z_s:
// P_h blended to zero over the top few dx varies on the kernel's own scale, and the pair
// sums' error in its gradient ((h/w)^2 of rho0 g) moved the top layers' pressure by 16 %
// (validation/README.md, session 43). A default-constructed one (rho0 = 0) is zero.
namespace sphdem {

struct HydrostaticPressure {
  double rho0 = 0.0;     // reference fluid density (0: no split)
  double gz = 0.0;       // gravity along z (negative)
  double surface = 0.0;  // free-surface height z_s (the fill height)

  double operator()(double z) const { return z < surface ? -rho0 * gz * (surface - z) : 0.0; }
  double gradient_z(double z) const { return z < surface ? rho0 * gz : 0.0; }  // dP_h/dz
};

}  // namespace sphdem
