#include "scene/initial_state.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "scene/random_packing.hpp"

namespace sphdem {

BlockLattice block_lattice(const Scene& sc, const ParticleGroupSpec& g, double d) {
  BlockLattice L;
  L.fcc = g.fcc;
  const double basis = g.fcc ? 4.0 : 1.0;           // sites per cubic cell
  const double V = basis * M_PI * d * d * d / 6.0;  // solid volume per cell
  const double a = std::cbrt(V / (1.0 - g.voidage));
  for (int k = 0; k < 2; ++k) {
    const double span = g.hi[k] - g.lo[k];
    const bool full =
        sc.box.periodic[k] && std::abs(span - sc.box.length(k)) < 1e-12 * sc.box.length(k);
    L.count[k] = full ? std::max(1, static_cast<int>(std::lround(span / a)))
                      : static_cast<int>(std::floor(span / a + 1e-9));
    L.spacing[k] = full ? span / L.count[k] : a;
  }
  L.spacing[2] = V / ((1.0 - g.voidage) * L.spacing[0] * L.spacing[1]);
  const double span_z = g.hi[2] - g.lo[2];
  if (sc.box.periodic[2] && std::abs(span_z - sc.box.length(2)) < 1e-12 * sc.box.length(2)) {
    // across a periodic height: whole cells (fcc: an even number of layers), so the
    // lattice closes on itself; the voidage follows from the spacings (L.voidage)
    const int cells = std::max(1, static_cast<int>(std::lround(span_z / L.spacing[2])));
    L.spacing[2] = span_z / cells;
  }
  const double dz = g.fcc ? 0.5 * L.spacing[2] : L.spacing[2];  // between layers
  L.count[2] = static_cast<int>(std::floor(span_z / dz + 1e-9));
  for (int k = 0; k < 3; ++k) {
    const double span = g.hi[k] - g.lo[k], step = k == 2 ? dz : L.spacing[k];
    L.origin[k] = g.lo[k] + 0.5 * (span - L.count[k] * step) + 0.5 * step;
  }
  L.voidage = 1.0 - V / (L.spacing[0] * L.spacing[1] * L.spacing[2]);
  return L;
}

BlockLattice block_lattice(const Scene& sc, const ParticleGroupSpec& g) {
  if (g.mixture.size() <= 1)
    return block_lattice(sc, g, sc.species[sc.species_index(g.species)].diameter);
  double d3 = 0.0;
  for (std::size_t i = 0; i < g.mixture.size(); ++i)
    d3 += g.fractions[i] * std::pow(sc.species[sc.species_index(g.mixture[i])].diameter, 3);
  return block_lattice(sc, g, std::cbrt(d3));
}

namespace {

// Species of each of n lattice sites for the number fractions x_i: counts by largest
// remainder (exact to one sphere), then a seeded Fisher-Yates shuffle (the top bits of
// mt19937_64, so the same sites on every standard library).
std::vector<int> deal_species(const Scene& sc, const ParticleGroupSpec& g, std::size_t n) {
  std::vector<int> site(n, sc.species_index(g.species));
  if (g.mixture.size() <= 1) return site;
  const std::size_t m = g.mixture.size();
  std::vector<std::size_t> count(m);
  std::vector<std::pair<double, std::size_t>> remainder;
  std::size_t dealt = 0;
  for (std::size_t i = 0; i < m; ++i) {
    const double want = g.fractions[i] * static_cast<double>(n);
    count[i] = static_cast<std::size_t>(std::floor(want));
    dealt += count[i];
    remainder.emplace_back(want - std::floor(want), i);
  }
  std::sort(remainder.begin(), remainder.end(), [](auto& a, auto& b) { return a.first > b.first; });
  for (std::size_t k = 0; dealt < n; ++k, ++dealt) ++count[remainder[k % m].second];
  std::size_t k = 0;
  for (std::size_t i = 0; i < m; ++i)
    for (std::size_t c = 0; c < count[i]; ++c) site[k++] = sc.species_index(g.mixture[i]);
  std::mt19937_64 rng(static_cast<std::uint64_t>(g.seed));
  for (std::size_t i = n; i > 1; --i) std::swap(site[i - 1], site[(rng() >> 11) % i]);
  return site;
}

}  // namespace

void place_particles(const Scene& sc, FluidParticles& f, DemParticles& s) {
  const double dx = sc.fluid.spacing;
  const int nx = static_cast<int>(std::lround(sc.box.length(0) / dx));
  const int ny = static_cast<int>(std::lround(sc.box.length(1) / dx));
  // periodic in z: the whole height, no wall (the loader has Lz/dx whole)
  const double height = sc.periodic_z() ? sc.box.length(2) : sc.fill_height();
  const int nz = sc.fluid.enabled ? static_cast<int>(std::floor(height / dx + 1e-6)) : 0;
  const int nw = sc.fluid.enabled && !sc.periodic_z() ? sc.fluid.wall_layers : 0;
  const std::size_t n = static_cast<std::size_t>(nx) * ny * (nz + nw);
  f.resize(n);
  f.n_owned = n;
  std::size_t k = 0;
  for (int iz = -nw; iz < nz; ++iz)
    for (int iy = 0; iy < ny; ++iy)
      for (int ix = 0; ix < nx; ++ix, ++k) {
        f.x[k] = (ix + 0.5) * dx;
        f.y[k] = (iy + 0.5) * dx;
        f.z[k] = (iz + 0.5) * dx;
        f.kind[k] = iz < 0 ? kWall : kFluid;
        f.id[k] = static_cast<std::int64_t>(k);
      }

  s.resize(0);
  int group_id = 0;
  for (std::size_t gi = 0; gi < sc.particles.size(); ++gi) {
    const ParticleGroupSpec& g = sc.particles[gi];
    const int sp = sc.species_index(g.species);
    const SpeciesSpec& spec = sc.species[sp];
    const int rigid = g.rigid ? group_id++ : -1;
    // Velocity jitter: uniform in [-1, 1) from the top 53 bits of a seeded generator
    // (the same numbers on every standard library, unlike std::uniform_real_distribution).
    std::mt19937_64 jitter_rng(static_cast<std::uint64_t>(g.velocity_seed));
    auto jitter = [&] {
      return g.velocity_jitter * (2.0 * static_cast<double>(jitter_rng() >> 11) * 0x1.0p-53 - 1.0);
    };
    // A sphere of species k and radius r: mass m = rho_p pi d^3 / 6 (2.35).
    auto add = [&](double x, double y, double z, int k, double r) {
      const std::size_t i = s.size();
      s.resize(i + 1);
      s.x[i] = x;
      s.y[i] = y;
      s.z[i] = z;
      s.vx[i] = g.velocity[0] + jitter();
      s.vy[i] = g.velocity[1] + jitter();
      s.vz[i] = g.velocity[2] + jitter();
      s.radius[i] = r;
      const double d = 2.0 * r;
      s.mass[i] = sc.species[k].density * M_PI * d * d * d / 6.0;
      s.species[i] = static_cast<std::uint16_t>(k);
      s.rigid_group[i] = rigid;
      s.id[i] = static_cast<std::int64_t>(i);
    };
    const double r = 0.5 * spec.diameter;
    if (g.kind == ParticleGroupSpec::Kind::kSingle) {
      add(g.position[0], g.position[1], g.position[2], sp, r);
      continue;
    }
    if (g.kind == ParticleGroupSpec::Kind::kRandom) {
      const RandomPacking P = random_packing(sc, gi, s);
      for (std::size_t j = 0; j < P.x.size(); ++j)
        add(P.x[j], P.y[j], P.z[j], P.species[j], P.radius[j]);
      continue;
    }
    const BlockLattice L = block_lattice(sc, g);
    double d_max = spec.diameter;
    for (const auto& name : g.mixture)
      d_max = std::max(d_max, sc.species[sc.species_index(name)].diameter);
    for (int c = 0; c < 3; ++c) {
      if (L.count[c] < 1)
        throw SceneError(
            fmt::format("{}: key 'particles.{}': the region holds no lattice site along "
                        "axis {} (spacing {} m)",
                        sc.source, gi, "xyz"[c], L.spacing[c]));
      if (L.spacing[c] < d_max * (1.0 - 1e-9))
        throw SceneError(
            fmt::format("{}: key 'particles.{}.voidage': lattice spacing {} m along {} is "
                        "below the largest diameter {} m; raise the voidage or widen the region",
                        sc.source, gi, L.spacing[c], "xyz"[c], d_max));
    }
    if (L.fcc) {  // nearest sites: half a face diagonal, in a layer and between layers
      const double ax = L.spacing[0], ay = L.spacing[1], az = L.spacing[2];
      const double nearest =
          0.5 * std::sqrt(std::min({ax * ax + ay * ay, ax * ax + az * az, ay * ay + az * az}));
      if (nearest < d_max * (1.0 - 1e-9))
        throw SceneError(
            fmt::format("{}: key 'particles.{}.voidage': fcc sites {} m apart, below the largest "
                        "diameter {} m; raise the voidage (fcc packs to 0.2595 at the least)",
                        sc.source, gi, nearest, d_max));
    }
    const double dz = L.fcc ? 0.5 * L.spacing[2] : L.spacing[2];  // between layers
    if (!sc.periodic_z() &&
        (L.origin[2] - 0.5 * dz < 0 || L.origin[2] < 0.5 * d_max * (1.0 - 1e-12)))
      throw SceneError(
          fmt::format("{}: key 'particles.{}.min': the block cuts the bottom wall", sc.source, gi));
    const int per_cell = L.fcc ? 2 : 1;  // sites a cell in one layer
    const std::vector<int> site = deal_species(
        sc, g, static_cast<std::size_t>(L.count[0]) * L.count[1] * L.count[2] * per_cell);
    std::size_t k = 0;
    for (int iz = 0; iz < L.count[2]; ++iz)
      for (int iy = 0; iy < L.count[1]; ++iy)
        for (int ix = 0; ix < L.count[0]; ++ix)
          for (int b = 0; b < per_cell; ++b, ++k) {
            const double p = L.fcc ? 0.5 * (iz % 2) : 0.0;  // the layer's parity shifts its sites
            const double ox = b == 0 ? p : 0.5 - p, oy = b == 0 ? 0.0 : 0.5;
            add(L.origin[0] + (ix + ox) * L.spacing[0], L.origin[1] + (iy + oy) * L.spacing[1],
                L.origin[2] + iz * dz, site[k], 0.5 * sc.species[site[k]].diameter);
          }
  }
  s.n_owned = s.size();
}

}  // namespace sphdem
