#pragma once
// main() of an MPI GoogleTest program: MPI around the tests, one rank's report, and a
// failure on any rank failing every rank. argv[1]: the rank count the test expects (the
// tests assert it: a launcher that starts R one-rank jobs must fail them).
#include <gtest/gtest.h>
#include <mpi.h>

#include <cstdlib>

namespace sphdem {

inline int run_mpi_gtests(int argc, char** argv, int& expected_ranks) {
  MPI_Init(&argc, &argv);
  ::testing::InitGoogleTest(&argc, argv);
  expected_ranks = argc > 1 ? std::atoi(argv[1]) : 1;
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  if (rank != 0) {
    auto& listeners = ::testing::UnitTest::GetInstance()->listeners();
    delete listeners.Release(listeners.default_result_printer());
  }
  int failed = RUN_ALL_TESTS() != 0, any = 0;
  MPI_Allreduce(&failed, &any, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
  MPI_Finalize();
  return any;
}

}  // namespace sphdem
