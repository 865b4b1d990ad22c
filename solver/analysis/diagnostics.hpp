#pragma once
// Per-species and global observables of the current state (the columns of log.csv).
#include <cstddef>
#include <vector>

namespace sphdem {

class Simulation;

struct Diagnostics {
  double time = 0;
  long step = 0;
  double dt_sph = 0, dt_dem = 0;
  double fluid_mass = 0;
  double kinetic_energy_fluid = 0, kinetic_energy_solid = 0;
  double max_overlap_over_d = 0;
  double max_density_error = 0;  // max |rho/(eps rho0) - 1| over mobile fluid
  std::size_t voidage_clamped = 0, omega_bounded = 0;
  double excess_pore_pressure_base = 0;  // analysis/pore_pressure.hpp: u_base / (rho_f |g| H)
  double wall_load_base =
      0;  // analysis/pore_pressure.hpp: the spheres' load on the wall, same unit
  double fluid_load_base =
      0;  // analysis/pore_pressure.hpp: the fluid's excess load on the wall, same unit
  double superficial_velocity = 0, pressure_drop = 0;  // propagator/flow_controller.hpp
  double bed_height = 0;  // twice the spheres' volume-weighted mean height over the distributor
  double bed_weight = 0;  // their buoyant weight per area (Pa), the plateau's pressure drop
  std::vector<double> vz_mean, slip_z_mean, com_z;  // per species
  std::vector<std::size_t> count;                   // spheres per species
};

Diagnostics diagnostics(const Simulation& sim);

}  // namespace sphdem
