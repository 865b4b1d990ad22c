#pragma once
// The halo a run's passes read: on one rank, PeriodicHalo's images of the owned particles
// across the periodic faces; on several, RankHalo's copies of the particles other ranks
// own near this rank's cells (and this rank's own images across a periodic face), by
// the decomposition's cuts. Both fill per field, fill positions with their image and
// scatter the copies' shares back alike, so the passes never ask which. One rank keeps
// PeriodicHalo so that its bits stay those of a run without MPI.
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "domain/decomposition.hpp"
#include "domain/periodic_halo.hpp"
#include "domain/rank_comm.hpp"
#include "domain/rank_halo.hpp"

namespace sphdem {

class Halo {
 public:
  explicit Halo(const RankComm& comm = RankComm(MPI_COMM_NULL)) : comm_(comm) {}

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
    self_.resize(rank_.n_ghost());
    for (std::size_t g = 0; g < self_.size(); ++g)
      self_[g] = static_cast<std::uint32_t>(n_owned + g);
    no_shift_.assign(rank_.n_ghost(), 0.0);
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
  // The positions and the double `fields` (on ranks in one exchange). Collective on ranks.
  void fill_positions_and(double* x, double* y, double* z,
                          const std::vector<double*>& fields) const {
    if (ranks()) {
      rank_.fill_positions_and(comm_, x, y, z, fields);
      return;
    }
    periodic_.fill_positions(x, y, z);
    for (double* f : fields) periodic_.fill(f);
  }
  // Ranks: the copies a pass between builds reads (wanted[g] != 0 for copy g), and their
  // positions and `fields` refreshed alone (RankHalo::select, fill_selected). Collective.
  void select(const std::vector<std::uint8_t>& wanted) { rank_.select(comm_, wanted); }
  std::size_t n_selected() const { return ranks() ? rank_.n_selected() : 0; }
  // Ranks: the copies (and selected copies) of other ranks' particles, not own images.
  std::size_t n_ghost_from_others() const { return ranks() ? rank_.n_ghost_from_others() : 0; }
  std::size_t n_selected_from_others() const {
    return ranks() ? rank_.n_selected_from_others() : 0;
  }
  void fill_selected(double* x, double* y, double* z, const std::vector<double*>& fields) const {
    rank_.fill_selected(comm_, x, y, z, fields);
  }
  // The copies' rows of `stride` values added to their owners' (the reverse of fill).
  void add_to_sources(double* rows, std::size_t stride) const {
    if (ranks())
      rank_.add_to_sources(comm_, rows, stride);
    else
      periodic_.add_to_sources(rows, stride);
  }
  // How a pass reads a neighbour through the halo (periodic_halo.hpp's owned_image): on one
  // rank an image reads its owned source, so that copies need no refresh between builds;
  // on several a copy stands for itself (no shift), and its fields must be refreshed
  // before each pass that reads them (the DEM sub-steps do: SphereLists::refresh_motion).
  HaloImages images() const {
    if (!ranks()) return periodic_.images();
    return {rank_.n_owned(), self_.data(), no_shift_.data(), no_shift_.data(), no_shift_.data()};
  }
  // One rank: each image's owned source (tests).
  const PeriodicHalo& periodic() const { return periodic_; }

 private:
  RankComm comm_;
  PeriodicHalo periodic_;
  RankHalo rank_;
  std::vector<std::uint32_t> self_;  // ranks: each copy's own index
  std::vector<double> no_shift_;
};

// The fields the registry marks refreshed (the carried state that changes between builds;
// all doubles, which one exchange packs in rows).
template <class Particles>
std::vector<double*> refreshed_fields(Particles& p) {
  std::vector<double*> fields;
  p.for_each_field([&](const FieldInfo& field, auto& v) {
    if (!field.refreshed()) return;
    if constexpr (std::is_same_v<std::decay_t<decltype(v)>, std::vector<double>>)
      fields.push_back(v.data());
    else
      throw std::logic_error(std::string("refreshed halo field '") + field.name +
                             "' is not a double");
  });
  return fields;
}

// Between builds: the copies' positions and refreshed fields, on ranks in one exchange.
template <class Particles>
void refresh_copies(const Halo& halo, Particles& p) {
  halo.fill_positions_and(p.x.data(), p.y.data(), p.z.data(), refreshed_fields(p));
}

// Ranks: the same for the selected copies only (Halo::select).
template <class Particles>
void refresh_selected_copies(const Halo& halo, Particles& p) {
  halo.fill_selected(p.x.data(), p.y.data(), p.z.data(), refreshed_fields(p));
}

}  // namespace sphdem
