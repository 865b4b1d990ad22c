#pragma once
// Halo copies ("ghosts") of owned particles for periodic images.
//
// Every pass loops over owned particles and reads neighbours among owned + ghost
// particles, exactly as it will once MPI halos exist: a ghost is an owned particle
// seen through a periodic face (later: or through a rank boundary). The plan is
// built once per neighbour rebuild and applied per field (Cabana's Halo idea).
#include <cstddef>
#include <cstdint>
#include <vector>

#include "domain/box.hpp"

namespace sphdem {

// Where the halo copies come from: copy n_owned + g is owned particle source[g] shifted by
// (shift_x[g], shift_y[g], shift_z[g]), exact multiples of the box lengths. A pass that
// needs a separation exactly antisymmetric across a periodic face takes it as
// (x_i - x_source) - shift: the two sides of a pair then compute negatives bit for bit,
// which x_i - (x_source + shift) does not give (the two images round differently).
// An MPI halo will provide the same: the owner's coordinates and the shift.
struct HaloImages {
  std::size_t n_owned = 0;
  const std::uint32_t* source = nullptr;
  const double* shift_x = nullptr;
  const double* shift_y = nullptr;
  const double* shift_z = nullptr;
};

// The owned particle that neighbour j stands for (j itself if owned, else its source) and
// the separation x_i - x_j, across a periodic face as (x_i - x_source) - shift. A pass
// that reads its neighbours' fields through the returned index needs no halo fill.
template <class Field>
inline std::size_t owned_image(const HaloImages& im, std::size_t j, double xi, double yi, double zi,
                               const Field& x, const Field& y, const Field& z, double& dx,
                               double& dy, double& dz) {
  if (j < im.n_owned) {
    dx = xi - x[j];
    dy = yi - y[j];
    dz = zi - z[j];
    return j;
  }
  const std::size_t g = j - im.n_owned;
  const std::size_t h = im.source[g];
  dx = (xi - x[h]) - im.shift_x[g];
  dy = (yi - y[h]) - im.shift_y[g];
  dz = (zi - z[h]) - im.shift_z[g];
  return h;
}

class PeriodicHalo {
 public:
  // Below this many copies a fill runs on one thread (a parallel region costs more).
  static constexpr long kMinParallelCopies = 4096;

  // Builds the ghost list: every owned particle within `width` of a periodic face
  // gets an image on the far side (edges and corners included); with width > L/2 a
  // particle near both faces gets both, so a cut-off above half the box finds every image
  // within it, not only the nearest. Requires width <= box length on each periodic axis.
  void build(const Box& box, double width, const double* x, const double* y, const double* z,
             std::size_t n_owned);

  std::size_t n_owned() const { return n_owned_; }
  std::size_t n_ghost() const { return source_.size(); }
  double width() const { return width_; }

  // Writes ghost positions (source position + periodic shift) after the owned ones.
  void fill_positions(double* x, double* y, double* z) const;
  // Copies a per-particle field from each ghost's owned source.
  template <class T>
  void fill(T* field) const {
    const long n = static_cast<long>(source_.size());
#pragma omp parallel for schedule(static) if (n > kMinParallelCopies)
    for (long g = 0; g < n; ++g) field[n_owned_ + g] = field[source_[g]];
  }
  template <class Vec>
  void fill(Vec& field) const {
    fill(field.data());
  }
  // The reverse of fill, for sums a pass wrote to the ghosts: adds each ghost's row of
  // `stride` values (rows: owned, then ghosts) to its source's row. One thread, so that
  // the images of one particle add in a fixed order. (An MPI halo: the ghosts' rows go
  // back to their owning rank.)
  void add_to_sources(double* rows, std::size_t stride) const {
    for (std::size_t g = 0; g < source_.size(); ++g) {
      const double* from = rows + (n_owned_ + g) * stride;
      double* to = rows + std::size_t{source_[g]} * stride;
      for (std::size_t i = 0; i < stride; ++i) to[i] += from[i];
    }
  }
  const std::vector<std::uint32_t>& source() const {
    return source_;
  }
  HaloImages images() const {
    return {n_owned_, source_.data(), sx_.data(), sy_.data(), sz_.data()};
  }

 private:
  std::size_t n_owned_ = 0;
  double width_ = 0;
  std::vector<std::uint32_t> source_;  // owned index of each ghost
  std::vector<double> sx_, sy_, sz_;   // shift added to the source position
};

}  // namespace sphdem
