#include "dem/contact_forces.hpp"

#include <algorithm>
#include <cmath>

namespace sphdem {

void ContactNeighbourList::build(const DemParticles& s, const CellList& cells, double skin_) {
  skin = skin_;
  const std::size_t n = s.n_owned;
  offset.assign(n + 1, 0);
  neighbour.clear();
  double rmax = 0.0;
  for (std::size_t i = 0; i < s.size(); ++i) rmax = std::max(rmax, s.radius[i]);
  const double rc_max = 2.0 * rmax + skin;
  for (std::size_t i = 0; i < n; ++i) {
    cells.for_each_neighbour(s.x[i], s.y[i], s.z[i], rc_max * rc_max,
                             [&](std::uint32_t j, double, double, double, double r2) {
                               if (j == i) return;
                               const double rc = s.radius[i] + s.radius[j] + skin;
                               if (r2 < rc * rc) neighbour.push_back(j);
                             });
    offset[i + 1] = static_cast<std::uint32_t>(neighbour.size());
  }
}

void compute_contact_forces(DemParticles& s, const ContactNeighbourList& list,
                            const LinearSpringDashpot& law, double wall_z) {
  const long n = static_cast<long>(s.n_owned);
#pragma omp parallel for schedule(static) if (n > 256)  // a parallel region costs more than a few spheres
  for (long i = 0; i < n; ++i) {
    double fx = 0, fy = 0, fz = 0, dmax = 0;
    const double ri = s.radius[i], mi = s.mass[i];
    for (std::uint32_t k = list.offset[i]; k < list.offset[i + 1]; ++k) {
      const std::uint32_t j = list.neighbour[k];
      const double dx = s.x[i] - s.x[j], dy = s.y[i] - s.y[j], dz = s.z[i] - s.z[j];
      const double r2 = dx * dx + dy * dy + dz * dz;
      const double rsum = ri + s.radius[j];
      if (r2 >= rsum * rsum) continue;
      const double r = std::sqrt(r2);
      const double nx = dx / r, ny = dy / r, nz = dz / r;  // from j to i
      const double delta = rsum - r;
      // d(delta)/dt = -(v_i - v_j) . n
      const double ddelta = -((s.vx[i] - s.vx[j]) * nx + (s.vy[i] - s.vy[j]) * ny + (s.vz[i] - s.vz[j]) * nz);
      const double m12 = mi * s.mass[j] / (mi + s.mass[j]);
      const double fn = law.normal_force(delta, ddelta, law.beta_for(m12));
      fx += fn * nx;
      fy += fn * ny;
      fz += fn * nz;
      dmax = std::max(dmax, delta);
    }
    const double dw = ri - (s.z[i] - wall_z);  // flat bottom wall, normal +z
    if (dw > 0.0) {
      fz += law.normal_force(dw, -s.vz[i], law.beta_for(mi));
      dmax = std::max(dmax, dw);
    }
    s.cx[i] = fx;
    s.cy[i] = fy;
    s.cz[i] = fz;
    s.overlap_max[i] = dmax;
  }
}

}  // namespace sphdem
