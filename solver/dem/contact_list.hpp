#pragma once
#include <cstdint>
#include <vector>

#include "dem/dem_particles.hpp"
#include "domain/cell_list.hpp"
#include "domain/compressed_rows.hpp"

namespace sphdem {

// Verlet list for sphere contacts: for each owned sphere, every sphere (owned or
// halo) within r_i + r_j + skin. A full list: each owned sphere sums the forces on
// itself only, so threads never write to the same sphere; the pair force is written
// antisymmetrically, so action and reaction cancel exactly.
struct ContactNeighbourList {
  std::vector<std::uint32_t> offset, neighbour;
  double skin = 0.0;
  void build(const DemParticles& s, const CellList& cells, double skin);

 private:
  CompressedRowBuilder rows_;
};

}  // namespace sphdem
