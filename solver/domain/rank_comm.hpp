#pragma once
// The ranks of a run: an MPI communicator with the few collectives the solver needs, each
// exact in any order, so that two runs on the same ranks give the same bits: sums of
// integers, max and min of doubles, and the personalised all-to-all exchange. One rank
// without MPI initialised: every collective is the identity. Knows nothing of SPH or DEM.
#include <mpi.h>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace sphdem {

class RankComm {
 public:
  // What this rank's collectives moved since the communicator was made (its copies count
  // into the same tally): the personalised exchanges and the bytes this rank sent in them
  // to other ranks, and the other collectives (reductions, count exchanges, broadcasts,
  // barriers).
  struct Traffic {
    std::uint64_t exchanges = 0, bytes_sent = 0, collectives = 0;
  };

  RankComm();  // MPI_COMM_WORLD if MPI is initialised, else one rank
  explicit RankComm(MPI_Comm comm);

  int rank() const { return rank_; }
  int size() const { return size_; }
  bool parallel() const { return size_ > 1; }
  MPI_Comm comm() const { return comm_; }

  void sum(std::vector<std::uint64_t>& values) const;  // in place, over the ranks
  std::uint64_t sum(std::uint64_t value) const;
  double max(double value) const;
  double min(double value) const;
  void max(std::vector<double>& values) const;  // in place, element by element
  void sum(std::vector<double>& values) const;  // in place (floating point: order of ranks)
  std::string broadcast(const std::string& text, int root) const;  // root's text on every rank
  void barrier() const;

  // Every rank sends send_count[q] items of `bytes` bytes each to rank q from `send`
  // (grouped by destination, in rank order) and receives into `recv` (grouped by source,
  // in rank order). recv_count: what each rank sends here (from counts()). Collective, but
  // messages pass only between ranks with something to send (point to point).
  void exchange(const void* send, const std::vector<std::uint64_t>& send_count, void* recv,
                const std::vector<std::uint64_t>& recv_count, std::size_t bytes) const;
  // The counts the other ranks will send here, from those this rank sends them.
  std::vector<std::uint64_t> counts(const std::vector<std::uint64_t>& send_count) const;

  const Traffic& traffic() const { return *traffic_; }

  // Every rank's `mine` (plain values) joined in rank order on rank 0; empty on the others.
  template <class T>
  std::vector<T> gather_to_root(const std::vector<T>& mine) const {
    std::vector<std::uint64_t> send(size_, 0);
    send[0] = mine.size();
    const std::vector<std::uint64_t> recv = counts(send);
    std::uint64_t n = 0;
    for (std::uint64_t c : recv) n += c;
    std::vector<T> all(n);
    exchange(mine.data(), send, all.data(), recv, sizeof(T));
    return all;
  }

 private:
  MPI_Comm comm_ = MPI_COMM_NULL;
  int rank_ = 0, size_ = 1;
  std::shared_ptr<Traffic> traffic_ = std::make_shared<Traffic>();
};

}  // namespace sphdem
