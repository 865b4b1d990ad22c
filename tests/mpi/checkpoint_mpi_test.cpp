// One checkpoint file written by R ranks together (parallel HDF5, io/checkpoint_file.hpp):
// each rank holds an uneven slice of a global array (one rank none when R >= 3); the
// file must read back whole with its checksum (the slices' CRCs combined in rank order
// equal the serial CRC of the whole array) and hold what one rank writing the whole
// arrays holds, entry for entry.
//
//   mpirun -np R checkpoint_mpi_test R WORK_DIR
#include <gtest/gtest.h>
#include <mpi.h>

#include <cstdlib>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include "domain/rank_comm.hpp"
#include "io/checkpoint_file.hpp"
#include "mpi_gtest_main.hpp"

namespace sphdem {
namespace {

int g_expected_ranks = 0;
std::string g_work;

TEST(RanksCheckpoint, OneFileFromEveryRankReadsBackWhole) {
  const RankComm comm;
  ASSERT_EQ(comm.size(), g_expected_ranks) << "the launcher started other rank counts";
  const int R = comm.size(), me = comm.rank();
  const std::size_t N = 1237;
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<double> x(N);
  std::vector<std::int64_t> id(N);
  for (std::size_t i = 0; i < N; ++i) {
    x[i] = u(rng);
    id[i] = static_cast<std::int64_t>(1000 + 7 * i);
  }
  // uneven slices by weights r + 1, rank 1 empty when R >= 3
  std::vector<std::size_t> first(R + 1, 0);
  std::size_t wsum = 0;
  for (int r = 0; r < R; ++r) wsum += (R >= 3 && r == 1) ? 0 : r + 1;
  std::size_t acc = 0;
  for (int r = 0; r < R; ++r) {
    acc += (R >= 3 && r == 1) ? 0 : r + 1;
    first[r + 1] = N * acc / wsum;
  }
  const std::size_t lo = first[me], n = first[me + 1] - first[me];
  const std::string parallel = g_work + "/parallel.h5", serial = g_work + "/serial.h5";
  {
    CheckpointWriter w(parallel, comm);
    w.scalar("run/time", 0.125);
    w.text("scene/yaml", "name: ranks\n");
    w.distributed("fluid/x", x.data() + lo, n);
    w.distributed("fluid/id", id.data() + lo, n);
    w.finish();
  }
  if (me == 0) {
    CheckpointWriter w(serial);
    w.scalar("run/time", 0.125);
    w.text("scene/yaml", "name: ranks\n");
    w.array("fluid/x", x);
    w.array("fluid/id", id);
    w.finish();
  }
  MPI_Barrier(comm.comm());
  // every rank reads the one file (as a resume on any rank count would)
  const CheckpointReader p(parallel);
  EXPECT_EQ(p.array<double>("fluid/x"), x);
  EXPECT_EQ(p.array<std::int64_t>("fluid/id"), id);
  EXPECT_EQ(p.scalar<double>("run/time"), 0.125);
  EXPECT_EQ(p.text("scene/yaml"), "name: ranks\n");
  const CheckpointReader s(serial);
  for (const char* group : {"fluid/", "run/", "scene/"}) EXPECT_EQ(p.names(group), s.names(group));
}

}  // namespace
}  // namespace sphdem

int main(int argc, char** argv) {
  sphdem::g_work = argc > 2 ? argv[2] : ".";
  std::filesystem::create_directories(sphdem::g_work);  // (every rank: no race, it exists after)
  return sphdem::run_mpi_gtests(argc, argv, sphdem::g_expected_ranks);
}
