#pragma once
// What `sphdem check --ranks R` says of a scene on R ranks, from its state on one: the cuts
// the decomposition would make by the work counted per cell (the fluid's pairs and each
// sphere's contact row in every sub-step, as Simulation counts them), and from them each
// rank's owned particles, its halo copies (the particles within the reach of its cells,
// or of its own across a periodic face, as RankHalo sends them) and its share of the work.
#include <cstddef>

namespace sphdem {

class Simulation;

struct RankForecast {
  int ranks = 1;
  std::size_t owned_max = 0;    // the most particles (fluid + spheres) one rank owns
  std::size_t ghosts_max = 0;   // the most halo copies one rank holds
  double ghosts_per_owned = 0;  // over all ranks
  double largest_share = 1;     // the largest rank's work over the total
};

// sim: a scene on one rank after at least one step (its lists and sub-step count).
RankForecast forecast_ranks(const Simulation& sim, int ranks);

}  // namespace sphdem
