#include "scene/random_packing.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <random>

#include "scene/collective_rearrangement.hpp"
#include "scene/size_distribution.hpp"
#include "scene/sphere_grid.hpp"

namespace sphdem {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr std::size_t kMaxSpheres = 20'000'000;

double sphere_volume(double d) {
  return kPi * d * d * d / 6.0;
}

std::mt19937_64 stream(std::int64_t seed, std::uint32_t which) {
  const auto s = static_cast<std::uint64_t>(seed);
  std::seed_seq seq{static_cast<std::uint32_t>(s), static_cast<std::uint32_t>(s >> 32), which};
  return std::mt19937_64(seq);
}

// Where the centre of a sphere of radius r may lie, [lo, lo + width) along each axis: the
// whole span of an axis the group fills periodically, else the region less r at each face.
struct CentreRange {
  std::array<double, 3> lo{}, width{};

  std::array<double, 3> draw(std::mt19937_64& rng) const {
    std::array<double, 3> c{};
    for (int a = 0; a < 3; ++a) c[a] = lo[a] + width[a] * uniform01(rng);
    return c;
  }
};

CentreRange centre_range(const ParticleGroupSpec& g, const std::array<double, 3>& span,
                         const std::array<bool, 3>& full, double r) {
  CentreRange out;
  for (int a = 0; a < 3; ++a) {
    out.lo[a] = full[a] ? g.lo[a] : g.lo[a] + r;
    out.width[a] = full[a] ? span[a] : span[a] - 2.0 * r;
  }
  return out;
}

}  // namespace

