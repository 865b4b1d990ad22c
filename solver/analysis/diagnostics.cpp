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
  const RankComm& comm = sim.comm();
  if (sim.flow().on()) {  // periodic in z: no base, the flow's U and pressure drop instead
    d.superficial_velocity = sim.flow().superficial_velocity();
    d.pressure_drop = sim.flow().pressure_drop(scene.gravity[2]);
  } else {
    d.excess_pore_pressure_base = excess_pore_pressure_base(f, base, comm);
    const double k = std::visit([](const auto& law) { return law.normal.k; }, sim.contact_law());
    const double area = scene.box.length(0) * scene.box.length(1);
    d.wall_load_base = wall_load_base(s, k, area, base, comm);
    d.fluid_load_base =
        fluid_load_base(f, s, sim.walls_on_spheres_z(), sim.hydrostatic_split(), area, base, comm);
  }
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
  const double bed_floor = sim.params().dem.walls.bottom;  // a bed on the distributor
  const bool bed = scene.flow.distributor && scene.periodic_z();
  double bed_moment = 0.0, bed_volume = 0.0;  // sum V_j (z_j - floor), sum V_j
  double bed_weight = 0.0;                    // sum (m_j - rho_f V_j) |g| of the mobile
  const std::vector<char>& fixed = sim.params().dem.fixed_groups;
  for (std::size_t j = 0; j < s.n_owned; ++j) {
    const int grp = s.rigid_group[j];
    if (bed && (grp < 0 || grp >= static_cast<int>(fixed.size()) || !fixed[grp])) {
      bed_moment += s.volume(j) * (s.z[j] - bed_floor);
      bed_volume += s.volume(j);
      bed_weight += s.mass[j] - rho0 * s.volume(j);
    }
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
  if (comm.parallel()) {  // the sums and maxima over the ranks
    std::vector<double> sums{d.fluid_mass, d.kinetic_energy_fluid, d.kinetic_energy_solid,
                             static_cast<double>(d.voidage_clamped),
                             static_cast<double>(d.omega_bounded)};
    for (std::size_t sp = 0; sp < ns; ++sp)
      for (double v : {d.vz_mean[sp], d.slip_z_mean[sp], d.com_z[sp], mass[sp],
                       static_cast<double>(d.count[sp])})
        sums.push_back(v);
    sums.push_back(bed_moment);
    sums.push_back(bed_volume);
    sums.push_back(bed_weight);
    comm.sum(sums);
    bed_moment = sums[sums.size() - 3];
    bed_volume = sums[sums.size() - 2];
    bed_weight = sums.back();
    d.fluid_mass = sums[0];
    d.kinetic_energy_fluid = sums[1];
    d.kinetic_energy_solid = sums[2];
    d.voidage_clamped = static_cast<std::size_t>(sums[3]);
    d.omega_bounded = static_cast<std::size_t>(sums[4]);
    for (std::size_t sp = 0; sp < ns; ++sp) {
      const double* v = sums.data() + 5 + 5 * sp;
      d.vz_mean[sp] = v[0];
      d.slip_z_mean[sp] = v[1];
      d.com_z[sp] = v[2];
      mass[sp] = v[3];
      d.count[sp] = static_cast<std::size_t>(v[4]);
    }
    std::vector<double> maxima{d.max_overlap_over_d, d.max_density_error};
    comm.max(maxima);
    d.max_overlap_over_d = maxima[0];
    d.max_density_error = maxima[1];
  }
  // the height of a uniform bed with the spheres' mean height: twice it
  if (bed_volume > 0.0) d.bed_height = 2.0 * bed_moment / bed_volume;
  d.bed_weight =
      bed_weight * std::abs(scene.gravity[2]) / (scene.box.length(0) * scene.box.length(1));
  for (std::size_t sp = 0; sp < ns; ++sp) {
    if (d.count[sp] == 0) continue;
    d.vz_mean[sp] /= d.count[sp];
    d.slip_z_mean[sp] /= d.count[sp];
    d.com_z[sp] /= mass[sp];
  }
  return d;
}

}  // namespace sphdem
