#include "analysis/sediment_output.hpp"

#include <algorithm>
#include <filesystem>
#include <limits>

#include "analysis/bulk_density.hpp"
#include "analysis/contact_network.hpp"
#include "analysis/size_thirds.hpp"
#include "analysis/voidage_grid.hpp"
#include "propagator/simulation.hpp"

namespace sphdem {

void write_sediment_output(const Simulation& sim, const std::string& out_dir) {
  namespace fs = std::filesystem;
  const Scene& sc = sim.scene();
  const DemParticles& s = sim.spheres();
  if (s.n_owned == 0 || sc.species.empty()) return;
  const fs::path dir(out_dir);

  const bool one_density =
      std::all_of(sc.species.begin(), sc.species.end(),
                  [&](const SpeciesSpec& sp) { return sp.density == sc.species[0].density; });
  // Without fluid (dry DEM) there is no voidage field to report.
  if (one_density && sc.fluid.enabled) {
    const GridSpec grid =
        column_voidage_grid(sc.box.length(0), sc.box.length(1), sc.fill_height(), sc.fluid.spacing);
    const std::vector<double> eps = grain_voidage_on_grid(sim, grid, sc.fluid.lattice_h());
    write_bulk_density_csv(
        bulk_density_profile(eps, grid, sc.fluid.density, sc.species[0].density, sc.fill_height()),
        (dir / "bulk_density.csv").string());
  }
  double d_lo = std::numeric_limits<double>::infinity(), d_hi = 0;
  for (const auto& sp : sc.species) {
    d_lo = std::min(d_lo, sp.d_min());
    d_hi = std::max(d_hi, sp.d_max());
  }
  if (d_hi <= d_lo) {  // one size: one bin around it
    d_lo *= 0.95;
    d_hi *= 1.05;
  }
  write_size_thirds_csv(size_thirds(s, d_lo, d_hi, 10), (dir / "size_thirds.csv").string());
  const ContactNetwork net = contact_network(s, sim.contact_list(), sc.contact.normal);
  write_contact_network_csv(net, (dir / "contact_network.csv").string());
  write_contact_network_vtp(net, (dir / "contact_network.vtp").string());
}

}  // namespace sphdem
