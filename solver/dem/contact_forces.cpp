#include "dem/contact_forces.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <type_traits>

namespace sphdem {

void ContactNeighbourList::build(const DemParticles& s, const CellList& cells, double skin_) {
  skin = skin_;
  const std::size_t n = s.n_owned;
  double rmax = 0.0;
  for (std::size_t i = 0; i < s.size(); ++i) rmax = std::max(rmax, s.radius[i]);
  const double rc_max = 2.0 * rmax + skin;
  rows_.build(n, offset, neighbour, [&](std::size_t i, std::vector<std::uint32_t>& out) {
    cells.for_each_neighbour(s.x[i], s.y[i], s.z[i], rc_max * rc_max,
                             [&](std::uint32_t j, double, double, double, double r2) {
                               if (j == i) return;
                               const double rc = s.radius[i] + s.radius[j] + skin;
                               if (r2 < rc * rc) out.push_back(j);
                             });
  });
}

void compute_contact_forces(DemParticles& s, const ContactNeighbourList& list,
                            const LinearSpringDashpot& law, double wall_z) {
  const long n = static_cast<long>(s.n_owned);
  const double bf = law.beta_factor();
  // Chunks taken in turn: a bed and a dilute suspension above it differ in contacts per
  // sphere. Below 256 spheres a parallel region costs more than the work.
#pragma omp parallel for schedule(dynamic, 256) if (n > 256)
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
      const double fn = law.normal_force(delta, ddelta, law.beta_for(m12, bf));
      fx += fn * nx;
      fy += fn * ny;
      fz += fn * nz;
      dmax = std::max(dmax, delta);
    }
    const double dw = ri - (s.z[i] - wall_z);  // flat bottom wall, normal +z
    if (dw > 0.0) {
      fz += law.normal_force(dw, -s.vz[i], law.beta_for(mi, bf));
      dmax = std::max(dmax, dw);
    }
    s.cx[i] = fx;
    s.cy[i] = fy;
    s.cz[i] = fz;
    s.overlap_max[i] = dmax;
  }
}

