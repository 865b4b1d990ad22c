#pragma once
// One owned sphere's contact force and torque: a row of the full contact list. The
// contact pass (contact_forces.cpp) stores rows; the DEM sub-step's force pass adds the
// fluid force and the acceleration to a row while it is still in registers, so a
// sub-step streams the sphere arrays once for all its forces.
//
// Halo neighbours are read through HaloImages: on one rank through their owned source, so
// that between two list builds the sub-steps need no halo fill; on several ranks a copy
// stands for itself, refreshed before every pass (SphereLists::refresh_for_contacts).
#include <algorithm>
#include <cmath>
#include <cstdint>

#include "dem/contact_history.hpp"
#include "dem/contact_list.hpp"
#include "dem/contact_model.hpp"
#include "dem/dem_particles.hpp"
#include "dem/sphere_walls.hpp"
#include "domain/periodic_halo.hpp"

namespace sphdem {

// A sphere's own share of the cost of its row, in list entries (domain/row_partition.hpp).
constexpr double kContactRowCost = 4.0;

struct ContactRow {
  double fx = 0, fy = 0, fz = 0;  // force on the sphere
  double qx = 0, qy = 0, qz = 0;  // torque (tangential and rolling parts)
  double overlap = 0;             // largest overlap
};

// The top plane's normal force on sphere i (frictionless, normal -z), into row.
inline void add_top_plane(const DemParticles& s, const LinearSpringDashpot& law, double bf,
                          double top_z, std::size_t i, ContactRow& row) {
  const double dt = s.radius[i] - (top_z - s.z[i]);
  if (dt > 0.0) {
    row.fz -= law.normal_force(dt, s.vz[i], law.beta_for(s.mass[i], bf));
    row.overlap = std::max(row.overlap, dt);
  }
}

// Linear spring-dashpot (2.36) with the other spheres, the flat bottom wall at
// z = walls.bottom (normal +z) and the top plane; bf = law.beta_factor().
inline ContactRow normal_contact_row(const DemParticles& s, const ContactNeighbourList& list,
                                     const LinearSpringDashpot& law, double bf,
                                     const HaloImages& images, SphereWalls walls, std::size_t i) {
  const double wall_z = walls.bottom;
  ContactRow row;
  const double ri = s.radius[i], mi = s.mass[i];
  for (std::uint32_t k = list.offset[i]; k < list.offset[i + 1]; ++k) {
    double dx, dy, dz;
    const std::size_t j =
        owned_image(images, list.neighbour[k], s.x[i], s.y[i], s.z[i], s.x, s.y, s.z, dx, dy, dz);
    const double r2 = dx * dx + dy * dy + dz * dz;
    const double rsum = ri + s.radius[j];
    if (r2 >= rsum * rsum) continue;
    const double r = std::sqrt(r2);
    const double nx = dx / r, ny = dy / r, nz = dz / r;  // from j to i
    const double delta = rsum - r;
    // d(delta)/dt = -(v_i - v_j) . n
    const double ddelta =
        -((s.vx[i] - s.vx[j]) * nx + (s.vy[i] - s.vy[j]) * ny + (s.vz[i] - s.vz[j]) * nz);
    const double m12 = mi * s.mass[j] / (mi + s.mass[j]);
    const double fn = law.normal_force(delta, ddelta, law.beta_for(m12, bf));
    row.fx += fn * nx;
    row.fy += fn * ny;
    row.fz += fn * nz;
    row.overlap = std::max(row.overlap, delta);
  }
  const double dw = ri - (s.z[i] - wall_z);
  if (dw > 0.0) {
    row.fz += law.normal_force(dw, -s.vz[i], law.beta_for(mi, bf));
    row.overlap = std::max(row.overlap, dw);
  }
  add_top_plane(s, law, bf, walls.top, i, row);
  return row;
}

// With tangential and rolling parts (a registered ContactModel with kHistory): advances
// the working copy of the contact history by dt (contact_forces.hpp gives the
// conventions: canonical orientation from the lower id, contact point mid-overlap).
template <class Model>
inline ContactRow history_contact_row(const DemParticles& s, const ContactNeighbourList& list,
                                      const Model& model, double bf, ContactHistory& history,
                                      const HaloImages& images, SphereWalls walls, double dt,
                                      std::size_t i) {
  const double wall_z = walls.bottom;
  constexpr bool kRolling = decltype(model.rolling)::kEnabled;
  const LinearSpringDashpot& law = model.normal;
  const auto& tangential = model.tangential;
  ContactRow row;
  const double ri = s.radius[i], mi = s.mass[i];
  const std::int64_t id_i = s.id[i];
  for (std::uint32_t k = list.offset[i]; k < list.offset[i + 1]; ++k) {
    double dx, dy, dz;  // x_i - x_j, exactly antisymmetric (HaloImages)
    const std::size_t j =
        owned_image(images, list.neighbour[k], s.x[i], s.y[i], s.z[i], s.x, s.y, s.z, dx, dy, dz);
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
    const std::size_t a = i_is_a ? i : j;
    const std::size_t b = i_is_a ? j : i;
    const double r = std::sqrt(r2);
    const double nv[3] = {sg * dx / r, sg * dy / r, sg * dz / r};
    const double delta = rsum - r;
    const double vrx = s.vx[a] - s.vx[b], vry = s.vy[a] - s.vy[b], vrz = s.vz[a] - s.vz[b];
    const double ma = s.mass[a], mb = s.mass[b];
    const double m12 = ma * mb / (ma + mb);
    const double fn =
        law.normal_force(delta, -(vrx * nv[0] + vry * nv[1] + vrz * nv[2]), law.beta_for(m12, bf));
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
    row.fx += sg * (fn * nv[0] + ft[0]);
    row.fy += sg * (fn * nv[1] + ft[1]);
    row.fz += sg * (fn * nv[2] + ft[2]);
    // torque -c_i n x F_t, the same sign on both sides (F_t and n both flip)
    const double ci = i_is_a ? ca : cb;
    row.qx -= ci * (nv[1] * ft[2] - nv[2] * ft[1]);
    row.qy -= ci * (nv[2] * ft[0] - nv[0] * ft[2]);
    row.qz -= ci * (nv[0] * ft[1] - nv[1] * ft[0]);
    if constexpr (kRolling) {
      const double w[3] = {s.wx[a] - s.wx[b], s.wy[a] - s.wy[b], s.wz[a] - s.wz[b]};
      const double ra = s.radius[a], rb = s.radius[b];
      const double ia = 1.4 * ma * ra * ra, ib = 1.4 * mb * rb * rb;  // I + m r^2
      double m[3];
      model.rolling.torque(nv, w, ra * rb / (ra + rb), ia * ib / (ia + ib), fn_abs, dt, st.mr, m);
      row.qx += sg * m[0];
      row.qy += sg * m[1];
      row.qz += sg * m[2];
    }
    row.overlap = std::max(row.overlap, delta);
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
    row.fx += ft[0];
    row.fy += ft[1];
    row.fz += fn;
    row.qx += hw * ft[1];  // -h z x F_t
    row.qy -= hw * ft[0];
    if constexpr (kRolling) {
      const double w[3] = {s.wx[i], s.wy[i], s.wz[i]};
      double m[3];
      model.rolling.torque(nz, w, ri, 1.4 * mi * ri * ri, fn_abs, dt, sw.mr, m);
      row.qx += m[0];
      row.qy += m[1];
      row.qz += m[2];
    }
    row.overlap = std::max(row.overlap, dw);
  } else if (sw.active()) {
    sw = ContactState{};
  }
  add_top_plane(s, law, bf, walls.top, i, row);
  return row;
}

// Any registered model's row (contact_registry.hpp); dt and the history are unused by
// the normal-only one.
template <class Model>
inline ContactRow contact_row(const DemParticles& s, const ContactNeighbourList& list,
                              const Model& model, double bf, ContactHistory& history,
                              const HaloImages& images, SphereWalls walls, double dt,
                              std::size_t i) {
  if constexpr (Model::kHistory)
    return history_contact_row(s, list, model, bf, history, images, walls, dt, i);
  else
    return normal_contact_row(s, list, model.normal, bf, images, walls, i);
}

// Stores what a row gives besides its force: with a history model the torque
// (tx,ty,tz), and overlap_max. The DEM sub-step adds the force to the acceleration.
template <class Model>
inline void store_torque_and_overlap(DemParticles& s, std::size_t i, const ContactRow& row) {
  if constexpr (Model::kHistory) {
    s.tx[i] = row.qx;
    s.ty[i] = row.qy;
    s.tz[i] = row.qz;
  }
  s.overlap_max[i] = row.overlap;
}

// Stores a row as the contact pass's output: the force (cx,cy,cz), the torque and the overlap.
template <class Model>
inline void store_contact_row(DemParticles& s, std::size_t i, const ContactRow& row) {
  s.cx[i] = row.fx;
  s.cy[i] = row.fy;
  s.cz[i] = row.fz;
  store_torque_and_overlap<Model>(s, i, row);
}

}  // namespace sphdem
