#pragma once
// The hydrostatic pressure of the fluid at rest that the variational pressure coupling can
// take out of the pair forces (coupling/pressure_coupling.hpp): P_h(z) = rho0 |g_z| q(z),
// with q the depth below the free surface z_s in the bulk and zero in the top layers, so
// that the particles whose kernels reach the free surface keep the whole pressure and
// feel gravity as in plain SPH (with the depth to the top, a surface particle lifted by a
// wave would keep P - P_h > 0 and its gravity cancelled by -grad P_h: it floats off and the
// clear liquid rises out of the box). With the taper width w:
//   q = z_s - z                      for z <= z_s - 2w   (the split as derived)
//   q = w (3t^3 - 4t^2 - t + 2)      for t = (z - z_s + 2w) / w in [0, 1]  (C1: slope -1 -> 0)
//   q = 0                            for z >= z_s - w    (plain SPH)
// Any q gives the same forces in the continuum (pairs carry P - P_h, the particles get
// -grad P_h analytically); only the kernel sums' errors differ. A default-constructed one
// (rho0 = 0) is zero; taper 0 is the linear split everywhere.
namespace sphdem {

struct HydrostaticPressure {
  double rho0 = 0.0;     // reference fluid density (0: no split)
  double gz = 0.0;       // gravity along z (negative)
  double surface = 0.0;  // free-surface height z_s
  double taper = 0.0;    // w: the top layers [z_s - w, z_s] keep the whole pressure

  double operator()(double z) const { return -rho0 * gz * depth(z); }
  double gradient_z(double z) const { return -rho0 * gz * depth_slope(z); }  // dP_h/dz

 private:
  double blend(double z) const { return (z - surface + 2.0 * taper) / taper; }
  double depth(double z) const {
    if (z <= surface - 2.0 * taper) return surface - z;
    if (z >= surface - taper) return 0.0;
    const double t = blend(z);
    return taper * (((3.0 * t - 4.0) * t - 1.0) * t + 2.0);
  }
  double depth_slope(double z) const {  // dq/dz
    if (z <= surface - 2.0 * taper) return -1.0;
    if (z >= surface - taper) return 0.0;
    const double t = blend(z);
    return (9.0 * t - 8.0) * t - 1.0;
  }
};

}  // namespace sphdem
