#include "run/log_columns.hpp"

#include <fmt/format.h>

namespace sphdem {

namespace {

template <class... T>
void put(std::string& row, fmt::format_string<T...> f, T&&... v) {
  fmt::format_to(std::back_inserter(row), f, std::forward<T>(v)...);
}

}  // namespace

const std::vector<LogColumn>& log_columns() {
  using D = const Diagnostics&;
  using S = std::size_t;
  // %.17g where a value is compared bit for bit (time; the species' means with the
  // in-situ data), fewer digits where the value is a diagnostic.
  static const std::vector<LogColumn> columns = {
      {"time", "s", "simulated time since release", false,
       [](std::string& r, D d, S) { put(r, "{:.17g}", d.time); }},
      {"step", "–", "SPH steps since release", false,
       [](std::string& r, D d, S) { put(r, "{}", d.step); }},
      {"dt_sph", "s", "current SPH step", false,
       [](std::string& r, D d, S) { put(r, "{:.6g}", d.dt_sph); }},
      {"dt_dem", "s", "DEM sub-step of the last SPH step", false,
       [](std::string& r, D d, S) { put(r, "{:.6g}", d.dt_dem); }},
      {"fluid_mass", "kg", "total mass of the mobile fluid particles (constant)", false,
       [](std::string& r, D d, S) { put(r, "{:.12g}", d.fluid_mass); }},
      {"kinetic_energy_fluid", "J", "Σ ½ m u² over the fluid particles", false,
       [](std::string& r, D d, S) { put(r, "{:.9g}", d.kinetic_energy_fluid); }},
      {"kinetic_energy_solid", "J", "Σ ½ m v² over the spheres (translation only)", false,
       [](std::string& r, D d, S) { put(r, "{:.9g}", d.kinetic_energy_solid); }},
      {"max_overlap_over_d", "–",
       "largest sphere–sphere or sphere–wall overlap / d at the last contact evaluation", false,
       [](std::string& r, D d, S) { put(r, "{:.6g}", d.max_overlap_over_d); }},
      {"max_density_error", "–", "max |ρ_a / (ε_a ρ0) − 1| over the fluid particles", false,
       [](std::string& r, D d, S) { put(r, "{:.6g}", d.max_density_error); }},
      {"voidage_clamped", "count",
       "fluid particles whose ε was raised to `coupling.voidage_floor` in the last voidage pass",
       false, [](std::string& r, D d, S) { put(r, "{}", d.voidage_clamped); }},
      {"omega_bounded", "count",
       "fluid particles whose grad-h Ω (2.54) was clamped to [0.5, 2] in the last density-rate "
       "pass",
       false, [](std::string& r, D d, S) { put(r, "{}", d.omega_bounded); }},
      {"wall_load_base", "–",
       "the spheres' contact load on the bottom wall, Σ k max(0, r_i − z_i) / (A ρf |g| H)", false,
       [](std::string& r, D d, S) { put(r, "{:.6g}", d.wall_load_base); }},
      {"fluid_load_base", "–",
       "the fluid's excess load on the bottom wall (the wall particles' forces on the column "
       "less the clear column's weight) over A ρf |g| H: with `wall_load_base` it closes the "
       "column's momentum balance, (1 − n)(ρs/ρf − 1) at steady settling (eq. 15)",
       false, [](std::string& r, D d, S) { put(r, "{:.6g}", d.fluid_load_base); }},
      {"superficial_velocity", "m/s",
       "the fluid's superficial velocity along z, Σ m_a u_z,a / (ρf V_box), of a column periodic "
       "in z: `flow`'s U(t), which the flow controller holds (0 elsewhere)",
       false, [](std::string& r, D d, S) { put(r, "{:.9g}", d.superficial_velocity); }},
      {"pressure_drop", "Pa",
       "the frictional pressure drop over a column periodic in z, (G_z + ρf g_z) L_z with G the "
       "mean pressure gradient the flow controller sets (0 elsewhere): the bed's buoyant weight "
       "per area once it is fluidised",
       false, [](std::string& r, D d, S) { put(r, "{:.9g}", d.pressure_drop); }},
      {"bed_height", "m",
       "the height of a bed on `flow.distributor`: twice the spheres' volume-weighted mean "
       "height above it, the height of a uniform bed that holds them (0 without a distributor); "
       "its voidage 1 − Σ V_j / (A bed_height)",
       false, [](std::string& r, D d, S) { put(r, "{:.9g}", d.bed_height); }},
      {"bed_weight", "Pa",
       "the buoyant weight per area of the spheres over `flow.distributor` (not `fixed`), "
       "Σ (m_j − ρf V_j) |g_z| / A: the pressure drop of the bed once fluidised (0 without a "
       "distributor)",
       false, [](std::string& r, D d, S) { put(r, "{:.9g}", d.bed_weight); }},
      {"vz_mean", "m/s", "mean vertical velocity of the spheres of the species", true,
       [](std::string& r, D d, S s) { put(r, "{:.17g}", d.vz_mean[s]); }},
      {"slip_z_mean", "m/s", "mean superficial slip ε_i (u_f,z − v_z) (2.74) of the species", true,
       [](std::string& r, D d, S s) { put(r, "{:.17g}", d.slip_z_mean[s]); }},
      {"com_z", "m", "mass-weighted mean height of the species", true,
       [](std::string& r, D d, S s) { put(r, "{:.17g}", d.com_z[s]); }},
  };
  return columns;
}

}  // namespace sphdem
