#include "domain/sfc_grid.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>

namespace sphdem {

std::uint64_t hilbert_key(std::uint32_t x, std::uint32_t y, std::uint32_t z, int bits) {
  std::uint32_t X[3] = {x, y, z};
  const std::uint32_t top = 1u << (bits - 1);
  for (std::uint32_t q = top; q > 1; q >>= 1) {  // undo the excess work: invert or exchange
    const std::uint32_t p = q - 1;
    for (int i = 0; i < 3; ++i) {
      if (X[i] & q) {
        X[0] ^= p;
      } else {
        const std::uint32_t t = (X[0] ^ X[i]) & p;
        X[0] ^= t;
        X[i] ^= t;
      }
    }
  }
  for (int i = 1; i < 3; ++i) X[i] ^= X[i - 1];  // Gray encode
  std::uint32_t t = 0;
  for (std::uint32_t q = top; q > 1; q >>= 1)
    if (X[2] & q) t ^= q - 1;
  for (std::uint32_t& v : X) v ^= t;
  std::uint64_t key = 0;
  for (int b = bits - 1; b >= 0; --b)
    for (int i = 0; i < 3; ++i) key = (key << 1) | ((X[i] >> b) & 1u);
  return key;
}

SfcGrid::SfcGrid(const Box& box, double min_cell) : box_(box) {
  if (!(min_cell > 0.0)) throw std::invalid_argument("SfcGrid: the cell size must be > 0");
  int largest = 1;
  for (int d = 0; d < 3; ++d) {
    // a power of two: a range of the curve over a whole 2^b cube is a union of octree
    // boxes, near a cube (bench/RESULTS.md, session 29: 1.2-1.5 times a cube's ghosts
    // on other counts, 1.0-1.2 on these)
    const int fit = std::max(1, static_cast<int>(std::floor(box.length(d) / min_cell)));
    n_[d] = 1;
    while (2 * n_[d] <= fit) n_[d] *= 2;
    size_[d] = box.length(d) / n_[d];
    largest = std::max(largest, n_[d]);
  }
  bits_ = 1;
  while ((1 << bits_) < largest) ++bits_;
  if (bits_ > 21) throw std::invalid_argument("SfcGrid: more than 2^21 cells along an axis");
  if (cell_count() > std::size_t{1} << 31)
    throw std::invalid_argument("SfcGrid: more than 2^31 cells");
  std::vector<std::uint64_t> keys(cell_count());
  for (std::size_t i = 0; i < keys.size(); ++i) keys[i] = key(cell(i));
  curve_.resize(cell_count());
  std::iota(curve_.begin(), curve_.end(), 0u);
  std::sort(curve_.begin(), curve_.end(),
            [&](std::uint32_t a, std::uint32_t b) { return keys[a] < keys[b]; });
  position_.resize(cell_count());
  for (std::size_t k = 0; k < curve_.size(); ++k) position_[curve_[k]] = std::uint32_t(k);
}

std::array<int, 3> SfcGrid::cell_of(double x, double y, double z) const {
  const double p[3] = {x, y, z};
  std::array<int, 3> c{};
  for (int d = 0; d < 3; ++d) {
    const double v = box_.periodic[d] ? box_.wrap(d, p[d]) : p[d];
    const int i = static_cast<int>(std::floor((v - box_.lo[d]) / size_[d]));
    c[d] = std::clamp(i, 0, n_[d] - 1);
  }
  return c;
}

std::array<int, 3> SfcGrid::cell(std::size_t index) const {
  const int ix = static_cast<int>(index % n_[0]);
  const int iy = static_cast<int>((index / n_[0]) % n_[1]);
  const int iz = static_cast<int>(index / (std::size_t(n_[0]) * n_[1]));
  return {ix, iy, iz};
}

double SfcGrid::distance2_to_cell(std::size_t index, const double p[3]) const {
  const std::array<int, 3> c = cell(index);
  double r2 = 0.0;
  for (int d = 0; d < 3; ++d) {
    double lo = box_.lo[d] + c[d] * size_[d], hi = lo + size_[d];
    if (!box_.periodic[d]) {  // cell_of clamps points past a wall into the last cells
      if (c[d] == 0) lo = -std::numeric_limits<double>::infinity();
      if (c[d] == n_[d] - 1) hi = std::numeric_limits<double>::infinity();
    }
    const double out = p[d] < lo ? lo - p[d] : p[d] > hi ? p[d] - hi : 0.0;
    r2 += out * out;
  }
  return r2;
}

double decomposition_cell(const Box& box, double reach, int ranks) {
  double cell = reach;
  for (int halved = 0; halved < 2; ++halved)
    if (SfcGrid(box, cell).cell_count() < kCellsPerRank * static_cast<std::size_t>(ranks))
      cell /= 2;
  return cell;
}

}  // namespace sphdem
