#include "domain/rank_halo.hpp"

#include <algorithm>

namespace sphdem {

void RankHalo::build(const RankComm& comm, const SfcGrid& grid, const SfcPartition& part,
                     const std::array<int, 3>& reach, const double* x, const double* y,
                     const double* z, std::size_t n_owned) {
  n_owned_ = n_owned;
  // the owned particles of each cell, in index order
  const std::size_t cells = grid.cell_count();
  std::vector<std::uint32_t> start(cells + 1, 0), cell_of(n_owned);
  for (std::size_t i = 0; i < n_owned; ++i) {
    cell_of[i] = static_cast<std::uint32_t>(grid.index(grid.cell_of(x[i], y[i], z[i])));
    ++start[cell_of[i] + 1];
  }
  for (std::size_t c = 0; c < cells; ++c) start[c + 1] += start[c];
  std::vector<std::uint32_t> members(n_owned), fill_at(start.begin(), start.end() - 1);
  for (std::size_t i = 0; i < n_owned; ++i) members[fill_at[cell_of[i]]++] = std::uint32_t(i);

  if (sends_first_ != part.first || sends_reach_ != reach || sends_.empty()) {
    sends_ = halo_sends(grid, part, comm.rank(), reach);  // by rank
    sends_first_ = part.first;
    sends_reach_ = reach;
  }
  const std::vector<HaloSend>& sends = sends_;
  send_index_.clear();
  send_count_.assign(comm.size(), 0);
  std::vector<double> send_shift;
  const Box& box = grid.box();
  for (const HaloSend& s : sends) {
    for (std::uint32_t k = start[s.cell]; k < start[s.cell + 1]; ++k) {
      send_index_.push_back(members[k]);
      for (int d = 0; d < 3; ++d) send_shift.push_back(s.image[d] * box.length(d));
    }
    send_count_[s.rank] += start[s.cell + 1] - start[s.cell];
  }
  recv_count_ = comm.counts(send_count_);
  n_ghost_ = 0;
  for (const std::uint64_t c : recv_count_) n_ghost_ += c;
  shift_.resize(3 * n_ghost_);
  comm.exchange(send_shift.data(), send_count_, shift_.data(), recv_count_, 3 * sizeof(double));
}

void RankHalo::fill_positions(const RankComm& comm, double* x, double* y, double* z) const {
  fill(comm, x);
  fill(comm, y);
  fill(comm, z);
  for (std::size_t g = 0; g < n_ghost_; ++g) {
    x[n_owned_ + g] += shift_[3 * g];
    y[n_owned_ + g] += shift_[3 * g + 1];
    z[n_owned_ + g] += shift_[3 * g + 2];
  }
}

void RankHalo::add_to_sources(const RankComm& comm, double* rows, std::size_t stride) const {
  // the copies' rows go back the way they came (the exchange with the counts swapped)
  std::vector<double> back(send_index_.size() * stride);
  comm.exchange(rows + n_owned_ * stride, recv_count_, back.data(), send_count_,
                stride * sizeof(double));
  for (std::size_t k = 0; k < send_index_.size(); ++k) {
    double* to = rows + std::size_t{send_index_[k]} * stride;
    for (std::size_t i = 0; i < stride; ++i) to[i] += back[k * stride + i];
  }
}

}  // namespace sphdem
