#include "run/rank_forecast.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "domain/sfc_grid.hpp"
#include "domain/sfc_partition.hpp"
#include "propagator/simulation.hpp"
#include "sph/kernel.hpp"

namespace sphdem {

namespace {

// The positions of both phases' owned particles, with each one's work, by cell.
struct Cells {
  std::vector<std::vector<std::array<double, 3>>> points;
  std::vector<std::uint64_t> work;
};

}  // namespace

RankForecast forecast_ranks(const Simulation& sim, int ranks) {
  const FluidParticles& f = sim.fluid();
  const DemParticles& s = sim.spheres();
  double hmax = 0.0;
  for (std::size_t a = 0; a < f.n_owned; ++a) hmax = std::max(hmax, f.h[a]);
  const double reach = kernel::kSupport * hmax + sim.fluid_skin();  // the fluid lists' cell
  const Box& box = sim.params().box;
  const SfcGrid grid(box, decomposition_cell(box, reach, ranks));
  Cells cells{std::vector<std::vector<std::array<double, 3>>>(grid.cell_count()),
              std::vector<std::uint64_t>(grid.cell_count(), 0)};
  auto add = [&](double x, double y, double z, std::uint64_t work) {
    x = box.wrap(0, x);
    y = box.wrap(1, y);
    z = box.wrap(2, z);
    const std::size_t c = grid.index(grid.cell_of(x, y, z));
    cells.points[c].push_back({x, y, z});
    cells.work[c] += work;
  };
  const NeighbourList& pairs = sim.fluid_pairs();
  for (std::size_t a = 0; a < f.n_owned; ++a)
    add(f.x[a], f.y[a], f.z[a], a < pairs.size() ? pairs.end(a) - pairs.begin(a) + 1 : 1);
  for (std::size_t j = 0; j < s.n_owned; ++j) add(s.x[j], s.y[j], s.z[j], sim.dem().sphere_work(j));

  RankForecast out;
  out.ranks = ranks;
  const SfcPartition part = partition_curve(grid, cells.work, ranks);
  const std::vector<std::uint64_t> work = rank_weights(grid, part, cells.work);
  std::uint64_t total = 0;
  for (const std::uint64_t w : work) total += w;
  out.largest_share =
      total > 0 ? static_cast<double>(*std::max_element(work.begin(), work.end())) / total : 1.0;
  std::vector<std::size_t> owned(ranks, 0), ghosts(ranks, 0);
  for (std::size_t c = 0; c < grid.cell_count(); ++c)
    owned[part.owner(grid, grid.cell(c))] += cells.points[c].size();
  std::array<int, 3> reach_cells{};
  for (int d = 0; d < 3; ++d)
    reach_cells[d] = static_cast<int>(std::ceil(reach / grid.cell_size(d)));
  const double reach2 = reach * reach;
  for (int q = 0; q < ranks; ++q)
    for (const HaloSend& send : halo_sends(grid, part, q, reach_cells))
      for (const auto& p : cells.points[send.cell]) {
        double image[3];
        for (int d = 0; d < 3; ++d) image[d] = p[d] + send.image[d] * box.length(d);
        for (const std::uint32_t t : send.targets)
          if (grid.distance2_to_cell(t, image) <= reach2) {
            ++ghosts[send.rank];
            break;
          }
      }
  std::size_t owned_sum = 0, ghost_sum = 0;
  for (int r = 0; r < ranks; ++r) {
    out.owned_max = std::max(out.owned_max, owned[r]);
    out.ghosts_max = std::max(out.ghosts_max, ghosts[r]);
    owned_sum += owned[r];
    ghost_sum += ghosts[r];
  }
  out.ghosts_per_owned = owned_sum > 0 ? static_cast<double>(ghost_sum) / owned_sum : 0.0;
  return out;
}

}  // namespace sphdem
