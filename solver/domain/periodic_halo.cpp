#include "domain/periodic_halo.hpp"

#include <stdexcept>
#include <string>

namespace sphdem {

void PeriodicHalo::build(const Box& box, double width, const double* x, const double* y,
                         const double* z, std::size_t n_owned) {
  n_owned_ = n_owned;
  width_ = width;
  source_.clear();
  sx_.clear();
  sy_.clear();
  sz_.clear();
  const double* pos[3] = {x, y, z};
  for (int d = 0; d < 3; ++d) {
    if (!box.periodic[d]) continue;
    const double L = box.length(d);
    if (width > L)  // one shift of +-L per axis reaches every image within width
      throw std::runtime_error("periodic box axis " + std::to_string(d) + " (" + std::to_string(L) +
                               " m) is narrower than the halo width (" + std::to_string(width) +
                               " m)");
    // Images of owned particles and of the ghosts made along earlier axes (edges, corners).
    const std::size_t n_before = source_.size();
    auto consider = [&](std::uint32_t src, double sx, double sy, double sz) {
      const double s[3] = {sx, sy, sz};
      const double p = pos[d][src] + s[d];
      if (p < box.lo[d] + width) {
        source_.push_back(src);
        sx_.push_back(sx + (d == 0 ? L : 0.0));
        sy_.push_back(sy + (d == 1 ? L : 0.0));
        sz_.push_back(sz + (d == 2 ? L : 0.0));
      }
      if (p >= box.hi[d] - width) {
        source_.push_back(src);
        sx_.push_back(sx - (d == 0 ? L : 0.0));
        sy_.push_back(sy - (d == 1 ? L : 0.0));
        sz_.push_back(sz - (d == 2 ? L : 0.0));
      }
    };
    for (std::size_t i = 0; i < n_owned; ++i) consider(static_cast<std::uint32_t>(i), 0, 0, 0);
    for (std::size_t g = 0; g < n_before; ++g) consider(source_[g], sx_[g], sy_[g], sz_[g]);
  }
}

void PeriodicHalo::fill_positions(double* x, double* y, double* z) const {
  const long n = static_cast<long>(source_.size());
#pragma omp parallel for schedule(static) if (n > kMinParallelCopies)
  for (long g = 0; g < n; ++g) {
    const std::uint32_t s = source_[g];
    x[n_owned_ + g] = x[s] + sx_[g];
    y[n_owned_ + g] = y[s] + sy_[g];
    z[n_owned_ + g] = z[s] + sz_[g];
  }
}

}  // namespace sphdem
