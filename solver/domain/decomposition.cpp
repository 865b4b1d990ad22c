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

}  // namespace sphdem
