#pragma once
// The simulation box: an axis-aligned region, periodic or bounded per axis.
// Knows nothing of SPH or DEM (layer 0, like SPH-EXA's cstone).
#include <algorithm>
#include <array>
#include <cmath>

namespace sphdem {

struct Box {
  std::array<double, 3> lo{0, 0, 0};
  std::array<double, 3> hi{1, 1, 1};
  std::array<bool, 3> periodic{true, true, false};

  double length(int d) const { return hi[d] - lo[d]; }

  // Map a coordinate back into [lo, hi) along a periodic axis.
  double wrap(int d, double v) const {
    if (!periodic[d]) return v;
    const double L = length(d);
    double r = std::fmod(v - lo[d], L);  // in (-L, L)
    if (r < 0) r += L;                   // in [0, L], L only by round-off
    const double w = lo[d] + r;
    return (w >= hi[d] || w < lo[d]) ? lo[d] : w;  // round-off at either face
  }

  // A halo width of at least `needed`, and up to `wanted` where the periodic lengths
  // allow (a wider halo than the box would only repeat images).
  double halo_width(double needed, double wanted) const {
    double width = std::max(needed, wanted);
    for (int d = 0; d < 3; ++d)
      if (periodic[d]) width = std::min(width, std::max(needed, length(d)));
    return width;
  }
};

}  // namespace sphdem
