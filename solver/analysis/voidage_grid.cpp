#include "analysis/voidage_grid.hpp"

#include <algorithm>
#include <cmath>
#include <unordered_map>

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

namespace {

// The nodes' positions, in VTK order (x fastest).
struct Nodes {
  const GridSpec& g;
  int nx, ny;
  explicit Nodes(const GridSpec& spec)
      : g(spec), nx(spec.extent[1] - spec.extent[0] + 1), ny(spec.extent[3] - spec.extent[2] + 1) {}
  std::array<double, 3> at(long k) const {
    const int i = static_cast<int>(k % nx), j = static_cast<int>((k / nx) % ny),
              l = static_cast<int>(k / (static_cast<long>(nx) * ny));
    return {g.origin[0] + (g.extent[0] + i) * g.spacing[0],
            g.origin[1] + (g.extent[2] + j) * g.spacing[1],
            g.origin[2] + (g.extent[4] + l) * g.spacing[2]};
  }
};

// The box round n points widened by `reach`: a node outside it has no point within reach.
struct Reach {
  std::array<double, 3> lo{0, 0, 0}, hi{-1, -1, -1};
  Reach(const double* x, const double* y, const double* z, std::size_t n, double reach) {
    if (n == 0) return;
    lo = {x[0], y[0], z[0]};
    hi = lo;
    for (std::size_t i = 1; i < n; ++i) {
      lo = {std::min(lo[0], x[i]), std::min(lo[1], y[i]), std::min(lo[2], z[i])};
      hi = {std::max(hi[0], x[i]), std::max(hi[1], y[i]), std::max(hi[2], z[i])};
    }
    for (int d = 0; d < 3; ++d) {
      lo[d] -= reach;
      hi[d] += reach;
    }
  }
  bool holds(const std::array<double, 3>& p) const {
    return p[0] >= lo[0] && p[0] <= hi[0] && p[1] >= lo[1] && p[1] <= hi[1] && p[2] >= lo[2] &&
           p[2] <= hi[2];
  }
};

}  // namespace

// Each node's sums are taken in passes whose partial sums add over ranks (every rank's
// sources are its owned particles and their images): h(x)'s numerator and weight first,
// then the spheres' solid fraction and the (3.10) Shepard sums with the summed h(x).
std::vector<double> voidage_at_nodes(const VoidageSources& src, const GridSpec& g,
                                     const RankComm& comm) {
  const FluidParticles& f = src.fluid;
  const DemParticles& s = src.spheres;
  const bool apart = src.is_big && src.phi;
  double h_max = src.fixed_h;
  for (std::size_t b = 0; b < f.size() && src.fixed_h <= 0; ++b)
    if (f.kind[b] == kFluid) h_max = std::max(h_max, f.h[b]);
  if (comm.parallel()) h_max = comm.max(h_max);
  std::vector<double> eps(g.count(), 1.0);
  if (h_max <= 0.0) return eps;  // no fluid
  const double fluid_reach = kernel::kSupport * h_max;
  const double sphere_reach = src.sphere_kernel_scale * fluid_reach;
  CellList fluid_cells, sphere_cells;
  if (src.fixed_h <= 0)
    fluid_cells.build(f.x.data(), f.y.data(), f.z.data(), f.size(), fluid_reach);
  sphere_cells.build(s.x.data(), s.y.data(), s.z.data(), s.size(), sphere_reach);
  const Reach near_fluid(f.x.data(), f.y.data(), f.z.data(), src.fixed_h <= 0 ? f.size() : 0,
                         fluid_reach);
  const Reach near_spheres(s.x.data(), s.y.data(), s.z.data(), s.size(), sphere_reach);
  const auto volume = [&](std::uint32_t b) { return f.mass[b] / f.rho[b]; };
  const Nodes nodes(g);
  const long n = static_cast<long>(eps.size());
  const auto summed = [&](std::vector<double>& v) {
    if (comm.parallel()) comm.sum(v);
  };

  std::vector<double> h_sum, weight;  // h(x): the mobile fluid's Shepard mean
  if (src.fixed_h <= 0) {
    h_sum.assign(n, 0.0);
    weight.assign(n, 0.0);
#pragma omp parallel for schedule(static)
    for (long k = 0; k < n; ++k) {
      const auto [x, y, z] = nodes.at(k);
      if (!near_fluid.holds({x, y, z})) continue;
      fluid_cells.for_each_neighbour(x, y, z, fluid_reach * fluid_reach,
                                     [&](std::uint32_t b, double, double, double, double r2) {
                                       if (f.kind[b] != kFluid) return;
                                       const double vw = volume(b) * kernel::w(r2, f.h[b]);
                                       h_sum[k] += vw * f.h[b];
                                       weight[k] += vw;
                                     });
    }
    summed(h_sum);
    summed(weight);
  }
  const auto h_at = [&](long k) {  // 0: no fluid reaches the node
    if (src.fixed_h > 0) return src.fixed_h;
    return weight[k] > 0.0 ? h_sum[k] / weight[k] : 0.0;
  };

  std::vector<double> solid(n, 0.0), num, shepard;
  if (apart) {
    num.assign(n, 0.0);
    shepard.assign(n, 0.0);
  }
#pragma omp parallel for schedule(static)
  for (long k = 0; k < n; ++k) {
    const double h = h_at(k);
    if (h <= 0.0) continue;
    const auto [x, y, z] = nodes.at(k);
    const double H = src.sphere_kernel_scale * h;
    if (near_spheres.holds({x, y, z}))  // (2.50), the spheres not smoothed apart
      sphere_cells.for_each_neighbour(x, y, z, kernel::kSupport * kernel::kSupport * H * H,
                                      [&](std::uint32_t p, double, double, double, double r2) {
                                        if (!apart || !(*src.is_big)[s.species[p]])
                                          solid[k] += s.volume(p) * kernel::w(r2, H);
                                      });
    if (apart && near_fluid.holds({x, y, z}))  // (3.10): Shepard-interpolated with h(x)
      fluid_cells.for_each_neighbour(x, y, z, kernel::kSupport * kernel::kSupport * h * h,
                                     [&](std::uint32_t b, double, double, double, double r2) {
                                       const double vw = volume(b) * kernel::w(r2, h);
                                       num[k] += vw * (*src.phi)[b];
                                       shepard[k] += vw;
                                     });
  }
  summed(solid);
  if (apart) {
    summed(num);
    summed(shepard);
  }
  for (long k = 0; k < n; ++k) {
    if (h_at(k) <= 0.0) continue;
    double solid_here = solid[k];
    if (apart && shepard[k] > 0.0) solid_here += num[k] / shepard[k];
    eps[k] = 1.0 - solid_here;
  }
  return eps;
}

