#pragma once
// Neighbour list in compressed rows: for each query point i (an owned particle),
// the indices of the binned points within the cut-off. Built once per step from a
// cell list, then walked by every pass that shares the cut-off, so the cell walk
// (about 7 candidates per true neighbour) is paid once, not once per pass.
#include <cstdint>
#include <vector>

#include "domain/cell_list.hpp"
#include "domain/compressed_rows.hpp"

namespace sphdem {

struct NeighbourList {
  std::vector<std::uint32_t> offset;     // size n_query + 1
  std::vector<std::uint32_t> neighbour;  // indices into the binned points

  std::size_t size() const { return offset.empty() ? 0 : offset.size() - 1; }
  std::uint32_t begin(std::size_t i) const { return offset[i]; }
  std::uint32_t end(std::size_t i) const { return offset[i + 1]; }

  // Points j of `cells` with |x_i - x_j| < rc for i in [0, n_query); self excluded
  // when exclude_self (query i and binned i are the same particle). With half, a pair
  // of query points is listed once (j > i); points j >= n_query (halo copies) are
  // always listed, since their owners compute the mirror pair themselves.
  void build(const CellList& cells, const double* x, const double* y, const double* z,
             std::size_t n_query, double rc, bool exclude_self, bool half = false);
  // Each query i's own cut-off rc[i] (<= the cells' size): points j within rc[i] of i.
  void build_within(const CellList& cells, const double* x, const double* y, const double* z,
                    std::size_t n_query, const double* rc);
  // A half list of the points themselves (no self) with a cut-off per pair,
  // max(reach[i], reach[j]) (<= the cells' size); reach covers every binned point.
  void build_half_within(const CellList& cells, const double* x, const double* y, const double* z,
                         std::size_t n_query, const double* reach);

 private:
  CompressedRowBuilder rows_;
};

}  // namespace sphdem
