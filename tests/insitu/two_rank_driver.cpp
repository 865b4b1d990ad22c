// Test driver for the Catalyst adaptor under MPI (test insitu_two_ranks, two_ranks.sh).
//
//   two_rank_driver OUT_DIR PIPELINES_DIR
//
// Every rank builds the same known particle set (fixed-seed mt19937), owns the spheres
// and fluid particles with index % nranks == rank, computes its z-slab of the voidage
// grid from all spheres (plus their lateral periodic images, as the solver's halos
// would supply) and publishes three frames through InSitu with the reduction
// pipelines voidage_height, interfaces and com_tracks. Run on 1 and on 2 ranks, the
// reduced outputs in OUT_DIR/insitu must agree (compare_ranks.py).
//
// The set is reproducible in Python: uniforms are numpy's random_sample (genrand_res53)
// built from two raw 32-bit mt19937 outputs, drawn in the order documented in
// make_spheres(). Rank 0 also writes OUT_DIR/known_com.csv, the mass-weighted centre of
// mass per species computed here over all spheres, as a cross-check.
#include <mpi.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <exception>
#include <filesystem>
#include <iostream>
#include <random>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "analysis/voidage_grid.hpp"
#include "dem/dem_particles.hpp"
#include "insitu.hpp"
#include "scene/scene.hpp"
#include "sph/fluid_particles.hpp"
#include "sph/kernel.hpp"

namespace {

using namespace sphdem;

constexpr unsigned kSeed = 20240607u;
constexpr int kSpheres = 400;
constexpr int kBand = 370;  // spheres [0, kBand) in the dense band, the rest spread out
constexpr double kLx = 0.0016, kLy = 0.0016, kLz = 0.004;
constexpr double kBandLo = 0.0016, kBandHi = 0.0024;      // dense band (m)
constexpr double kSpreadLo = 0.0005, kSpreadHi = 0.0035;  // sparse spheres (m)
constexpr double kDrop = 2e-4;  // per frame: z -= kDrop * (1 + 0.1 * species)
constexpr double kDiameter[2] = {1.0e-4, 1.6e-4};
constexpr double kDensity[2] = {2500.0, 4000.0};

const char* kSceneYaml = R"(name: two_ranks
description: known particle set for the two-rank in-situ test
domain:
  size: [0.0016, 0.0016, 0.004]
fluid:
  density: 1000
  viscosity: 8.9e-4
  spacing: 2.0e-4
  smoothing_factor: 1.5
species:
  - {name: small, diameter: 1.0e-4, density: 2500}
  - {name: large, diameter: 1.6e-4, density: 4000}
insitu:
  pipelines: [voidage_height, interfaces, com_tracks]
)";

// numpy's random_sample: 53-bit uniform in [0, 1) from two raw 32-bit outputs.
double res53(std::mt19937& g) {
  const std::uint32_t a = static_cast<std::uint32_t>(g()) >> 5,
                      b = static_cast<std::uint32_t>(g()) >> 6;
  return (a * 67108864.0 + b) / 9007199254740992.0;
}

// All spheres, in index order. Per sphere i, four uniforms in this order:
// species (u < 0.5: small), x = Lx u, y = Ly u, z = lo + (hi - lo) u with the band
// range for i < kBand and the spread range otherwise.
DemParticles make_spheres() {
  std::mt19937 g(kSeed);
  DemParticles s;
  s.resize(kSpheres);
  for (int i = 0; i < kSpheres; ++i) {
    const int sp = res53(g) < 0.5 ? 0 : 1;
    const double ux = res53(g), uy = res53(g), uz = res53(g);
    s.species[i] = static_cast<std::uint16_t>(sp);
    s.x[i] = kLx * ux;
    s.y[i] = kLy * uy;
    s.z[i] =
        i < kBand ? kBandLo + (kBandHi - kBandLo) * uz : kSpreadLo + (kSpreadHi - kSpreadLo) * uz;
    s.radius[i] = 0.5 * kDiameter[sp];
    s.mass[i] = kDensity[sp] * s.volume(i);
    s.vz[i] = -kDrop * (1.0 + 0.1 * sp) / 1e-3;
    s.id[i] = i;
    s.rigid_group[i] = -1;
    s.eps[i] = 1.0;
    s.shepard[i] = 1.0;
  }
  s.n_owned = kSpheres;
  return s;
}

// Fluid lattice at the scene spacing, cell-centred, filling the box.
FluidParticles make_fluid(const Scene& sc) {
  const double dx = sc.fluid.spacing, h = sc.fluid.lattice_h();
  const int nx = static_cast<int>(std::lround(kLx / dx)),
            ny = static_cast<int>(std::lround(kLy / dx)),
            nz = static_cast<int>(std::lround(kLz / dx));
  FluidParticles f;
  f.resize(static_cast<std::size_t>(nx) * ny * nz);
  std::size_t a = 0;
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i, ++a) {
        f.x[a] = (i + 0.5) * dx;
        f.y[a] = (j + 0.5) * dx;
        f.z[a] = (k + 0.5) * dx;
        f.vx[a] = f.vy[a] = 0.0;
        f.vz[a] = 1e-3 * std::sin(0.1 * static_cast<double>(a));
        f.eps[a] = 1.0;
        f.rho[a] = sc.fluid.density * f.eps[a];
        f.mass[a] = sc.fluid.density * dx * dx * dx;
        f.P[a] = sc.fluid.density * 9.81 * (kLz - f.z[a]);
        f.h[a] = h;
        f.inv_h[a] = 1.0 / h;
        f.kind[a] = kFluid;
        f.id[a] = static_cast<std::int64_t>(a);
      }
  f.n_owned = f.size();
  return f;
}

