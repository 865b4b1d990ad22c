#pragma once
// Reordering of owned particles (e.g. into cell order, for memory locality): every
// field of a structure-of-arrays container is permuted, halo copies are dropped.
#include <cstdint>
#include <vector>

#include "domain/cell_list.hpp"
#include "domain/field_info.hpp"

namespace sphdem {

// new index i <- old index perm[i], for every field the container lists.
template <class Particles>
void permute_owned(Particles& p, const std::vector<std::uint32_t>& perm) {
  p.for_each_field([&](const FieldInfo&, auto& v) {
    auto tmp = v;
    v.resize(perm.size());
    for (std::size_t i = 0; i < perm.size(); ++i) v[i] = tmp[perm[i]];
  });
  p.n_owned = perm.size();
}

// Sorts the owned particles by the cells of a grid of side cell_size.
template <class Particles>
void sort_owned_by_cell(Particles& p, double cell_size) {
  CellList cells;
  cells.build(p.x.data(), p.y.data(), p.z.data(), p.n_owned, cell_size);
  permute_owned(p, cells.order());
}

}  // namespace sphdem
