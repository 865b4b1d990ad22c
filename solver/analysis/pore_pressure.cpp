#include "analysis/pore_pressure.hpp"

#include <limits>

namespace sphdem {

double excess_pore_pressure_base(const FluidParticles& f, const BasePorePressure& b,
                                 const RankComm& comm) {
  const double p0 = b.rho_f * b.g * b.H;
  double sum = 0.0;
  long n = 0;
  for (std::size_t a = 0; a < f.n_owned; ++a) {
    if (f.kind[a] != kFluid || f.z[a] >= b.dx) continue;
    sum += (f.P[a] - b.rho_f * b.g * (b.H - f.z[a])) / p0;
    ++n;
  }
  std::vector<double> v{sum, static_cast<double>(n)};
  comm.sum(v);
  sum = v[0];
  n = static_cast<long>(v[1]);
  return n > 0 ? sum / n : std::numeric_limits<double>::quiet_NaN();
}

double wall_load_base(const DemParticles& s, double k, double area, const BasePorePressure& b,
                      const RankComm& comm) {
  double load = 0.0;
  for (std::size_t i = 0; i < s.n_owned; ++i)
    if (s.z[i] < s.radius[i]) load += k * (s.radius[i] - s.z[i]);
  std::vector<double> v{load};
  comm.sum(v);
  load = v[0];
  return load / (area * b.rho_f * b.g * b.H);
}

double fluid_load_base(const FluidParticles& f, const DemParticles& s, double walls_on_spheres_z,
                       const HydrostaticPressure& ph, double area, const BasePorePressure& b,
                       const RankComm& comm) {
  double force = walls_on_spheres_z, fluid_mass = 0.0, sphere_volume = 0.0;
  for (std::size_t a = 0; a < f.n_owned; ++a) {
    if (f.kind[a] != kFluid) continue;
    force += f.mass[a] * f.thz[a] - ph.gradient_z(f.z[a]) * f.mass[a] * f.eps[a] / f.rho[a];
    fluid_mass += f.mass[a];
  }
  for (std::size_t j = 0; j < s.n_owned; ++j) {
    sphere_volume += s.volume(j);
    force -= ph.gradient_z(s.z[j]) * s.volume(j);
  }
  std::vector<double> v{force, fluid_mass, sphere_volume};
  comm.sum(v);  // (walls_on_spheres_z: each rank's own pairs)
  force = v[0];
  fluid_mass = v[1];
  sphere_volume = v[2];
  const double clear_column = b.g * (fluid_mass + b.rho_f * sphere_volume);
  return (force - clear_column) / (area * b.rho_f * b.g * b.H);
}

}  // namespace sphdem
