#pragma once
// The decomposition a run keeps over its ranks: the Hilbert-ordered grid, the current cuts,
// and the work counted per cell since the last balance (pair evaluations and contacts,
// deterministic integers, not times: two runs on the same ranks cut alike). balance()
// sums the counts over the ranks, and where the largest rank's share passes the mean by
// more than the threshold, recuts the curve by them; every rank takes the same decision
// from the same sums. The particles then migrate to their new owners (rank_halo.hpp).
#include <cstdint>
#include <vector>

#include "domain/rank_comm.hpp"
#include "domain/sfc_grid.hpp"
#include "domain/sfc_partition.hpp"

namespace sphdem {

class Decomposition {
 public:
  // Cells of at least min_cell (the reach of the widest pair), cut by cell count.
  Decomposition(const RankComm& comm, const Box& box, double min_cell);

  const SfcGrid& grid() const { return grid_; }
  const SfcPartition& partition() const { return part_; }
  int owner(double x, double y, double z) const {
    return part_.owner(grid_, grid_.cell_of(x, y, z));
  }
  // Work done for a particle at (x, y, z) since the last balance.
  void count(double x, double y, double z, std::uint64_t work) {
    counts_[grid_.index(grid_.cell_of(x, y, z))] += work;
  }
  // The summed counts' max / mean over the current cuts; recut when above threshold (or
  // always with force). Clears the counts. Returns whether the cuts changed. Collective.
  // steps: how many steps the cuts in use stood for (the record's weights).
  bool balance(double threshold = 1.10, bool force = false, long steps = 1);
  // A run continued: the cuts it had (same rank count) and the work it had counted since
  // its last balance, summed over its ranks (given on one rank, zero on the others: the
  // next balance sums them alike).
  void restore(std::vector<std::uint32_t> first, std::vector<std::uint64_t> counts);
  // The work counted since the last balance, summed over the ranks. Collective.
  std::vector<std::uint64_t> summed_counts() const;
  // The imbalance the last balance() found before it recut, and after.
  double imbalance_before() const { return before_; }
  double imbalance_after() const { return after_; }
  // Over the balances with work counted: how often the cuts in use were within the
  // threshold (max/mean before a recut), the worst, the recuts; and the same for the
  // first cuts kept fixed (the control: what a run that never rebalances would have had);
  // and weighted by the steps each balance stood for.
  struct Record {
    long balances = 0, within = 0, recuts = 0, fixed_within = 0;
    long steps = 0, steps_within = 0, fixed_steps_within = 0;
    double worst = 1.0, fixed_worst = 1.0;
    double weighted = 0, fixed_weighted = 0;  // sum of max/mean x steps: / steps, the mean
  };
  const Record& record() const { return record_; }

 private:
  const RankComm& comm_;
  SfcGrid grid_;
  SfcPartition part_;
  std::vector<std::uint64_t> counts_;
  SfcPartition first_cuts_;  // the control
  Record record_;
  double before_ = 1.0, after_ = 1.0;
};

}  // namespace sphdem
