#include "domain/rank_comm.hpp"

#include <algorithm>
#include <cstring>
#include <limits>
#include <stdexcept>

namespace sphdem {

namespace {

bool mpi_running() {
  int on = 0, off = 0;
  MPI_Initialized(&on);
  MPI_Finalized(&off);
  return on && !off;
}

}  // namespace

RankComm::RankComm() : RankComm(mpi_running() ? MPI_COMM_WORLD : MPI_COMM_NULL) {}

RankComm::RankComm(MPI_Comm comm) : comm_(comm) {
  if (comm_ == MPI_COMM_NULL) return;
  MPI_Comm_rank(comm_, &rank_);
  MPI_Comm_size(comm_, &size_);
}

void RankComm::sum(std::vector<std::uint64_t>& values) const {
  if (!parallel() || values.empty()) return;
  static_assert(sizeof(unsigned long) == sizeof(std::uint64_t));
  ++traffic_->collectives;
  MPI_Allreduce(MPI_IN_PLACE, values.data(), static_cast<int>(values.size()), MPI_UNSIGNED_LONG,
                MPI_SUM, comm_);
}

std::uint64_t RankComm::sum(std::uint64_t value) const {
  std::vector<std::uint64_t> v{value};
  sum(v);
  return v[0];
}

double RankComm::max(double value) const {
  if (!parallel()) return value;
  ++traffic_->collectives;
  MPI_Allreduce(MPI_IN_PLACE, &value, 1, MPI_DOUBLE, MPI_MAX, comm_);
  return value;
}

double RankComm::min(double value) const {
  if (!parallel()) return value;
  ++traffic_->collectives;
  MPI_Allreduce(MPI_IN_PLACE, &value, 1, MPI_DOUBLE, MPI_MIN, comm_);
  return value;
}

void RankComm::max(std::vector<double>& values) const {
  if (!parallel() || values.empty()) return;
  ++traffic_->collectives;
  MPI_Allreduce(MPI_IN_PLACE, values.data(), static_cast<int>(values.size()), MPI_DOUBLE, MPI_MAX,
                comm_);
}

void RankComm::sum(std::vector<double>& values) const {
  if (!parallel() || values.empty()) return;
  // gathered and added in rank order on every rank: the same bits on each, run after run
  ++traffic_->collectives;
  std::vector<double> all(values.size() * size_);
  MPI_Allgather(values.data(), static_cast<int>(values.size()), MPI_DOUBLE, all.data(),
                static_cast<int>(values.size()), MPI_DOUBLE, comm_);
  for (std::size_t i = 0; i < values.size(); ++i) {
    double s = 0.0;
    for (int q = 0; q < size_; ++q) s += all[q * values.size() + i];
    values[i] = s;
  }
}

std::string RankComm::broadcast(const std::string& text, int root) const {
  if (!parallel()) return text;
  ++traffic_->collectives;
  std::uint64_t n = text.size();
  MPI_Bcast(&n, 1, MPI_UNSIGNED_LONG, root, comm_);
  std::string out = text;
  out.resize(n);
  MPI_Bcast(out.data(), static_cast<int>(n), MPI_CHAR, root, comm_);
  return out;
}

void RankComm::barrier() const {
  if (!parallel()) return;
  ++traffic_->collectives;
  MPI_Barrier(comm_);
}

std::vector<std::uint64_t> RankComm::counts(const std::vector<std::uint64_t>& send_count) const {
  if (!parallel()) return send_count;
  ++traffic_->collectives;
  std::vector<std::uint64_t> recv(size_);
  MPI_Alltoall(send_count.data(), 1, MPI_UNSIGNED_LONG, recv.data(), 1, MPI_UNSIGNED_LONG, comm_);
  return recv;
}

void RankComm::exchange(const void* send, const std::vector<std::uint64_t>& send_count, void* recv,
                        const std::vector<std::uint64_t>& recv_count, std::size_t bytes) const {
  if (!parallel()) {
    if (send_count[0] > 0) std::memmove(recv, send, send_count[0] * bytes);
    return;
  }
  // Point to point with the ranks that send or receive anything (a halo's few neighbours,
  // not every rank as MPI_Alltoallv's pairwise schedule): each message lands at its fixed
  // offset, and messages between two ranks keep their order (MPI's non-overtaking rule), so
  // successive exchanges never mix.
  constexpr int kTag = 36;
  const char* from = static_cast<const char*>(send);
  char* to = static_cast<char*>(recv);
  std::vector<std::uint64_t> sd(size_ + 1, 0), rd(size_ + 1, 0);  // byte offsets by rank
  for (int q = 0; q < size_; ++q) {
    sd[q + 1] = sd[q] + send_count[q] * bytes;
    rd[q + 1] = rd[q] + recv_count[q] * bytes;
    if (std::max(sd[q + 1] - sd[q], rd[q + 1] - rd[q]) >
        static_cast<std::uint64_t>(std::numeric_limits<int>::max()))
      throw std::overflow_error("RankComm::exchange: more than 2 GiB in one message");
  }
  std::vector<MPI_Request> requests;
  for (int q = 0; q < size_; ++q)
    if (q != rank_ && rd[q + 1] > rd[q]) {
      requests.emplace_back();
      MPI_Irecv(to + rd[q], static_cast<int>(rd[q + 1] - rd[q]), MPI_BYTE, q, kTag, comm_,
                &requests.back());
    }
  for (int q = 0; q < size_; ++q)
    if (q != rank_ && sd[q + 1] > sd[q]) {
      requests.emplace_back();
      MPI_Isend(from + sd[q], static_cast<int>(sd[q + 1] - sd[q]), MPI_BYTE, q, kTag, comm_,
                &requests.back());
      traffic_->bytes_sent += sd[q + 1] - sd[q];
    }
  if (sd[rank_ + 1] > sd[rank_])  // this rank's own copies (periodic images)
    std::memmove(to + rd[rank_], from + sd[rank_], sd[rank_ + 1] - sd[rank_]);
  ++traffic_->exchanges;
  MPI_Waitall(static_cast<int>(requests.size()), requests.data(), MPI_STATUSES_IGNORE);
}

}  // namespace sphdem
