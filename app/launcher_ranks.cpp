#include "launcher_ranks.hpp"

#include <fmt/format.h>

#include <cstdlib>

namespace sphdem {

namespace {

int read_count(const char* text, int fallback) {
  if (!text || !*text) return fallback;
  char* end = nullptr;
  const long v = std::strtol(text, &end, 10);
  return (*end == '\0' && v >= 0 && v < 1L << 30) ? static_cast<int>(v) : fallback;
}

}  // namespace

LauncherRanks launcher_ranks(const char* (*getenv)(const char*)) {
  LauncherRanks r;
  for (const auto& [size, rank] : {std::pair{"OMPI_COMM_WORLD_SIZE", "OMPI_COMM_WORLD_RANK"},
                                   std::pair{"PMI_SIZE", "PMI_RANK"}}) {
    const int n = read_count(getenv(size), 0);
    if (n > 1) {
      r.size = n;
      r.rank = read_count(getenv(rank), 0);
      r.variable = size;
      return r;
    }
  }
  return r;
}

std::string one_process_message(const LauncherRanks& r) {
  return fmt::format(
      "sphdem: error: started as {} MPI ranks ({}={}); sphdem runs a scene on one process "
      "so far, its threads set by OMP_NUM_THREADS, and under mpirun every rank would run the "
      "whole scene into the same files. Run it without mpirun, e.g. OMP_NUM_THREADS=4 sphdem "
      "run CASE\n",
      r.size, r.variable, r.size);
}

}  // namespace sphdem
