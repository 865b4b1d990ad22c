#pragma once
// Particles across ranks (domain/sfc_partition.hpp's decomposition): migration to the rank
// that owns a particle's cell, with every field of the registry; and the halo, copies of
// the particles of the cells another rank needs (or this rank across a periodic face),
// filled per field as PeriodicHalo's are, with the reverse scatter that sums the shares
// written into copies back into their owners. Received copies are ordered by source rank,
// then by the source's (cell, image) order, then by the source's index: the same on every
// run. Knows nothing of SPH or DEM.
#include <array>
#include <cstdint>
#include <type_traits>
#include <vector>

#include "domain/field_info.hpp"
#include "domain/rank_comm.hpp"
#include "domain/sfc_partition.hpp"

namespace sphdem {

// The owned particles with dest[i] != this rank go to rank dest[i]; the kept ones stay in
// their order, the received follow (by source rank, then the source's order). Every
// field of the registry moves; halo copies are dropped (rebuild the halo after).
template <class Particles>
void migrate(const RankComm& comm, Particles& p, const std::vector<int>& dest);

// Every rank holds the same global set: keeps the particles with dest[i] == this rank, in
// their order (the start of a run, before any migration).
template <class Particles>
void keep_share(const RankComm& comm, Particles& p, const std::vector<int>& dest) {
  std::size_t kept = 0;
  p.for_each_field([&](const FieldInfo&, auto& v) {
    kept = 0;
    for (std::size_t i = 0; i < p.n_owned; ++i)
      if (dest[i] == comm.rank()) v[kept++] = v[i];
    v.resize(kept);
  });
  p.n_owned = kept;
}

class RankHalo {
 public:
  // The copies this rank sends, from its owned positions, and the count it gets: every
  // owned particle within `reach` (m) of a cell another rank owns (or of its own cells
  // across a periodic face), so that every pair within the reach is complete.
  void build(const RankComm& comm, const SfcGrid& grid, const SfcPartition& part, double reach,
             const double* x, const double* y, const double* z, std::size_t n_owned);
  std::size_t n_owned() const { return n_owned_; }
  std::size_t n_ghost() const { return n_ghost_; }
  std::size_t n_sent() const { return send_index_.size(); }
  // Copies of other ranks' particles (the rest are this rank's own periodic images).
  std::size_t n_ghost_from_others() const { return n_ghost_ - own_copies_; }
  std::size_t n_selected_from_others() const { return selected_ghost_.size() - own_selected_; }

  // Copies a field from the owners into [n_owned, n_owned + n_ghost) (sized by the caller).
  template <class T>
  void fill(const RankComm& comm, T* field) const;
  template <class Vec>
  void fill(const RankComm& comm, Vec& field) const {
    fill(comm, field.data());
  }
  // Positions: the owner's plus the image's whole box lengths.
  void fill_positions(const RankComm& comm, double* x, double* y, double* z) const;
  // The positions and `fields` in one exchange (a copy's values packed in one row): what
  // a sub-step refreshes, at one message's latency instead of one per field.
  void fill_positions_and(const RankComm& comm, double* x, double* y, double* z,
                          const std::vector<double*>& fields) const;
  // Adds each copy's row of `stride` values (rows: owned, then copies) to its owner's row,
  // in a fixed order (by source rank, then copy order).
  void add_to_sources(const RankComm& comm, double* rows, std::size_t stride) const;

  // The copies a pass reads (wanted[g] != 0 for copy g, as a contact list's partners): their
  // owners learn which, so that fill_selected refreshes only those. Collective; remade
  // after each build.
  void select(const RankComm& comm, const std::vector<std::uint8_t>& wanted);
  std::size_t n_selected() const { return selected_ghost_.size(); }
  bool selected() const { return selected_; }
  // fill_positions_and for the selected copies only (the others keep their values).
  void fill_selected(const RankComm& comm, double* x, double* y, double* z,
                     const std::vector<double*>& fields) const;

 private:
  std::size_t n_owned_ = 0, n_ghost_ = 0, own_copies_ = 0, own_selected_ = 0;
  // the cells sent, for the cuts and reach they were made for (remade when either changes)
  std::vector<HaloSend> sends_;
  std::vector<std::uint32_t> sends_first_;
  std::array<int, 3> sends_reach_{};
  std::vector<std::uint32_t> send_index_;  // owned particles sent, grouped by rank
  std::vector<std::uint64_t> send_count_, recv_count_;
  std::vector<double> shift_;  // three per copy: the image in metres
  // select(): the owned particles whose copies are wanted, grouped by rank, and the copies
  std::vector<std::uint32_t> selected_send_, selected_ghost_;
  std::vector<std::uint64_t> selected_send_count_, selected_recv_count_;
  bool selected_ = false;               // select() since the last build
  mutable std::vector<double> buffer_;  // the values sent (doubles: aligned for any field)
};

template <class T>
void RankHalo::fill(const RankComm& comm, T* field) const {
  static_assert(std::is_trivially_copyable_v<T>);
  buffer_.resize((send_index_.size() * sizeof(T) + 7) / 8);  // grows once, then reused
  T* send = reinterpret_cast<T*>(buffer_.data());
  for (std::size_t k = 0; k < send_index_.size(); ++k) send[k] = field[send_index_[k]];
  comm.exchange(send, send_count_, field + n_owned_, recv_count_, sizeof(T));
}

template <class Particles>
void migrate(const RankComm& comm, Particles& p, const std::vector<int>& dest) {
  const std::size_t n = p.n_owned;
  const int me = comm.rank();
  std::vector<std::uint64_t> send_count(comm.size(), 0);
  std::vector<std::uint32_t> keep, leave;
  for (std::size_t i = 0; i < n; ++i) {
    if (dest[i] == me) {
      keep.push_back(static_cast<std::uint32_t>(i));
    } else {
      ++send_count[dest[i]];
      leave.push_back(static_cast<std::uint32_t>(i));
    }
  }
  std::stable_sort(leave.begin(), leave.end(),
                   [&](std::uint32_t a, std::uint32_t b) { return dest[a] < dest[b]; });
  const std::vector<std::uint64_t> recv_count = comm.counts(send_count);
  std::uint64_t received = 0;
  for (const std::uint64_t c : recv_count) received += c;
  const std::size_t n_new = keep.size() + received;
  p.for_each_field([&](const FieldInfo&, auto& v) {
    using T = typename std::decay_t<decltype(v)>::value_type;
    std::vector<T> send(leave.size());
    for (std::size_t k = 0; k < leave.size(); ++k) send[k] = v[leave[k]];
    std::vector<T> next(n_new);
    for (std::size_t k = 0; k < keep.size(); ++k) next[k] = v[keep[k]];
    comm.exchange(send.data(), send_count, next.data() + keep.size(), recv_count, sizeof(T));
    v.swap(next);
  });
  p.n_owned = n_new;
}

}  // namespace sphdem
