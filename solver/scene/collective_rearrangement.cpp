#include "scene/collective_rearrangement.hpp"

#include <algorithm>
#include <cmath>

namespace sphdem {

namespace {

// The centre back inside the region: wrapped, or clamped to keep a sphere of radius r in.
double place(const PlacementRegion& w, int a, double v, double r) {
  if (w.wrap[a]) {
    v = w.lo[a] + std::fmod(v - w.lo[a], w.span[a]);
    return v < w.lo[a] ? v + w.span[a] : v;
  }
  return std::clamp(v, w.lo[a] + r, w.lo[a] + w.span[a] - r);
}

}  // namespace

Rearrangement rearrange(const PlacementRegion& where, const FixedSpheres& fixed, SphereGrid& grid,
                        std::vector<double>& x, std::vector<double>& y, std::vector<double>& z,
                        const std::vector<double>& radius) {
  const std::size_t n = radius.size();
  std::vector<double> px(n), py(n), pz(n);
  Rearrangement out;
  for (; out.sweeps < kMaxSweeps; ++out.sweeps) {
    grid.clear();
    for (std::size_t i = 0; i < n; ++i) grid.insert(x[i], y[i], z[i], radius[i]);
    for (std::size_t j = 0; j < fixed.x.size(); ++j)
      grid.insert(fixed.x[j], fixed.y[j], fixed.z[j], fixed.radius[j]);
    double worst = 0;
    for (std::size_t i = 0; i < n; ++i) {
      double ux = 0, uy = 0, uz = 0;
      grid.any_near(x[i], y[i], z[i],
                    [&](std::size_t j, double dx, double dy, double dz, double rj) {
                      const double contact = radius[i] + rj;
                      const double d2 = dx * dx + dy * dy + dz * dz;
                      if (j == i || d2 >= contact * contact) return false;
                      const double dist = std::sqrt(d2);
                      worst = std::max(worst, 1.0 - dist / contact);
                      const double push = (j < n ? 0.5 : 1.0) * (contact * (1.0 + kPushGap) - dist);
                      if (dist > 0) {
                        ux += push * dx / dist;
                        uy += push * dy / dist;
                        uz += push * dz / dist;
                      } else {  // coincident centres: apart along z, the lower index down
                        uz += i < j ? -push : push;
                      }
                      return false;
                    });
      px[i] = place(where, 0, x[i] + ux, radius[i]);
      py[i] = place(where, 1, y[i] + uy, radius[i]);
      pz[i] = place(where, 2, z[i] + uz, radius[i]);
    }
    out.overlap = worst;
    if (worst <= 0) {
      out.converged = true;
      return out;
    }
    x.swap(px);
    y.swap(py);
    z.swap(pz);
  }
  return out;
}

}  // namespace sphdem
