#include "analysis/voidage_grid.hpp"

#include <cmath>
#include <stdexcept>

#include "propagator/simulation.hpp"
#include "sph/kernel.hpp"

namespace sphdem {

GridSpec column_voidage_grid(double lx, double ly, double top, double spacing, double h) {
  GridSpec g;
  const int nx = std::max(1, static_cast<int>(std::lround(lx / spacing)));
  const int ny = std::max(1, static_cast<int>(std::lround(ly / spacing)));
  const double support = kernel::kSupport * h;
  // whole number of nodes across each periodic width, nodes at cell centres
  g.spacing = {lx / nx, ly / ny, spacing};
  g.origin = {0.5 * g.spacing[0], 0.5 * g.spacing[1], -support};
  const int nz = static_cast<int>(std::ceil((top + 2.0 * support) / spacing));
  g.extent = {0, nx - 1, 0, ny - 1, 0, nz};
  return g;
}

std::vector<double> compute_voidage_grid(const DemParticles& s, const CellList& cells,
                                         const GridSpec& g, double h) {
  const int nx = g.extent[1] - g.extent[0] + 1, ny = g.extent[3] - g.extent[2] + 1;
  std::vector<double> eps(g.count());
  const double rc = kernel::kSupport * h;
  const long n = static_cast<long>(eps.size());
#pragma omp parallel for schedule(static)
  for (long k = 0; k < n; ++k) {
    const int i = static_cast<int>(k % nx), j = static_cast<int>((k / nx) % ny),
              l = static_cast<int>(k / (nx * ny));
    const double x = g.origin[0] + (g.extent[0] + i) * g.spacing[0];
    const double y = g.origin[1] + (g.extent[2] + j) * g.spacing[1];
    const double z = g.origin[2] + (g.extent[4] + l) * g.spacing[2];
    double solid = 0.0;
    cells.for_each_neighbour(x, y, z, rc * rc,
                             [&](std::uint32_t p, double, double, double, double r2) {
                               solid += s.volume(p) * kernel::w(r2, h);
                             });
    eps[k] = 1.0 - solid;
  }
  return eps;
}

std::vector<double> voidage_on_grid(const Simulation& sim, const GridSpec& grid, double h) {
  const DemParticles& s = sim.spheres();
  if (kernel::kSupport * h > sim.dem().halo().width())
    throw std::runtime_error("voidage grid: kernel support exceeds the sphere halo width");
  CellList cells;
  cells.build(s.x.data(), s.y.data(), s.z.data(), s.size(), kernel::kSupport * h, 2);
  return compute_voidage_grid(s, cells, grid, h);
}

}  // namespace sphdem