// The entries with index % nranks == rank, every field copied.
template <class P>
P owned_part(const P& all, int rank, int nranks) {
  std::vector<std::size_t> idx;
  for (std::size_t i = static_cast<std::size_t>(rank); i < all.size();
       i += static_cast<std::size_t>(nranks))
    idx.push_back(i);
  P out;
  out.resize(idx.size());
  all.for_each_field([&](const FieldInfo& field, const auto& v) {
    out.for_each_field([&](const FieldInfo& ofield, auto& w) {
      if constexpr (std::is_same_v<std::decay_t<decltype(v)>, std::decay_t<decltype(w)>>)
        if (std::strcmp(field.name, ofield.name) == 0)
          for (std::size_t k = 0; k < idx.size(); ++k) w[k] = v[idx[k]];
    });
  });
  out.n_owned = idx.size();
  return out;
}

// All spheres followed by their 8 lateral periodic images (radius and position only:
// all that the voidage grid reads), so the kernel mass that crosses a periodic face
// comes back through the opposite one, as with the solver's halo copies.
void write_known_com(const std::string& path, const std::vector<std::vector<double>>& rows) {
  FILE* f = std::fopen(path.c_str(), "w");
  if (!f) throw std::runtime_error("cannot write " + path);
  std::fprintf(f, "time,com_z:small,com_z:large,com_z:all,solid_volume\n");
  for (const auto& r : rows) {
    for (std::size_t c = 0; c < r.size(); ++c) std::fprintf(f, c ? ",%.17g" : "%.17g", r[c]);
    std::fprintf(f, "\n");
  }
  std::fclose(f);
}

int run(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: two_rank_driver OUT_DIR PIPELINES_DIR\n";
    return 2;
  }
  int rank = 0, nranks = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &nranks);

  const Scene scene = load_scene_text(kSceneYaml, "two_rank_driver");
  const double reach = kernel::kSupport * scene.fluid.lattice_h();
  const GridSpec whole = column_voidage_grid(scene.box.length(0), scene.box.length(1),
                                             scene.fill_height(), scene.insitu.grid_spacing);

  // this rank's contiguous slab of z nodes
  GridSpec piece = whole;
  const int k0 = whole.extent[4], nk = whole.extent[5] - whole.extent[4] + 1;
  piece.extent[4] = k0 + rank * nk / nranks;
  piece.extent[5] = k0 + (rank + 1) * nk / nranks - 1;

  DemParticles all = make_spheres();
  const FluidParticles fluid_all = make_fluid(scene);
  const FluidParticles fluid = owned_part(fluid_all, rank, nranks);
  const FluidParticles fluid_images = with_periodic_images(fluid_all, scene.box, reach);

  InSituOptions io;
  io.out_dir = argv[1];
  io.pipelines_dir = argv[2];
  io.want_images = false;
  std::vector<std::vector<double>> known;
  std::size_t owned_spheres = 0;
  // published through zero-copy views: declared before the InSitu so that they outlive it
  DemParticles spheres;
  std::vector<double> voidage;
  {
    InSitu insitu(scene, io);
    for (int frame = 0; frame < 3; ++frame) {
      if (frame > 0)
        for (std::size_t i = 0; i < all.size(); ++i)
          all.z[i] -= kDrop * (1.0 + 0.1 * all.species[i]);

      spheres = owned_part(all, rank, nranks);
      owned_spheres = spheres.n_owned;
      // every rank sums over all particles, with their periodic images
      const DemParticles sphere_images = with_periodic_images(all, scene.box, reach);
      voidage = voidage_at_nodes({fluid_images, sphere_images}, piece);

      InSituFrame fr;
      fr.fluid = &fluid;
      fr.spheres = &spheres;
      fr.grid = piece;
      fr.whole_extent = whole.extent;
      fr.voidage = &voidage;
      fr.time = 1e-3 * frame;
      fr.step = frame;
      insitu.execute(fr);

      // the known answer, over all spheres
      double mz[2] = {0, 0}, m[2] = {0, 0}, vol = 0;
      for (std::size_t i = 0; i < all.size(); ++i) {
        mz[all.species[i]] += all.mass[i] * all.z[i];
        m[all.species[i]] += all.mass[i];
        vol += all.volume(i);
      }
      known.push_back({fr.time, mz[0] / m[0], mz[1] / m[1], (mz[0] + mz[1]) / (m[0] + m[1]), vol});
    }
  }  // InSitu finalized here: pipelines flush
  if (rank == 0)
    write_known_com((std::filesystem::path(argv[1]) / "known_com.csv").string(), known);
  std::cout << "two_rank_driver: rank " << rank << " owned " << owned_spheres << " spheres, "
            << fluid.n_owned << " fluid particles, z nodes " << piece.extent[4] << ".."
            << piece.extent[5] << std::endl;
  MPI_Barrier(MPI_COMM_WORLD);
  if (rank == 0)
    std::cout << "two_rank_driver: " << nranks << " rank(s), " << kSpheres << " spheres, "
              << fluid_all.size() << " fluid particles, grid z nodes " << whole.extent[4] << ".."
              << whole.extent[5] << "\n";
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  int rc = 0;
  try {
    rc = run(argc, argv);
  } catch (const std::exception& e) {
    std::cerr << "two_rank_driver: error: " << e.what() << "\n";
    MPI_Abort(MPI_COMM_WORLD, 1);
  }
  MPI_Finalize();
  return rc;
}
