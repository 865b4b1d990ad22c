#include "domain/rank_halo.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace sphdem {

void RankHalo::build(const RankComm& comm, const SfcGrid& grid, const SfcPartition& part,
                     double reach_m, const double* x, const double* y, const double* z,
                     std::size_t n_owned) {
  n_owned_ = n_owned;
  selected_ = false;
  std::array<int, 3> reach{};
  for (int d = 0; d < 3; ++d) reach[d] = static_cast<int>(std::ceil(reach_m / grid.cell_size(d)));
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

  if (sends_first_ != part.first || sends_reach_ != reach) {  // (first build: first is empty)
    sends_ = halo_sends(grid, part, comm.rank(), reach);      // by rank
    sends_first_ = part.first;
    sends_reach_ = reach;
  }
  const std::vector<HaloSend>& sends = sends_;
  send_index_.clear();
  send_count_.assign(comm.size(), 0);
  std::vector<double> send_shift;
  const Box& box = grid.box();
  const double reach2 = reach_m * reach_m;
  for (const HaloSend& s : sends) {
    double shift[3];
    for (int d = 0; d < 3; ++d) shift[d] = s.image[d] * box.length(d);
    for (std::uint32_t k = start[s.cell]; k < start[s.cell + 1]; ++k) {
      const std::uint32_t i = members[k];
      const double p[3] = {x[i] + shift[0], y[i] + shift[1], z[i] + shift[2]};
      bool needed = false;  // within the reach of one of the receiver's cells
      for (std::size_t t = 0; !needed && t < s.targets.size(); ++t)
        needed = grid.distance2_to_cell(s.targets[t], p) <= reach2;
      if (!needed) continue;
      send_index_.push_back(i);
      send_shift.insert(send_shift.end(), shift, shift + 3);
      ++send_count_[s.rank];
    }
  }
  recv_count_ = comm.counts(send_count_);
  n_ghost_ = 0;
  for (const std::uint64_t c : recv_count_) n_ghost_ += c;
  own_copies_ = recv_count_[comm.rank()];
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

namespace {

// Rows of the positions and fields of the particles `send` (grouped by rank) into the
// copies `ghost` (by source rank), each copy's position shifted by its image.
void exchange_rows(const RankComm& comm, const std::uint32_t* send, std::size_t n_send,
                   const std::vector<std::uint64_t>& send_count, const std::uint32_t* ghost,
                   std::size_t n_recv, const std::vector<std::uint64_t>& recv_count,
                   const std::vector<double>& shift, std::size_t n_owned, double* x, double* y,
                   double* z, const std::vector<double*>& fields) {
  const std::size_t stride = 3 + fields.size();
  std::vector<double> out(n_send * stride), in(n_recv * stride);
  for (std::size_t k = 0; k < n_send; ++k) {
    const std::size_t i = send[k];
    double* row = out.data() + k * stride;
    row[0] = x[i];
    row[1] = y[i];
    row[2] = z[i];
    for (std::size_t f = 0; f < fields.size(); ++f) row[3 + f] = fields[f][i];
  }
  comm.exchange(out.data(), send_count, in.data(), recv_count, stride * sizeof(double));
  for (std::size_t k = 0; k < n_recv; ++k) {
    const double* row = in.data() + k * stride;
    const std::size_t g = ghost ? ghost[k] : k, j = n_owned + g;
    x[j] = row[0] + shift[3 * g];
    y[j] = row[1] + shift[3 * g + 1];
    z[j] = row[2] + shift[3 * g + 2];
    for (std::size_t f = 0; f < fields.size(); ++f) fields[f][j] = row[3 + f];
  }
}

}  // namespace

void RankHalo::fill_positions_and(const RankComm& comm, double* x, double* y, double* z,
                                  const std::vector<double*>& fields) const {
  exchange_rows(comm, send_index_.data(), send_index_.size(), send_count_, nullptr, n_ghost_,
                recv_count_, shift_, n_owned_, x, y, z, fields);
}

void RankHalo::select(const RankComm& comm, const std::vector<std::uint8_t>& wanted) {
  // the flags go back the way the copies came (the exchange with the counts swapped)
  std::vector<std::uint8_t> back(send_index_.size());
  comm.exchange(wanted.data(), recv_count_, back.data(), send_count_, 1);
  const int R = comm.size();
  selected_send_.clear();
  selected_send_count_.assign(R, 0);
  std::size_t k = 0;
  for (int q = 0; q < R; ++q)
    for (std::uint64_t c = 0; c < send_count_[q]; ++c, ++k)
      if (back[k]) {
        selected_send_.push_back(send_index_[k]);
        ++selected_send_count_[q];
      }
  selected_ghost_.clear();
  selected_recv_count_.assign(R, 0);
  std::size_t g = 0;
  for (int q = 0; q < R; ++q)
    for (std::uint64_t c = 0; c < recv_count_[q]; ++c, ++g)
      if (wanted[g]) {
        selected_ghost_.push_back(static_cast<std::uint32_t>(g));
        ++selected_recv_count_[q];
      }
  own_selected_ = selected_recv_count_[comm.rank()];
  selected_ = true;
}

void RankHalo::fill_selected(const RankComm& comm, double* x, double* y, double* z,
                             const std::vector<double*>& fields) const {
  if (!selected_) throw std::logic_error("RankHalo::fill_selected: no select() since the build");
  exchange_rows(comm, selected_send_.data(), selected_send_.size(), selected_send_count_,
                selected_ghost_.data(), selected_ghost_.size(), selected_recv_count_, shift_,
                n_owned_, x, y, z, fields);
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
