#pragma once
// The box cut into a grid of cells, each named by its key on a Hilbert curve: the space a
// decomposition over ranks cuts into contiguous key ranges (as SPH-EXA's cstone, on a
// uniform grid instead of an octree). Consecutive keys are face neighbours, so a range of
// keys is a compact region whatever the cut. Knows nothing of SPH or DEM.
#include <array>
#include <cstdint>
#include <vector>

#include "domain/box.hpp"

namespace sphdem {

// The Hilbert key of a point (x, y, z) of a 2^bits cube (Skilling 2004, "Programming the
// Hilbert curve": the axes to the transposed form, then its bits interleaved); bits <= 21.
std::uint64_t hilbert_key(std::uint32_t x, std::uint32_t y, std::uint32_t z, int bits);

// The cell a decomposition over `ranks` cuts the box into, from the reach of the widest
// pair: the reach, halved (at most twice) while the box holds fewer than kCellsPerRank
// cells a rank, so that the cuts can follow the work of a bed that fills a few layers of
// cells (the halo then looks two or four cells out; bench/RESULTS.md, session 32).
inline constexpr std::size_t kCellsPerRank = 64;
double decomposition_cell(const Box& box, double reach, int ranks);

class SfcGrid {
 public:
  // Cells of at least min_cell along every axis (one cell where an axis is shorter), a
  // power of two of them along each (so up to twice min_cell).
  SfcGrid(const Box& box, double min_cell);

  const Box& box() const { return box_; }
  const std::array<int, 3>& cells() const { return n_; }
  std::size_t cell_count() const { return std::size_t(n_[0]) * n_[1] * n_[2]; }
  double cell_size(int d) const { return size_[d]; }
  // The cell holding a point (clamped into the grid: a point on or past a wall is in the
  // last cell).
  std::array<int, 3> cell_of(double x, double y, double z) const;
  std::size_t index(const std::array<int, 3>& c) const {
    return (std::size_t(c[2]) * n_[1] + c[1]) * n_[0] + c[0];
  }
  std::array<int, 3> cell(std::size_t index) const;
  // The squared distance from the point p to the points that fall in the cell with this
  // index: its box, open past the grid's faces on non-periodic axes (cell_of clamps the
  // points there, as wall particles, into the outer cells).
  double distance2_to_cell(std::size_t index, const double p[3]) const;
  std::uint64_t key(const std::array<int, 3>& c) const {
    return hilbert_key(std::uint32_t(c[0]), std::uint32_t(c[1]), std::uint32_t(c[2]), bits_);
  }
  // Every cell's index, in key order.
  const std::vector<std::uint32_t>& curve() const { return curve_; }
  // The position of each cell (by index) along the curve.
  const std::vector<std::uint32_t>& position() const { return position_; }

 private:
  Box box_;
  std::array<int, 3> n_{};
  std::array<double, 3> size_{};
  int bits_ = 0;
  std::vector<std::uint32_t> curve_, position_;
};

}  // namespace sphdem
