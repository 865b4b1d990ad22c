#include "analysis/diagnostics.hpp"

#include <algorithm>
#include <cmath>
#include <variant>

#include "analysis/pore_pressure.hpp"
#include "propagator/simulation.hpp"

namespace sphdem {

Diagnostics diagnostics(const Simulation& sim) {
  Diagnostics d;
  const FluidParticles& f = sim.fluid();
  const DemParticles& s = sim.spheres();
  const Scene& scene = sim.scene();
  const double rho0 = sim.eos().rho0;
  d.time = sim.time();
  d.step = sim.step_count();
  d.dt_sph = sim.dt_sph();
  d.dt_dem = sim.dt_dem();
  d.voidage_clamped = sim.voidage_clamped();
  d.omega_bounded = sim.omega_bounded();
  const BasePorePressure base{rho0, std::abs(scene.gravity[2]), scene.fill_height(),
                              scene.fluid.spacing};
  d.excess_pore_pressure_base = excess_pore_pressure_base(f, base);
  const double k = std::visit([](const auto& law) { return law.normal.k; }, sim.contact_law());
  const double area = scene.box.length(0) * scene.box.length(1);
  d.wall_load_base = wall_load_base(s, k, area, base);
  d.fluid_load_base =
      fluid_load_base(f, s, sim.walls_on_spheres_z(), sim.hydrostatic_split(), area, base);
  for (std::size_t a = 0; a < f.n_owned; ++a) {
    if (f.kind[a] != kFluid) continue;
    d.fluid_mass += f.mass[a];
    d.kinetic_energy_fluid +=
        0.5 * f.mass[a] * (f.vx[a] * f.vx[a] + f.vy[a] * f.vy[a] + f.vz[a] * f.vz[a]);
    d.max_density_error =
        std::max(d.max_density_error, std::abs(f.rho[a] / (f.eps[a] * rho0) - 1.0));
  }
  const std::size_t ns = scene.species.size();
  d.vz_mean.assign(ns, 0.0);
  d.slip_z_mean.assign(ns, 0.0);
  d.com_z.assign(ns, 0.0);
  d.count.assign(ns, 0);
  std::vector<double> mass(ns, 0.0);
  for (std::size_t j = 0; j < s.n_owned; ++j) {
    const int sp = s.species[j];
    d.kinetic_energy_solid +=
        0.5 * s.mass[j] * (s.vx[j] * s.vx[j] + s.vy[j] * s.vy[j] + s.vz[j] * s.vz[j]);
    d.max_overlap_over_d = std::max(d.max_overlap_over_d, s.overlap_max[j] / (2.0 * s.radius[j]));
    d.vz_mean[sp] += s.vz[j];
    d.slip_z_mean[sp] += s.eps[j] * (s.ufz[j] - s.vz[j]);
    d.com_z[sp] += s.mass[j] * s.z[j];
    mass[sp] += s.mass[j];
    ++d.count[sp];
  }
  for (std::size_t sp = 0; sp < ns; ++sp) {
    if (d.count[sp] == 0) continue;
    d.vz_mean[sp] /= d.count[sp];
    d.slip_z_mean[sp] /= d.count[sp];
    d.com_z[sp] /= mass[sp];
  }
  return d;
}

}  // namespace sphdem
