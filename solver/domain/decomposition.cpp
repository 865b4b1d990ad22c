#include "domain/decomposition.hpp"

#include <algorithm>

namespace sphdem {

Decomposition::Decomposition(const RankComm& comm, const Box& box, double min_cell)
    : comm_(comm), grid_(box, min_cell), counts_(grid_.cell_count(), 0) {
  part_ = partition_curve(grid_, counts_, comm_.size());  // no work yet: equal cell counts
}

bool Decomposition::balance(double threshold, bool force) {
  comm_.sum(counts_);
  before_ = load_imbalance(rank_weights(grid_, part_, counts_));
  after_ = before_;
  bool recut = false;
  if (force || before_ > threshold) {
    SfcPartition next = partition_curve(grid_, counts_, comm_.size());
    recut = next.first != part_.first;
    part_ = std::move(next);
    after_ = load_imbalance(rank_weights(grid_, part_, counts_));
  }
  std::fill(counts_.begin(), counts_.end(), 0);
  return recut;
}

void Decomposition::restore(std::vector<std::uint32_t> first, std::vector<std::uint64_t> counts) {
  if (!first.empty()) part_.first = std::move(first);
  if (counts.size() == counts_.size()) counts_ = std::move(counts);
}

std::vector<std::uint64_t> Decomposition::summed_counts() const {
  std::vector<std::uint64_t> c = counts_;
  comm_.sum(c);
  return c;
}

}  // namespace sphdem
