#pragma once
// The halo a run's passes read: on one rank, PeriodicHalo's images of the owned particles
// across the periodic faces; on several, RankHalo's copies of the particles other ranks
// own near this rank's cells (and this rank's own images across a periodic face), by
// the decomposition's cuts. Both fill per field, fill positions with their image and
// scatter the copies' shares back alike, so the passes never ask which. One rank keeps
// PeriodicHalo so that its bits stay those of a run without MPI.
#include <cstddef>

#include "domain/decomposition.hpp"
#include "domain/periodic_halo.hpp"
#include "domain/rank_comm.hpp"
#include "domain/rank_halo.hpp"

namespace sphdem {

class Halo {
 public:
  explicit Halo(const RankComm& comm = RankComm()) : comm_(comm) {}

  bool ranks() const { return comm_.parallel(); }
  const RankComm& comm() const { return comm_; }

  // One rank: images within `width` of a periodic face (PeriodicHalo::build).
  void build(const Box& box, double width, const double* x, const double* y, const double* z,
             std::size_t n_owned) {
    periodic_.build(box, width, x, y, z, n_owned);
  }
  // Ranks: every particle within `reach` of a cell another rank owns, or of this rank's
  // own across a periodic face (RankHalo::build). Collective.
  void build(const Decomposition& d, double reach, const double* x, const double* y,
             const double* z, std::size_t n_owned) {
    rank_.build(comm_, d.grid(), d.partition(), reach, x, y, z, n_owned);
  }

  std::size_t n_ghost() const { return ranks() ? rank_.n_ghost() : periodic_.n_ghost(); }

  template <class Vec>
  void fill(Vec& field) const {  // collective on ranks
    if (ranks())
      rank_.fill(comm_, field.data());
    else
      periodic_.fill(field.data());
  }
  void fill_positions(double* x, double* y, double* z) const {
    if (ranks())
      rank_.fill_positions(comm_, x, y, z);
    else
      periodic_.fill_positions(x, y, z);
  }
  // The copies' rows of `stride` values added to their owners' (the reverse of fill).
  void add_to_sources(double* rows, std::size_t stride) const {
    if (ranks())
      rank_.add_to_sources(comm_, rows, stride);
    else
      periodic_.add_to_sources(rows, stride);
  }
  // One rank: each image's owned source (tests).
  const PeriodicHalo& periodic() const { return periodic_; }

 private:
  RankComm comm_;
  PeriodicHalo periodic_;
  RankHalo rank_;
};

}  // namespace sphdem
