#include "analysis/sediment_output.hpp"

#include <algorithm>
#include <filesystem>
#include <limits>
#include <numeric>

#include "analysis/bulk_density.hpp"
#include "analysis/contact_network.hpp"
#include "analysis/size_thirds.hpp"
#include "analysis/voidage_grid.hpp"
#include "propagator/simulation.hpp"

namespace sphdem {

namespace {

// Rank 0's network: every rank's records (each pair is listed once, by the rank that
// owns its lower id), ordered by the pair's ids as no rank count changes.
ContactNetwork gathered(const ContactNetwork& mine, const RankComm& comm) {
  ContactNetwork all;
  all.id_a = comm.gather_to_root(mine.id_a);
  all.id_b = comm.gather_to_root(mine.id_b);
  all.xa = comm.gather_to_root(mine.xa);
  all.ya = comm.gather_to_root(mine.ya);
  all.za = comm.gather_to_root(mine.za);
  all.xb = comm.gather_to_root(mine.xb);
  all.yb = comm.gather_to_root(mine.yb);
  all.zb = comm.gather_to_root(mine.zb);
  all.overlap = comm.gather_to_root(mine.overlap);
  all.normal_force = comm.gather_to_root(mine.normal_force);
  std::vector<std::size_t> order(all.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return all.id_a[a] != all.id_a[b] ? all.id_a[a] < all.id_a[b] : all.id_b[a] < all.id_b[b];
  });
  const auto reorder = [&](auto& v) {
    auto copy = v;
    for (std::size_t k = 0; k < order.size(); ++k) v[k] = copy[order[k]];
  };
  reorder(all.id_a), reorder(all.id_b), reorder(all.xa), reorder(all.ya), reorder(all.za);
  reorder(all.xb), reorder(all.yb), reorder(all.zb), reorder(all.overlap);
  reorder(all.normal_force);
  return all;
}

}  // namespace

// On ranks every rank takes part (the grid's sums, the gathers) and rank 0 writes.
void write_sediment_output(const Simulation& sim, const std::string& out_dir) {
  namespace fs = std::filesystem;
  const Scene& sc = sim.scene();
  const DemParticles& s = sim.spheres();
  const RankComm& comm = sim.comm();
  const bool root = comm.rank() == 0;
  if (comm.sum(static_cast<std::uint64_t>(s.n_owned)) == 0 || sc.species.empty()) return;
  const fs::path dir(out_dir);

  const bool one_density =
      std::all_of(sc.species.begin(), sc.species.end(),
                  [&](const SpeciesSpec& sp) { return sp.density == sc.species[0].density; });
  // Without fluid (dry DEM) there is no voidage field to report.
  if (one_density && sc.fluid.enabled) {
    const GridSpec grid =
        column_voidage_grid(sc.box.length(0), sc.box.length(1), sc.fill_height(), sc.fluid.spacing);
    const std::vector<double> eps = grain_voidage_on_grid(sim, grid, sc.fluid.lattice_h());
    if (root)
      write_bulk_density_csv(bulk_density_profile(eps, grid, sc.fluid.density,
                                                  sc.species[0].density, sc.fill_height()),
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
  const ContactNetwork mine =
      contact_network(s, sim.contact_list(), sc.contact.normal, sim.params().dem.walls.bottom);
  if (!comm.parallel()) {
    write_size_thirds_csv(size_thirds(s, d_lo, d_hi, 10), (dir / "size_thirds.csv").string());
    write_contact_network_csv(mine, (dir / "contact_network.csv").string());
    write_contact_network_vtp(mine, (dir / "contact_network.vtp").string());
    return;
  }
  std::vector<double> d(s.n_owned);
  for (std::size_t j = 0; j < s.n_owned; ++j) d[j] = 2.0 * s.radius[j];
  const std::vector<double> z =
      comm.gather_to_root(std::vector<double>(s.z.begin(), s.z.begin() + s.n_owned));
  const std::vector<std::int64_t> id =
      comm.gather_to_root(std::vector<std::int64_t>(s.id.begin(), s.id.begin() + s.n_owned));
  const std::vector<double> all_d = comm.gather_to_root(d);
  const ContactNetwork net = gathered(mine, comm);
  if (!root) return;
  write_size_thirds_csv(size_thirds(z, id, all_d, d_lo, d_hi, 10),
                        (dir / "size_thirds.csv").string());
  write_contact_network_csv(net, (dir / "contact_network.csv").string());
  write_contact_network_vtp(net, (dir / "contact_network.vtp").string());
}

}  // namespace sphdem
