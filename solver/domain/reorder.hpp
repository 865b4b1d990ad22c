#pragma once
// Reordering of owned particles (e.g. into cell order, for memory locality): every
// field of a structure-of-arrays container is permuted, halo copies are dropped.
#include <cstdint>
#include <vector>

#include "domain/cell_list.hpp"
#include "domain/field_info.hpp"

namespace sphdem {

// new index i <- old index perm[i], for every field the container lists, in place: the
// permutation's cycles once, then each field along them (no copy of a field: a copy of
// every array of a large run is memory the system maps afresh, page by page, at each sort).
template <class Particles>
void permute_owned(Particles& p, const std::vector<std::uint32_t>& perm) {
  const std::size_t n = perm.size();
  // cycles as runs of `cycle`: start, perm[start], perm[perm[start]], ...
  std::vector<std::uint32_t> cycle, cycle_end;
  std::vector<bool> seen(n, false);
  cycle.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    if (seen[i] || perm[i] == i) continue;
    for (std::uint32_t j = static_cast<std::uint32_t>(i); !seen[j]; j = perm[j]) {
      seen[j] = true;
      cycle.push_back(j);
    }
    cycle_end.push_back(static_cast<std::uint32_t>(cycle.size()));
  }
  p.for_each_field([&](const FieldInfo&, auto& v) {
    v.resize(n);  // the owned ones (halo copies dropped)
    std::size_t b = 0;
    for (const std::uint32_t e : cycle_end) {  // v[c_k] <- v[c_{k+1}], the last <- the first
      auto first = v[cycle[b]];
      for (std::size_t k = b; k + 1 < e; ++k) v[cycle[k]] = v[cycle[k + 1]];
      v[cycle[e - 1]] = first;
      b = e;
    }
  });
  p.n_owned = n;
}

// Sorts the owned particles by the cells of a grid of side cell_size.
template <class Particles>
void sort_owned_by_cell(Particles& p, double cell_size) {
  CellList cells;
  cells.build(p.x.data(), p.y.data(), p.z.data(), p.n_owned, cell_size);
  permute_owned(p, cells.order());
}

}  // namespace sphdem
