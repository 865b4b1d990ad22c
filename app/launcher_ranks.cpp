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

std::string one_process_message(const LauncherRanks& r, const std::string& command) {
  return fmt::format(
      "sphdem: error: `sphdem {}` started as {} MPI ranks ({}={}); only `run` and `resume` "
      "share a scene over ranks (and rank 0 makes `figures`). Run `sphdem {}` without mpirun\n",
      command, r.size, r.variable, r.size, command);
}

}  // namespace sphdem
