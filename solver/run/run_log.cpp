#include "run/run_log.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace sphdem {

std::vector<std::string> RunLog::columns(const std::vector<SpeciesSpec>& species) {
  std::vector<std::string> c = {"time",
                                "step",
                                "dt_sph",
                                "dt_dem",
                                "fluid_mass",
                                "kinetic_energy_fluid",
                                "kinetic_energy_solid",
                                "max_overlap_over_d",
                                "max_density_error",
                                "voidage_clamped",
                                "omega_bounded",
                                "excess_pore_pressure_base",
                                "wall_load_base",
                                "fluid_load_base"};
  for (const char* q : {"vz_mean", "slip_z_mean", "com_z"})
    for (const auto& s : species) c.push_back(fmt::format("{}:{}", q, s.name));
  return c;
}

RunLog::RunLog(const std::string& path, const std::vector<SpeciesSpec>& species) : out_(path) {
  if (!out_) throw std::runtime_error("cannot write " + path);
  out_ << fmt::format("{}\n", fmt::join(columns(species), ","));
  out_.flush();
}

RunLog::RunLog(const std::string& path, const std::vector<SpeciesSpec>& species,
               long keep_through_step) {
  const std::vector<std::string> cols = columns(species);
  const std::string header = fmt::format("{}", fmt::join(cols, ","));
  std::string kept = header + "\n";
  {
    std::ifstream in(path);
    std::string line;
    if (in && std::getline(in, line) && line != header)
      throw std::runtime_error(path + ": its columns are not this scene's; cannot continue it");
    while (std::getline(in, line)) {
      const auto comma = line.find(',');
      if (static_cast<std::size_t>(std::count(line.begin(), line.end(), ',')) + 1 != cols.size())
        break;  // a row cut short by a kill
      char* end = nullptr;
      const long step = std::strtol(line.c_str() + comma + 1, &end, 10);
      if (*end != ',' || step > keep_through_step) break;
      kept += line + "\n";
    }
  }
  {
    std::ofstream tmp(path + ".tmp");
    tmp << kept;
    if (!tmp.flush()) throw std::runtime_error("cannot write " + path + ".tmp");
  }
  std::filesystem::rename(path + ".tmp", path);
  out_.open(path, std::ios::app);
  if (!out_) throw std::runtime_error("cannot write " + path);
}

void RunLog::write(const Diagnostics& d) {
  std::string row = fmt::format(
      "{:.17g},{},{:.6g},{:.6g},{:.12g},{:.9g},{:.9g},{:.6g},{:.6g},{},{},{:.6g},{:.6g},{:.6g}",
      d.time, d.step, d.dt_sph, d.dt_dem, d.fluid_mass, d.kinetic_energy_fluid,
      d.kinetic_energy_solid, d.max_overlap_over_d, d.max_density_error, d.voidage_clamped,
      d.omega_bounded, d.excess_pore_pressure_base, d.wall_load_base, d.fluid_load_base);
  for (const auto* v : {&d.vz_mean, &d.slip_z_mean, &d.com_z})
    for (double x : *v) row += fmt::format(",{:.17g}", x);  // exact: compared with the in-situ data
  out_ << row << '\n';
  out_.flush();
}

}  // namespace sphdem
