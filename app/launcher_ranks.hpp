#pragma once
// How many MPI ranks a launcher started this process as, read from what mpirun gives each
// process in its environment (Open MPI: OMPI_COMM_WORLD_SIZE and _RANK; MPICH, Intel MPI:
// PMI_SIZE and PMI_RANK), without initialising MPI: `run` and `resume` then share the scene
// over the ranks (MPI initialised for them only), every other command is refused.
#include <string>

namespace sphdem {

struct LauncherRanks {
  int size = 1, rank = 0;
  std::string variable;  // the environment variable that gave the size ("" when 1)
};

// getenv reads the environment (std::getenv in the program; a table in the tests).
LauncherRanks launcher_ranks(const char* (*getenv)(const char*));

// The refusal printed (by rank 0 only) when a command other than run or resume is
// started on size > 1 ranks.
std::string one_process_message(const LauncherRanks& r, const std::string& command);

}  // namespace sphdem
