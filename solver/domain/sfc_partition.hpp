#pragma once
// A decomposition of the box over ranks: rank r owns the cells at positions
// [first[r], first[r + 1]) along the Hilbert curve of an SfcGrid, cut so that each range
// holds near the same weight (work counters: pair evaluations and contacts per cell, not
// particles, so that a settling bed dense at the bottom and empty at the top is shared
// evenly). And the halo it implies: which cells a rank sends to which, with the periodic
// image the receiver sees them at. Every rank computes the same cuts from the same
// (integer, globally summed) weights, so the decomposition needs no other agreement.
#include <array>
#include <cstdint>
#include <vector>

#include "domain/sfc_grid.hpp"

namespace sphdem {

struct SfcPartition {
  std::vector<std::uint32_t> first;  // ranks + 1 positions along the curve
  int ranks() const { return static_cast<int>(first.size()) - 1; }
  // The rank owning the cell at this position along the curve.
  int owner_at(std::uint32_t position) const;
  int owner(const SfcGrid& grid, const std::array<int, 3>& cell) const {
    return owner_at(grid.position()[grid.index(cell)]);
  }
};

// The curve cut into `ranks` ranges of near-equal weight (by cell index): each cut falls at
// the cell boundary where the running sum is nearest to its share of the total, so every
// range is within one cell's weight of the mean. Zero total weight: equal cell counts.
// Throws std::invalid_argument for ranks < 1 or more ranks than cells.
SfcPartition partition_curve(const SfcGrid& grid, const std::vector<std::uint64_t>& weight,
                             int ranks);

// Each rank's summed weight.
std::vector<std::uint64_t> rank_weights(const SfcGrid& grid, const SfcPartition& part,
                                        const std::vector<std::uint64_t>& weight);
// max / mean of the ranks' weights (1 for zero weight): the load imbalance.
double load_imbalance(const std::vector<std::uint64_t>& rank_weight);

// One cell's particles sent as halo copies to `rank`, shifted there by `image` box lengths
// per axis (0 on a bounded axis); `targets` are the receiver's cells within the reach
// (the particles sent can be limited to those within the reach of one of them).
struct HaloSend {
  std::uint32_t cell = 0;
  int rank = 0;
  std::array<int, 3> image{};
  std::vector<std::uint32_t> targets;  // (not part of the order or equality)
  bool operator<(const HaloSend& o) const;
  bool operator==(const HaloSend& o) const {
    return cell == o.cell && rank == o.rank && image == o.image;
  }
};

// What `rank` sends: each of its cells within `reach` cells per axis of a cell of another
// rank, or of its own through a periodic face, once per destination and image; sorted.
// Pairs closer than reach * cell size along each axis are then complete on both sides.
std::vector<HaloSend> halo_sends(const SfcGrid& grid, const SfcPartition& part, int rank,
                                 const std::array<int, 3>& reach);

}  // namespace sphdem
