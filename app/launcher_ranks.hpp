#pragma once
// How many MPI ranks a launcher started this process as, read from what mpirun gives each
// process in its environment (Open MPI: OMPI_COMM_WORLD_SIZE and _RANK; MPICH, Intel MPI:
// PMI_SIZE and PMI_RANK), without initialising MPI. The solver runs a scene on one
// process: under `mpirun -np N` every rank would run the whole scene into the same files.
#include <string>

namespace sphdem {

struct LauncherRanks {
  int size = 1, rank = 0;
  std::string variable;  // the environment variable that gave the size ("" when 1)
};

// getenv reads the environment (std::getenv in the program; a table in the tests).
LauncherRanks launcher_ranks(const char* (*getenv)(const char*));

// The refusal printed (by rank 0 only) when size > 1.
std::string one_process_message(const LauncherRanks& r);

}  // namespace sphdem
