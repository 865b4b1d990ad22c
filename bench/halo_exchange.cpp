// The decomposition's communication on R ranks, weak scaling: N particles per rank on a
// jittered lattice of spacing dx in a periodic cube of (N R)^(1/3) dx, the SPH reach
// 2 h = 2.6 dx, cells of half the reach. Prints one line per rank count (rank 0): the
// ghosts per owned particle (largest and mean over ranks) against the model of a cubic
// sub-domain ((n^(1/3) + 2w)^3 - n) / n with w the reach in spacings, the bytes received per owned
// particle by a fill of 8 doubles, the medians of 20 fills and of 20 reverse scatters
// (3 doubles) and the halo build (its cells' plan made once per decomposition, so the
// builds after the first), the load imbalance, and the ping-pong latency and bandwidth
// between ranks 0 and 1 (0 on one rank). Ghost counts do not depend on the cores: run
// oversubscribed they are exact, the times are not.
//
//   mpirun -np R build/bench/halo_exchange N
#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <vector>

#include "domain/rank_comm.hpp"
#include "domain/rank_halo.hpp"
#include "domain/sfc_grid.hpp"
#include "domain/sfc_partition.hpp"

namespace {

struct Points {
  std::vector<double> x, y, z;
  std::vector<std::int64_t> id;
  std::size_t n_owned = 0;
  template <class F>
  void for_each_field(F&& f) {
    f(sphdem::FieldInfo{"x", sphdem::kState}, x);
    f(sphdem::FieldInfo{"y", sphdem::kState}, y);
    f(sphdem::FieldInfo{"z", sphdem::kState}, z);
    f(sphdem::FieldInfo{"id", sphdem::kState}, id);
  }
};

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

// one-way time of a message of `bytes` between ranks 0 and 1 (median of 50 round trips)
double ping_pong(const sphdem::RankComm& comm, std::size_t bytes) {
  if (comm.size() < 2) return 0.0;
  std::vector<char> buf(std::max<std::size_t>(bytes, 1));
  std::vector<double> t;
  for (int k = 0; k < 50; ++k) {
    MPI_Barrier(comm.comm());
    const double t0 = MPI_Wtime();
    if (comm.rank() == 0) {
      MPI_Send(buf.data(), int(bytes), MPI_BYTE, 1, 0, comm.comm());
      MPI_Recv(buf.data(), int(bytes), MPI_BYTE, 1, 0, comm.comm(), MPI_STATUS_IGNORE);
    } else if (comm.rank() == 1) {
      MPI_Recv(buf.data(), int(bytes), MPI_BYTE, 0, 0, comm.comm(), MPI_STATUS_IGNORE);
      MPI_Send(buf.data(), int(bytes), MPI_BYTE, 0, 0, comm.comm());
    }
    t.push_back(0.5 * (MPI_Wtime() - t0));
  }
  return median(t);
}

}  // namespace

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  {
    const sphdem::RankComm comm;
    const int R = comm.size(), me = comm.rank();
    const long n_per_rank = argc > 1 ? std::atol(argv[1]) : 10000;
    const double dx = 1.0, reach = 2.6 * dx;
    const int side = static_cast<int>(std::lround(std::cbrt(double(n_per_rank) * R)));
    const long n = long(side) * side * side;
    const double L = side * dx;
    sphdem::Box box{{0, 0, 0}, {L, L, L}, {true, true, true}};
    Points p;
    std::mt19937_64 rng(1);
    std::uniform_real_distribution<double> jitter(-0.1 * dx, 0.1 * dx);
    for (long i = 0; i < n; ++i) {  // every rank draws the same set, keeps a slice
      const double q[3] = {(i % side + 0.5) * dx + jitter(rng),
                           ((i / side) % side + 0.5) * dx + jitter(rng),
                           (i / (long(side) * side) + 0.5) * dx + jitter(rng)};
      if (i * R / n != me) continue;
      p.x.push_back(q[0]);
      p.y.push_back(q[1]);
      p.z.push_back(q[2]);
      p.id.push_back(i);
    }
    p.n_owned = p.x.size();
    const sphdem::SfcGrid grid(box, 0.5 * reach);
    std::vector<std::uint64_t> w(grid.cell_count(), 0);
    for (std::size_t i = 0; i < p.n_owned; ++i)
      ++w[grid.index(grid.cell_of(p.x[i], p.y[i], p.z[i]))];
    comm.sum(w);
    const sphdem::SfcPartition part = sphdem::partition_curve(grid, w, R);
    std::vector<int> dest(p.n_owned);
    for (std::size_t i = 0; i < p.n_owned; ++i)
      dest[i] = part.owner(grid, grid.cell_of(p.x[i], p.y[i], p.z[i]));
    MPI_Barrier(comm.comm());
    double t0 = MPI_Wtime();
    sphdem::migrate(comm, p, dest);
    const double t_migrate = comm.max(MPI_Wtime() - t0);
    sphdem::RankHalo halo;
    std::vector<double> t_build;
    for (int r = 0; r < 5; ++r) {
      MPI_Barrier(comm.comm());
      t0 = MPI_Wtime();
      halo.build(comm, grid, part, reach, p.x.data(), p.y.data(), p.z.data(), p.n_owned);
      t_build.push_back(comm.max(MPI_Wtime() - t0));
    }
    const std::size_t total = p.n_owned + halo.n_ghost();
    std::vector<std::vector<double>> fields(8, std::vector<double>(total, 1.0));
    std::vector<double> t_fill, t_scatter, rows(3 * total, 1.0);
    for (int r = 0; r < 20; ++r) {
      MPI_Barrier(comm.comm());
      t0 = MPI_Wtime();
      for (auto& f : fields) halo.fill(comm, f);
      t_fill.push_back(comm.max(MPI_Wtime() - t0));
      MPI_Barrier(comm.comm());
      t0 = MPI_Wtime();
      halo.add_to_sources(comm, rows.data(), 3);
      t_scatter.push_back(comm.max(MPI_Wtime() - t0));
    }
    const double ratio = double(halo.n_ghost()) / double(std::max<std::size_t>(p.n_owned, 1));
    const double ratio_max = comm.max(ratio);
    const double ratio_mean = double(comm.sum(halo.n_ghost())) / double(n);
    std::vector<std::uint64_t> rw(R, 0);
    rw[me] = p.n_owned;
    comm.sum(rw);
    const double m = double(n) / R, wr = reach / dx;
    const double model = std::pow(std::cbrt(m) + 2 * wr, 3) / m - 1.0;
    const double lat = ping_pong(comm, 8), big = ping_pong(comm, 1000000);
    const double bw = big > 0.0 ? 1e6 / big : 0.0;
    if (me == 0)
      std::printf(
          "ranks %d per_rank %.0f ghosts/owned max %.3f mean %.3f model_cube %.3f "
          "bytes/owned/fill8 %.1f fill8_ms %.3f scatter3_ms %.3f build_ms %.3f migrate_ms %.3f "
          "imbalance %.4f latency_us %.2f bandwidth_GBps %.2f\n",
          R, m, ratio_max, ratio_mean, model, 64.0 * ratio_mean, 1e3 * median(t_fill),
          1e3 * median(t_scatter), 1e3 * median(t_build), 1e3 * t_migrate,
          sphdem::load_imbalance(rw), 1e6 * lat, bw / 1e9);
  }
  MPI_Finalize();
  return 0;
}
