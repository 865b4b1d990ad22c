#include "domain/decomposition.hpp"

#include <algorithm>

namespace sphdem {

Decomposition::Decomposition(const RankComm& comm, const Box& box, double min_cell)
    : comm_(comm), grid_(box, min_cell), counts_(grid_.cell_count(), 0) {
  part_ = partition_curve(grid_, counts_, comm_.size());  // no work yet: equal cell counts
  first_cuts_ = part_;
}

bool Decomposition::balance(double threshold, bool force, long steps) {
  comm_.sum(counts_);
  before_ = load_imbalance(rank_weights(grid_, part_, counts_));
  after_ = before_;
  if (std::any_of(counts_.begin(), counts_.end(), [](std::uint64_t c) { return c > 0; })) {
    const double fixed = load_imbalance(rank_weights(grid_, first_cuts_, counts_));
    ++record_.balances;
    record_.within += before_ <= threshold;
    record_.worst = std::max(record_.worst, before_);
    record_.fixed_within += fixed <= threshold;
    record_.fixed_worst = std::max(record_.fixed_worst, fixed);
    record_.steps += steps;
    record_.steps_within += before_ <= threshold ? steps : 0;
    record_.fixed_steps_within += fixed <= threshold ? steps : 0;
    record_.weighted += before_ * static_cast<double>(steps);
    record_.fixed_weighted += fixed * static_cast<double>(steps);
  }
  bool recut = false;
  if (force || before_ > threshold) {
    SfcPartition next = partition_curve(grid_, counts_, comm_.size());
    recut = next.first != part_.first;
    record_.recuts += recut;
    part_ = std::move(next);
    after_ = load_imbalance(rank_weights(grid_, part_, counts_));
  }
  std::fill(counts_.begin(), counts_.end(), 0);
  return recut;
}

void Decomposition::restore(std::vector<std::uint32_t> first, std::vector<std::uint64_t> counts) {
  if (!first.empty()) part_.first = std::move(first);
  first_cuts_ = part_;  // (the control of this sitting)
  if (counts.size() == counts_.size()) counts_ = std::move(counts);
}

std::vector<std::uint64_t> Decomposition::summed_counts() const {
  std::vector<std::uint64_t> c = counts_;
  comm_.sum(c);
  return c;
}

}  // namespace sphdem