GridSpec rank_piece(const GridSpec& whole, int rank, int ranks) {
  GridSpec piece = whole;
  const long nz = whole.extent[5] - whole.extent[4] + 1;
  piece.extent[4] = whole.extent[4] + static_cast<int>(nz * rank / ranks);
  piece.extent[5] = whole.extent[4] + static_cast<int>(nz * (rank + 1) / ranks) - 1;
  return piece;
}

std::vector<double> piece_values(const std::vector<double>& values, const GridSpec& whole,
                                 const GridSpec& piece) {
  const long layer = static_cast<long>(whole.extent[1] - whole.extent[0] + 1) *
                     (whole.extent[3] - whole.extent[2] + 1);
  const long first = layer * (piece.extent[4] - whole.extent[4]);
  const long count = layer * std::max(0, piece.extent[5] - piece.extent[4] + 1);
  return {values.begin() + first, values.begin() + first + count};
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
  const RankComm& comm = sim.comm();
  double h_max = 0.0;
  for (std::size_t a = 0; a < f.n_owned; ++a) h_max = std::max(h_max, f.h[a]);
  if (comm.parallel()) h_max = comm.max(h_max);
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
    if (!comm.parallel()) {
      big_cells.build(spheres.x.data(), spheres.y.data(), spheres.z.data(), spheres.size(),
                      c.big_cutoff);
      fluid.n_owned = fluid.size();
      smooth_big_spheres(fluid, spheres, big_cells, c.is_big_species, c.big_h_over_d, big);
    } else {  // at the owned fluid from the run's spheres with their halo copies (which
              // reach big_cutoff); an image takes its original's phi, found by id
      const DemParticles& near = sim.spheres();
      big_cells.build(near.x.data(), near.y.data(), near.z.data(), near.size(), c.big_cutoff);
      smooth_big_spheres(fluid, near, big_cells, c.is_big_species, c.big_h_over_d, big);
      std::unordered_map<std::int64_t, double> owned_phi;
      for (std::size_t a = 0; a < fluid.n_owned; ++a) owned_phi[fluid.id[a]] = big.phi[a];
      big.phi.resize(fluid.size());
      for (std::size_t a = fluid.n_owned; a < fluid.size(); ++a)
        big.phi[a] = owned_phi.at(fluid.id[a]);
    }
    src.is_big = &c.is_big_species;
    src.phi = &big.phi;
  }
  return voidage_at_nodes(src, spec, comm);
}

std::vector<double> grain_voidage_on_grid(const Simulation& sim, const GridSpec& spec, double h) {
  const DemParticles spheres =
      with_periodic_images(sim.spheres(), sim.params().box, kernel::kSupport * h);
  VoidageSources src{sim.fluid(), spheres, 1.0};
  src.fixed_h = h;
  return voidage_at_nodes(src, spec, sim.comm());
}

}  // namespace sphdem