RandomPacking random_packing(const Scene& sc, std::size_t gi, const DemParticles& existing) {
  const ParticleGroupSpec& g = sc.particles[gi];
  auto fail = [&](const char* key, const std::string& what) {
    throw SceneError(fmt::format("{}: key 'particles.{}.{}': {}", sc.source, gi, key, what));
  };
  std::array<double, 3> span{};
  for (int a = 0; a < 3; ++a) span[a] = g.hi[a] - g.lo[a];
  const double v_region = span[0] * span[1] * span[2];
  const double v_target = (1.0 - g.voidage) * v_region;

  // 1. The spheres: species dealt by number fraction, diameters drawn from their laws,
  //    kept while each brings the solid volume closer to the target.
  std::vector<std::uint16_t> species_of;  // mixture entry -> Scene::species index
  std::vector<SizeSampler> samplers;
  for (const auto& name : g.mixture) {
    const int s = sc.species_index(name);
    species_of.push_back(static_cast<std::uint16_t>(s));
    samplers.emplace_back(sc.species[s].size);
  }
  QuotaDealer dealer(g.fractions);
  std::mt19937_64 size_rng = stream(g.seed, 1), position_rng = stream(g.seed, 2);
  std::vector<double> diameter;
  std::vector<std::uint16_t> species;
  double v_solid = 0.0;
  for (;;) {
    const std::size_t k = dealer.next();
    const double d = samplers[k].next(size_rng);
    const double v = sphere_volume(d);
    if (v_solid + 0.5 * v > v_target) break;
    v_solid += v;
    diameter.push_back(d);
    species.push_back(species_of[k]);
    if (diameter.size() > kMaxSpheres)
      fail("voidage", fmt::format("the region would hold more than {} spheres", kMaxSpheres));
  }
  if (diameter.empty())
    fail("voidage",
         fmt::format("the region holds less than half a sphere at voidage {}; raise its size or "
                     "lower the voidage",
                     g.voidage));

  // 2. Largest first (the hardest to place while there is room); ties keep draw order.
  std::vector<std::size_t> order(diameter.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t i, std::size_t j) { return diameter[i] > diameter[j]; });
  const double d_max = diameter[order.front()];

  // 3. Where centres may go: periodic across a whole periodic width, else inside the region.
  std::array<bool, 3> full{};
  for (int a = 0; a < 3; ++a) {
    full[a] =
        sc.box.periodic[a] && std::abs(span[a] - sc.box.length(a)) <= 1e-12 * sc.box.length(a);
    if (!full[a] && span[a] < d_max)
      fail("max",
           fmt::format("the region is {} m wide along {}, less than the largest diameter {} m",
                       span[a], "xyz"[a], d_max));
  }

  // 4. The grid holds the earlier groups' spheres that reach into the region's z range.
  double r_other = 0.0;
  std::vector<std::size_t> others;
  for (std::size_t j = 0; j < existing.size(); ++j)
    if (existing.z[j] + existing.radius[j] > g.lo[2] &&
        existing.z[j] - existing.radius[j] < g.hi[2]) {
      others.push_back(j);
      r_other = std::max(r_other, existing.radius[j]);
    }
  const double zlo = full[2] ? sc.box.lo[2] : g.lo[2] - r_other;
  const double zhi = full[2] ? sc.box.hi[2] : g.hi[2] + r_other;
  const double reach = 0.5 * d_max + std::max(0.5 * d_max, r_other);  // largest contact distance
  const double v_grid = sc.box.length(0) * sc.box.length(1) * (zhi - zlo);
  const double n_all = static_cast<double>(diameter.size() + others.size());
  SphereGrid grid(sc.box, zlo, zhi, std::max(reach, std::cbrt(v_grid / n_all)),  // ~1 a cell
                  full[2]);
  for (std::size_t j : others)
    grid.insert(existing.x[j], existing.y[j], existing.z[j], existing.radius[j]);

  RandomPacking out;
  const std::size_t n = diameter.size();
  if (g.voidage < kRearrangeBelow) {
    // 5'. Collective rearrangement: every centre drawn at once (clear of the earlier
    //     groups), the overlaps pushed apart.
    PlacementRegion where{g.lo, span, full};
    FixedSpheres fixed;
    for (std::size_t j : others) {
      fixed.x.push_back(existing.x[j]);
      fixed.y.push_back(existing.y[j]);
      fixed.z.push_back(existing.z[j]);
      fixed.radius.push_back(existing.radius[j]);
    }
    for (std::size_t k = 0; k < n; ++k) {
      const std::size_t i = order[k];
      const double r = 0.5 * diameter[i];
      out.radius.push_back(r);
      out.species.push_back(species[i]);
      const CentreRange range = centre_range(g, span, full, r);
      std::array<double, 3> c{};
      std::uint64_t tries = 0;
      do {  // outside the earlier groups' spheres, which do not move
        if (tries++ == kRsaAttemptsPerSphere)
          fail("voidage", fmt::format("{} random centres for sphere {} all overlapped an earlier "
                                      "group's spheres: the region is full",
                                      tries - 1, k));
        c = range.draw(position_rng);
      } while (grid.overlaps(c[0], c[1], c[2], r));
      out.attempts += tries;
      out.x.push_back(c[0]);
      out.y.push_back(c[1]);
      out.z.push_back(c[2]);
    }
    const Rearrangement R = rearrange(where, fixed, grid, out.x, out.y, out.z, out.radius);
    out.sweeps = R.sweeps;
    if (!R.converged)
      fail("voidage",
           fmt::format("collective rearrangement left spheres overlapping by {:.2g} of their "
                       "contact distance after {} sweeps at solid fraction {:.4f} (voidage {}); it "
                       "packs equal spheres to a solid fraction of 0.58-0.6 (random close "
                       "packing is 0.64): raise the voidage or use a lattice (lattice: fcc packs "
                       "to voidage 0.2595)",
                       R.overlap, R.sweeps, 1.0 - g.voidage, g.voidage));
    double v_placed = 0.0;
    for (double d : diameter) v_placed += sphere_volume(d);
    out.voidage = 1.0 - v_placed / v_region;
    return out;
  }

  // 5. Random sequential addition.
  for (auto* v : {&out.x, &out.y, &out.z, &out.radius}) v->reserve(n);
  out.species.reserve(n);
  double v_placed = 0.0;
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t i = order[k];
    const double r = 0.5 * diameter[i];
    const CentreRange range = centre_range(g, span, full, r);
    std::uint64_t tries = 0;
    for (;;) {
      if (tries == kRsaAttemptsPerSphere)
        fail("voidage", fmt::format("random sequential addition jammed at solid fraction {:.4f} "
                                    "({} of {} spheres placed; "
                                    "{} random centres for the next sphere, d = {:.4g} m, all "
                                    "overlapped) short of the target "
                                    "{:.4f} (voidage {}). RSA of equal spheres cannot pass a solid "
                                    "fraction of {} (voidage "
                                    "{:.3f}) and slows down well before it: raise the voidage "
                                    "(0.65 or more is safe for equal "
                                    "spheres) or widen the size distribution",
                                    v_placed / v_region, k, n, tries, 2.0 * r, 1.0 - g.voidage,
                                    g.voidage, kRsaSaturation, 1.0 - kRsaSaturation));
      ++tries;
      const auto [x, y, z] = range.draw(position_rng);
      if (grid.overlaps(x, y, z, r)) continue;
      grid.insert(x, y, z, r);
      out.x.push_back(x);
      out.y.push_back(y);
      out.z.push_back(z);
      out.radius.push_back(r);
      out.species.push_back(species[i]);
      v_placed += sphere_volume(diameter[i]);
      break;
    }
    out.attempts += tries;
  }
  out.voidage = 1.0 - v_placed / v_region;
  return out;
}

}  // namespace sphdem
