#pragma once
// A linked-cell grid of spheres for placing a particle group (random_packing.cpp,
// collective_rearrangement.cpp): head[cell] is the last sphere put in the cell and
// next[j] the one before it (-1 ends a list). Cells are at least min_width wide, so a
// sphere's neighbours within min_width lie in the 27 cells around it; distances are
// minimum images on the box's periodic x and y and, where the group fills a periodic
// height, on z. Build-time only: it allocates as it grows.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "scene/scene.hpp"

namespace sphdem {

class SphereGrid {
 public:
  // Cells of width >= min_width over the box in x and y (wrapping on periodic axes) and
  // over [zlo, zhi] in z (wrapping there where the group fills a periodic height).
  SphereGrid(const Box& box, double zlo, double zhi, double min_width, bool wrap_z) : box_(box) {
    const std::array<double, 3> lo{box.lo[0], box.lo[1], zlo}, hi{box.hi[0], box.hi[1], zhi};
    for (int a = 0; a < 3; ++a) {
      lo_[a] = lo[a];
      n_[a] = std::max(1, static_cast<int>(std::floor((hi[a] - lo[a]) / min_width)));
      width_[a] = (hi[a] - lo[a]) / n_[a];
      wrap_[a] = a < 2 ? box.periodic[a] : wrap_z;
    }
    head_.assign(static_cast<std::size_t>(n_[0]) * n_[1] * n_[2], -1);
  }

  // Empties the grid, keeping its cells.
  void clear() {
    std::fill(head_.begin(), head_.end(), -1);
    next_.clear();
    x_.clear();
    y_.clear();
    z_.clear();
    r_.clear();
  }

  void insert(double x, double y, double z, double r) {
    const std::int32_t j = static_cast<std::int32_t>(x_.size());
    x_.push_back(x);
    y_.push_back(y);
    z_.push_back(z);
    r_.push_back(r);
    const std::size_t c = cell(axis_cell(0, x), axis_cell(1, y), axis_cell(2, z));
    next_.push_back(head_[c]);
    head_[c] = j;
  }

  // Calls visit(j, dx, dy, dz, r_j) for each sphere j in the cells around (x, y, z), with
  // (dx, dy, dz) = (x, y, z) - centre_j by minimum image, until visit returns true (then
  // returns true).
  template <class Visit>
  bool any_near(double x, double y, double z, Visit&& visit) const {
    int cx[3], cy[3], cz[3];
    const int mx = around(0, axis_cell(0, x), cx), my = around(1, axis_cell(1, y), cy),
              mz = around(2, axis_cell(2, z), cz);
    const double Lx = box_.length(0), Ly = box_.length(1), Lz = box_.length(2);
    for (int kz = 0; kz < mz; ++kz)
      for (int ky = 0; ky < my; ++ky)
        for (int kx = 0; kx < mx; ++kx)
          for (std::int32_t j = head_[cell(cx[kx], cy[ky], cz[kz])]; j >= 0; j = next_[j]) {
            double dx = x - x_[j], dy = y - y_[j];
            double dz = z - z_[j];
            if (box_.periodic[0]) dx -= Lx * std::nearbyint(dx / Lx);
            if (box_.periodic[1]) dy -= Ly * std::nearbyint(dy / Ly);
            if (wrap_[2]) dz -= Lz * std::nearbyint(dz / Lz);
            if (visit(static_cast<std::size_t>(j), dx, dy, dz, r_[j])) return true;
          }
    return false;
  }

  // Does a sphere (x, y, z, r) overlap a placed one? Touching is allowed.
  bool overlaps(double x, double y, double z, double r) const {
    return any_near(x, y, z, [r](std::size_t, double dx, double dy, double dz, double rj) {
      const double rs = r + rj;
      return dx * dx + dy * dy + dz * dz < rs * rs;
    });
  }

 private:
  int axis_cell(int a, double v) const {
    int i = static_cast<int>(std::floor((v - lo_[a]) / width_[a]));
    if (wrap_[a]) {
      i %= n_[a];
      return i < 0 ? i + n_[a] : i;
    }
    return std::clamp(i, 0, n_[a] - 1);
  }
  // The distinct cells within one of cell i along axis a.
  int around(int a, int i, int out[3]) const {
    int m = 0;
    if (wrap_[a] && n_[a] < 3) {
      for (int k = 0; k < n_[a]; ++k) out[m++] = k;
      return m;
    }
    for (int d = -1; d <= 1; ++d) {
      int j = i + d;
      if (wrap_[a])
        j = (j + n_[a]) % n_[a];
      else if (j < 0 || j >= n_[a])
        continue;
      out[m++] = j;
    }
    return m;
  }
  std::size_t cell(int ix, int iy, int iz) const {
    return (static_cast<std::size_t>(iz) * n_[1] + iy) * n_[0] + ix;
  }

  Box box_;
  std::array<int, 3> n_{};
  std::array<double, 3> lo_{}, width_{};
  std::array<bool, 3> wrap_{};
  std::vector<std::int32_t> head_, next_;
  std::vector<double> x_, y_, z_, r_;
};

}  // namespace sphdem