template <class Model>
void compute_contact_forces(DemParticles& s, const ContactNeighbourList& list, const Model& model,
                            ContactHistory& history, const HaloImages& images, double wall_z, double dt) {
  static_assert(Model::kHistory, "the normal-only law has its own pass");
  constexpr bool kRolling = decltype(model.rolling)::kEnabled;
  const LinearSpringDashpot& law = model.normal;
  const auto& tangential = model.tangential;
  const std::size_t n_owned = s.n_owned;
  if (history.pair.size() != list.neighbour.size() || history.wall.size() != n_owned)
    throw std::logic_error("compute_contact_forces: the contact history is not loaded for this list");
  const long n = static_cast<long>(n_owned);
  const double bf = law.beta_factor();
#pragma omp parallel for schedule(dynamic, 256) if (n > 256)  // as the normal-only pass
  for (long i = 0; i < n; ++i) {
    double fx = 0, fy = 0, fz = 0, qx = 0, qy = 0, qz = 0, dmax = 0;
    const double ri = s.radius[i], mi = s.mass[i];
    const std::int64_t id_i = s.id[i];
    for (std::uint32_t k = list.offset[i]; k < list.offset[i + 1]; ++k) {
      const std::uint32_t j = list.neighbour[k];
      double dx, dy, dz;  // x_i - x_j, exactly antisymmetric (HaloImages)
      if (j < n_owned) {
        dx = s.x[i] - s.x[j];
        dy = s.y[i] - s.y[j];
        dz = s.z[i] - s.z[j];
      } else {
        const std::size_t g = j - images.n_owned;
        const std::uint32_t h = images.source[g];
        dx = (s.x[i] - s.x[h]) - images.shift_x[g];
        dy = (s.y[i] - s.y[h]) - images.shift_y[g];
        dz = (s.z[i] - s.z[h]) - images.shift_z[g];
      }
      const double r2 = dx * dx + dy * dy + dz * dz;
      const double rsum = ri + s.radius[j];
      ContactState& st = history.pair[k];
      if (r2 >= rsum * rsum) {
        if (st.active()) st = ContactState{};  // the contact has ended
        continue;
      }
      // Canonical orientation: a = the lower id, n from b to a.
      const bool i_is_a = id_i < s.id[j];
      const double sg = i_is_a ? 1.0 : -1.0;
      const std::size_t a = i_is_a ? static_cast<std::size_t>(i) : j;
      const std::size_t b = i_is_a ? j : static_cast<std::size_t>(i);
      const double r = std::sqrt(r2);
      const double nv[3] = {sg * dx / r, sg * dy / r, sg * dz / r};
      const double delta = rsum - r;
      const double vrx = s.vx[a] - s.vx[b], vry = s.vy[a] - s.vy[b], vrz = s.vz[a] - s.vz[b];
      const double ma = s.mass[a], mb = s.mass[b];
      const double m12 = ma * mb / (ma + mb);
      const double fn = law.normal_force(delta, -(vrx * nv[0] + vry * nv[1] + vrz * nv[2]), law.beta_for(m12, bf));
      const double fn_abs = std::abs(fn);
      // velocity of a relative to b at the contact point: v_a - v_b - (c_a w_a + c_b w_b) x n
      const double ca = s.radius[a] - 0.5 * delta, cb = s.radius[b] - 0.5 * delta;
      const double wsx = ca * s.wx[a] + cb * s.wx[b];
      const double wsy = ca * s.wy[a] + cb * s.wy[b];
      const double wsz = ca * s.wz[a] + cb * s.wz[b];
      const double vcx = vrx - (wsy * nv[2] - wsz * nv[1]);
      const double vcy = vry - (wsz * nv[0] - wsx * nv[2]);
      const double vcz = vrz - (wsx * nv[1] - wsy * nv[0]);
      const double vcn = vcx * nv[0] + vcy * nv[1] + vcz * nv[2];
      const double vt[3] = {vcx - vcn * nv[0], vcy - vcn * nv[1], vcz - vcn * nv[2]};
      double ft[3];
      tangential.force(nv, vt, tangential.gamma_for(m12), fn_abs, dt, st.xi, ft);
      fx += sg * (fn * nv[0] + ft[0]);
      fy += sg * (fn * nv[1] + ft[1]);
      fz += sg * (fn * nv[2] + ft[2]);
      // torque -c_i n x F_t, the same sign on both sides (F_t and n both flip)
      const double ci = i_is_a ? ca : cb;
      qx -= ci * (nv[1] * ft[2] - nv[2] * ft[1]);
      qy -= ci * (nv[2] * ft[0] - nv[0] * ft[2]);
      qz -= ci * (nv[0] * ft[1] - nv[1] * ft[0]);
      if constexpr (kRolling) {
        const double w[3] = {s.wx[a] - s.wx[b], s.wy[a] - s.wy[b], s.wz[a] - s.wz[b]};
        const double ra = s.radius[a], rb = s.radius[b];
        const double ia = 1.4 * ma * ra * ra, ib = 1.4 * mb * rb * rb;  // I + m r^2
        double m[3];
        model.rolling.torque(nv, w, ra * rb / (ra + rb), ia * ib / (ia + ib), fn_abs, dt, st.mr, m);
        qx += sg * m[0];
        qy += sg * m[1];
        qz += sg * m[2];
      }
      dmax = std::max(dmax, delta);
    }
    // Flat bottom wall, normal +z; lever arm = distance of the centre to the wall.
    const double hw = s.z[i] - wall_z;
    const double dw = ri - hw;
    ContactState& sw = history.wall[i];
    if (dw > 0.0) {
      const double fn = law.normal_force(dw, -s.vz[i], law.beta_for(mi, bf));
      const double fn_abs = std::abs(fn);
      static constexpr double nz[3] = {0.0, 0.0, 1.0};
      const double vt[3] = {s.vx[i] - hw * s.wy[i], s.vy[i] + hw * s.wx[i], 0.0};
      double ft[3];
      tangential.force(nz, vt, tangential.gamma_for(mi), fn_abs, dt, sw.xi, ft);
      fx += ft[0];
      fy += ft[1];
      fz += fn;
      qx += hw * ft[1];  // -h z x F_t
      qy -= hw * ft[0];
      if constexpr (kRolling) {
        const double w[3] = {s.wx[i], s.wy[i], s.wz[i]};
        double m[3];
        model.rolling.torque(nz, w, ri, 1.4 * mi * ri * ri, fn_abs, dt, sw.mr, m);
        qx += m[0];
        qy += m[1];
        qz += m[2];
      }
      dmax = std::max(dmax, dw);
    } else if (sw.active()) {
      sw = ContactState{};
    }
    s.cx[i] = fx;
    s.cy[i] = fy;
    s.cz[i] = fz;
    s.tx[i] = qx;
    s.ty[i] = qy;
    s.tz[i] = qz;
    s.overlap_max[i] = dmax;
  }
}

template void compute_contact_forces(DemParticles&, const ContactNeighbourList&, const FrictionalContact&,
                                     ContactHistory&, const HaloImages&, double, double);
template void compute_contact_forces(DemParticles&, const ContactNeighbourList&, const FrictionalRollingContact&,
                                     ContactHistory&, const HaloImages&, double, double);

void compute_contact_forces(DemParticles& s, const ContactNeighbourList& list, const ContactLaw& law,
                            ContactHistory& history, const HaloImages& images, double wall_z, double dt) {
  std::visit(
      [&](const auto& model) {
        if constexpr (std::decay_t<decltype(model)>::kHistory)
          compute_contact_forces(s, list, model, history, images, wall_z, dt);
        else
          compute_contact_forces(s, list, model.normal, wall_z);
      },
      law);
}

}  // namespace sphdem
