#include "run/run_log.hpp"

#include <fmt/format.h>

#include <stdexcept>

namespace sphdem {

std::vector<std::string> RunLog::columns(const std::vector<SpeciesSpec>& species) {
  std::vector<std::string> c = {"time", "step", "dt_sph", "dt_dem", "fluid_mass", "kinetic_energy_fluid",
                                "kinetic_energy_solid", "max_overlap_over_d", "max_density_error",
                                "voidage_clamped", "omega_bounded", "excess_pore_pressure_base",
                                "wall_load_base", "fluid_load_base"};
  for (const char* q : {"vz_mean", "slip_z_mean", "com_z"})
    for (const auto& s : species) c.push_back(fmt::format("{}:{}", q, s.name));
  return c;
}

RunLog::RunLog(const std::string& path, const std::vector<SpeciesSpec>& species) : out_(path) {
  if (!out_) throw std::runtime_error("cannot write " + path);
  out_ << fmt::format("{}\n", fmt::join(columns(species), ","));
  out_.flush();
}

void RunLog::write(const Diagnostics& d) {
  std::string row = fmt::format("{:.17g},{},{:.6g},{:.6g},{:.12g},{:.9g},{:.9g},{:.6g},{:.6g},{},{},{:.6g},{:.6g},{:.6g}", d.time,
                                d.step, d.dt_sph, d.dt_dem, d.fluid_mass, d.kinetic_energy_fluid,
                                d.kinetic_energy_solid, d.max_overlap_over_d, d.max_density_error,
                                d.voidage_clamped, d.omega_bounded, d.excess_pore_pressure_base, d.wall_load_base,
                                d.fluid_load_base);
  for (const auto* v : {&d.vz_mean, &d.slip_z_mean, &d.com_z})
    for (double x : *v) row += fmt::format(",{:.17g}", x);  // exact: compared with the in-situ data
  out_ << row << '\n';
  out_.flush();
}

}  // namespace sphdem
