#include "analysis/voidage_grid.hpp"

#include <algorithm>
#include <cmath>

#include "coupling/double_smoothing.hpp"
#include "domain/cell_list.hpp"
#include "domain/periodic_halo.hpp"
#include "propagator/simulation.hpp"
#include "sph/kernel.hpp"

namespace sphdem {

GridSpec column_voidage_grid(double lx, double ly, double height, double spacing) {
  GridSpec g;
  const auto cells = [&](double length) {
    return std::max(1, static_cast<int>(std::lround(length / spacing)));
  };
  const int nx = cells(lx), ny = cells(ly), nz = cells(height);
  g.spacing = {lx / nx, ly / ny, height / nz};
  g.origin = {0.5 * g.spacing[0], 0.5 * g.spacing[1], 0.5 * g.spacing[2]};
  g.extent = {0, nx - 1, 0, ny - 1, 0, nz - 1};
  return g;
}

std::vector<double> voidage_at_nodes(const VoidageSources& src, const GridSpec& g) {
  const FluidParticles& f = src.fluid;
  const DemParticles& s = src.spheres;
  const bool apart = src.is_big && src.phi;
  double h_max = src.fixed_h;
  for (std::size_t b = 0; b < f.size() && src.fixed_h <= 0; ++b)
    if (f.kind[b] == kFluid) h_max = std::max(h_max, f.h[b]);
  std::vector<double> eps(g.count(), 1.0);
  if (h_max <= 0.0) return eps;  // no fluid
  const double fluid_reach = kernel::kSupport * h_max;
  const double sphere_reach = src.sphere_kernel_scale * fluid_reach;
  CellList fluid_cells, sphere_cells;
  if (src.fixed_h <= 0)
    fluid_cells.build(f.x.data(), f.y.data(), f.z.data(), f.size(), fluid_reach);
  sphere_cells.build(s.x.data(), s.y.data(), s.z.data(), s.size(), sphere_reach);
  const auto volume = [&](std::uint32_t b) { return f.mass[b] / f.rho[b]; };
  const int nx = g.extent[1] - g.extent[0] + 1, ny = g.extent[3] - g.extent[2] + 1;
  const long n = static_cast<long>(eps.size());
#pragma omp parallel for schedule(static)
  for (long k = 0; k < n; ++k) {
    const int i = static_cast<int>(k % nx), j = static_cast<int>((k / nx) % ny),
              l = static_cast<int>(k / (nx * ny));
    const double x = g.origin[0] + (g.extent[0] + i) * g.spacing[0];
    const double y = g.origin[1] + (g.extent[2] + j) * g.spacing[1];
    const double z = g.origin[2] + (g.extent[4] + l) * g.spacing[2];
    double h = src.fixed_h;
    if (h <= 0.0) {  // h(x): the mobile fluid's Shepard mean
      double h_sum = 0.0, weight = 0.0;
      fluid_cells.for_each_neighbour(x, y, z, fluid_reach * fluid_reach,
                                     [&](std::uint32_t b, double, double, double, double r2) {
                                       if (f.kind[b] != kFluid) return;
                                       const double vw = volume(b) * kernel::w(r2, f.h[b]);
                                       h_sum += vw * f.h[b];
                                       weight += vw;
                                     });
      if (weight <= 0.0) continue;  // no fluid reaches the node
      h = h_sum / weight;
    }
    const double H = src.sphere_kernel_scale * h;
    double solid = 0.0;  // (2.50), the spheres not smoothed apart
    sphere_cells.for_each_neighbour(x, y, z, kernel::kSupport * kernel::kSupport * H * H,
                                    [&](std::uint32_t p, double, double, double, double r2) {
                                      if (!apart || !(*src.is_big)[s.species[p]])
                                        solid += s.volume(p) * kernel::w(r2, H);
                                    });
    if (apart) {  // (3.10): the big spheres' fraction, Shepard-interpolated with h(x)
      double num = 0.0, shepard = 0.0;
      fluid_cells.for_each_neighbour(x, y, z, kernel::kSupport * kernel::kSupport * h * h,
                                     [&](std::uint32_t b, double, double, double, double r2) {
                                       const double vw = volume(b) * kernel::w(r2, h);
                                       num += vw * (*src.phi)[b];
                                       shepard += vw;
                                     });
      if (shepard > 0.0) solid += num / shepard;
    }
    eps[k] = 1.0 - solid;
  }
  return eps;
}

namespace {

template <class Particles>
Particles imaged(const Particles& owned, const Box& box, double width) {
  Particles p = owned;
  p.resize(p.n_owned);         // the run's own halo copies may be stale
  for (int d = 0; d < 3; ++d)  // the images of one shell: the loader keeps kernels within it
    if (box.periodic[d]) width = std::min(width, box.length(d));
  PeriodicHalo halo;
  halo.build(box, width, p.x.data(), p.y.data(), p.z.data(), p.n_owned);
  p.resize(p.n_owned + halo.n_ghost());
  halo.fill_positions(p.x.data(), p.y.data(), p.z.data());
  p.for_each_field([&](const FieldInfo& info, auto& v) {
    if ((info.flags & kPosition) == 0) halo.fill(v);
  });
  return p;
}

}  // namespace

FluidParticles with_periodic_images(const FluidParticles& f, const Box& box, double width) {
  return imaged(f, box, width);
}
DemParticles with_periodic_images(const DemParticles& s, const Box& box, double width) {
  return imaged(s, box, width);
}

std::vector<double> voidage_on_grid(const Simulation& sim, const GridSpec& spec) {
  const FluidParticles& f = sim.fluid();
  const CouplingParams& c = sim.params().coupling;
  const Box& box = sim.params().box;
  double h_max = 0.0;
  for (std::size_t a = 0; a < f.n_owned; ++a) h_max = std::max(h_max, f.h[a]);
  const double fluid_reach = kernel::kSupport * h_max;
  FluidParticles fluid = with_periodic_images(f, box, fluid_reach);
  // the spheres round the nodes and, for phi, round every fluid particle the nodes read
  const double sphere_reach = std::max(c.sphere_kernel_scale * fluid_reach,
                                       c.double_smoothing ? fluid_reach + c.big_cutoff : 0.0);
  const DemParticles spheres = with_periodic_images(sim.spheres(), box, sphere_reach);
  VoidageSources src{fluid, spheres, c.sphere_kernel_scale};
  BigSphereFraction big;
  if (c.double_smoothing) {  // (3.9) at every fluid particle, images included
    CellList big_cells;
    big_cells.build(spheres.x.data(), spheres.y.data(), spheres.z.data(), spheres.size(),
                    c.big_cutoff);
    fluid.n_owned = fluid.size();
    smooth_big_spheres(fluid, spheres, big_cells, c.is_big_species, c.big_h_over_d, big);
    src.is_big = &c.is_big_species;
    src.phi = &big.phi;
  }
  return voidage_at_nodes(src, spec);
}

std::vector<double> grain_voidage_on_grid(const Simulation& sim, const GridSpec& spec, double h) {
  const DemParticles spheres =
      with_periodic_images(sim.spheres(), sim.params().box, kernel::kSupport * h);
  VoidageSources src{sim.fluid(), spheres, 1.0};
  src.fixed_h = h;
  return voidage_at_nodes(src, spec);
}

}  // namespace sphdem
