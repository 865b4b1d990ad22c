#include "domain/sfc_partition.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <tuple>

namespace sphdem {

int SfcPartition::owner_at(std::uint32_t position) const {
  const auto it = std::upper_bound(first.begin(), first.end(), position);
  return static_cast<int>(it - first.begin()) - 1;
}

SfcPartition partition_curve(const SfcGrid& grid, const std::vector<std::uint64_t>& weight,
                             int ranks) {
  const std::size_t cells = grid.cell_count();
  if (ranks < 1) throw std::invalid_argument("partition_curve: ranks must be >= 1");
  if (static_cast<std::size_t>(ranks) > cells)
    throw std::invalid_argument("partition_curve: " + std::to_string(ranks) + " ranks for " +
                                std::to_string(cells) + " cells");
  if (weight.size() != cells) throw std::invalid_argument("partition_curve: one weight per cell");
  const std::vector<std::uint32_t>& curve = grid.curve();
  std::vector<std::uint64_t> sum(cells + 1, 0);  // running sum before each position
  for (std::size_t k = 0; k < cells; ++k) sum[k + 1] = sum[k] + weight[curve[k]];
  const bool counts = sum[cells] == 0;  // no weight yet: equal cell counts
  const auto at = [&](std::size_t k) { return counts ? std::uint64_t(k) : sum[k]; };
  const std::uint64_t total = at(cells);
  SfcPartition part;
  part.first.assign(ranks + 1, 0);
  part.first[ranks] = static_cast<std::uint32_t>(cells);
  std::size_t k = 0;
  for (int r = 1; r < ranks; ++r) {
    // the share r / R of the total, in exact integer arithmetic (2x to round to nearest)
    const unsigned __int128 target2 = (unsigned __int128)2 * total * r / ranks;
    while (k < cells && (unsigned __int128)2 * at(k + 1) <= target2) ++k;
    // k: the last boundary at or below the share; k + 1 if that one is nearer
    if (k < cells && (unsigned __int128)2 * at(k) <= target2 &&
        (unsigned __int128)2 * at(k + 1) - target2 < target2 - 2 * at(k))
      ++k;
    // every range holds a cell: at least r cells before, ranks - r after
    k = std::clamp(k, static_cast<std::size_t>(part.first[r - 1]) + 1, cells - (ranks - r));
    part.first[r] = static_cast<std::uint32_t>(k);
  }
  return part;
}

std::vector<std::uint64_t> rank_weights(const SfcGrid& grid, const SfcPartition& part,
                                        const std::vector<std::uint64_t>& weight) {
  std::vector<std::uint64_t> w(part.ranks(), 0);
  for (int r = 0; r < part.ranks(); ++r)
    for (std::uint32_t k = part.first[r]; k < part.first[r + 1]; ++k)
      w[r] += weight[grid.curve()[k]];
  return w;
}

double load_imbalance(const std::vector<std::uint64_t>& rank_weight) {
  std::uint64_t total = 0, largest = 0;
  for (const std::uint64_t w : rank_weight) {
    total += w;
    largest = std::max(largest, w);
  }
  if (total == 0) return 1.0;
  return static_cast<double>(largest) * static_cast<double>(rank_weight.size()) /
         static_cast<double>(total);
}

bool HaloSend::operator<(const HaloSend& o) const {
  return std::tie(rank, cell, image) < std::tie(o.rank, o.cell, o.image);
}

std::vector<HaloSend> halo_sends(const SfcGrid& grid, const SfcPartition& part, int rank,
                                 const std::array<int, 3>& reach) {
  const std::array<int, 3>& n = grid.cells();
  const Box& box = grid.box();
  std::vector<HaloSend> sends;
  for (std::uint32_t k = part.first[rank]; k < part.first[rank + 1]; ++k) {
    const std::uint32_t index = grid.curve()[k];
    const std::array<int, 3> c = grid.cell(index);
    std::array<int, 3> o{};
    for (o[2] = -reach[2]; o[2] <= reach[2]; ++o[2])
      for (o[1] = -reach[1]; o[1] <= reach[1]; ++o[1])
        for (o[0] = -reach[0]; o[0] <= reach[0]; ++o[0]) {
          std::array<int, 3> t{}, wraps{};
          bool inside = true;
          for (int d = 0; d < 3; ++d) {
            const int u = c[d] + o[d];
            if (box.periodic[d]) {  // u = t + wraps n, t in [0, n)
              wraps[d] = u >= 0 ? u / n[d] : -((-u + n[d] - 1) / n[d]);
              t[d] = u - wraps[d] * n[d];
            } else {
              inside = inside && u >= 0 && u < n[d];
              t[d] = u;
            }
          }
          if (!inside) continue;
          const int q = part.owner(grid, t);
          // q's cell t sees cell c across -wraps periodic lengths
          const std::array<int, 3> image{-wraps[0], -wraps[1], -wraps[2]};
          if (q == rank && image == std::array<int, 3>{0, 0, 0}) continue;
          sends.push_back(HaloSend{index, q, image, {static_cast<std::uint32_t>(grid.index(t))}});
        }
  }
  std::sort(sends.begin(), sends.end(), [](const HaloSend& a, const HaloSend& b) {
    return a < b || (a == b && a.targets < b.targets);
  });
  std::vector<HaloSend> merged;  // one entry per (rank, cell, image), its targets in order
  for (HaloSend& s : sends) {
    if (!merged.empty() && merged.back() == s) {
      if (merged.back().targets.back() != s.targets[0])
        merged.back().targets.push_back(s.targets[0]);
    } else {
      merged.push_back(std::move(s));
    }
  }
  return merged;
}

}  // namespace sphdem
