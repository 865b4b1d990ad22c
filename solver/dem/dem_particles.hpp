#pragma once
// DEM spheres, structure of arrays. [0, n_owned) owned, the rest halo copies.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "domain/field_info.hpp"

namespace sphdem {

// Below this many spheres the sphere loops run on one thread: a parallel region costs
// more than the work (a single settling sphere takes ~10^5 sub-steps).
constexpr long kMinParallelSpheres = 256;

struct DemParticles {
  // Roles (carried state, scratch, halo) are in the registry at the end.
  std::vector<double> x, y, z;     // centre (m)
  std::vector<double> vx, vy, vz;  // velocity (m/s)
  std::vector<double> wx, wy, wz;  // angular velocity (rad/s); integrated only when the contact
                                   // model has tangential or rolling parts, never for rigid groups
  std::vector<double> radius;      // (m)
  std::vector<double> mass;        // (kg)
  std::vector<std::uint16_t> species;
  std::vector<std::int32_t> rigid_group;  // >= 0: moves rigidly with its group (thesis §4.5)
  std::vector<std::int64_t> id;
  // fluid fields interpolated at the sphere, held fixed during DEM sub-steps (2.69, 2.74)
  std::vector<double> shepard;        // S_j, eq. 2.72
  std::vector<double> eps;            // voidage at the sphere
  std::vector<double> d_sauter;       // local Sauter mean diameter at the sphere (2.80)
  std::vector<double> ufx, ufy, ufz;  // fluid velocity at the sphere
  std::vector<double> gx, gy, gz;     // (-grad P + div tau) at the sphere, eq. 2.69
  // forces
  std::vector<double> fx, fy, fz;     // fluid force now, eq. 2.68
  std::vector<double> fmx, fmy, fmz;  // fluid force averaged over the last SPH step
  std::vector<double> drag_c;         // the last force pass's drag coefficient c (2.68)
  std::vector<double> cx, cy, cz;     // contact force
  std::vector<double> tx, ty, tz;     // contact torque (tangential and rolling parts; else 0)
  std::vector<double> ax, ay, az;     // acceleration
  std::vector<double> x0, y0, z0;     // positions at the last neighbour-list build
  std::vector<double> overlap_max;    // largest overlap on this sphere (diagnostic)

  std::size_t n_owned = 0;
  std::size_t size() const { return x.size(); }

  // The field registry: every per-particle array with its name and role
  // (domain/field_info.hpp), for checkpoints, halos, resizing and reordering.
  static constexpr int kFieldCount = 43;
  template <class F>
  void for_each_field(F&& f) {
    visit_fields(*this, f);
  }
  template <class F>
  void for_each_field(F&& f) const {
    visit_fields(*this, f);
  }
  void resize(std::size_t n) {
    const std::size_t old = rigid_group.size();
    for_each_field([n](const FieldInfo&, auto& v) { v.resize(n); });
    for (std::size_t i = old; i < n; ++i)
      rigid_group[i] = -1;  // new spheres belong to no rigid group
  }
  double volume(std::size_t i) const {
    return 4.0 / 3.0 * 3.14159265358979323846 * radius[i] * radius[i] * radius[i];
  }
  // Moment of inertia of a solid sphere, 2/5 m r^2 (kg m^2).
  double inertia(std::size_t i) const { return 0.4 * mass[i] * radius[i] * radius[i]; }

 private:
  template <class Self, class F>
  static void visit_fields(Self& p, F& f) {
    constexpr unsigned kConst = kState | kConstant;
    constexpr unsigned kMoving = kState | kHaloOnBuild;  // positions, velocities, spins
    f(FieldInfo{"species", kConst | kHaloOnBuild}, p.species);
    f(FieldInfo{"rigid_group", kConst}, p.rigid_group);
    f(FieldInfo{"id", kConst | kHaloOnBuild}, p.id);
    f(FieldInfo{"x", kMoving | kPosition}, p.x);
    f(FieldInfo{"y", kMoving | kPosition}, p.y);
    f(FieldInfo{"z", kMoving | kPosition}, p.z);
    f(FieldInfo{"vx", kMoving}, p.vx);
    f(FieldInfo{"vy", kMoving}, p.vy);
    f(FieldInfo{"vz", kMoving}, p.vz);
    f(FieldInfo{"wx", kMoving}, p.wx);
    f(FieldInfo{"wy", kMoving}, p.wy);
    f(FieldInfo{"wz", kMoving}, p.wz);
    f(FieldInfo{"radius", kConst | kHaloOnBuild}, p.radius);
    f(FieldInfo{"mass", kConst | kHaloOnBuild}, p.mass);
    // the fluid fields at the sphere are held over the sub-steps of the next half step
    f(FieldInfo{"shepard", kState | kHaloAfterPass}, p.shepard);
    f(FieldInfo{"eps", kState}, p.eps);
    f(FieldInfo{"d_sauter", kState}, p.d_sauter);
    f(FieldInfo{"ufx", kState}, p.ufx);
    f(FieldInfo{"ufy", kState}, p.ufy);
    f(FieldInfo{"ufz", kState}, p.ufz);
    f(FieldInfo{"gx", kState}, p.gx);
    f(FieldInfo{"gy", kState}, p.gy);
    f(FieldInfo{"gz", kState}, p.gz);
    f(FieldInfo{"fx", kState}, p.fx);  // the trapezoid's old force
    f(FieldInfo{"fy", kState}, p.fy);
    f(FieldInfo{"fz", kState}, p.fz);
    f(FieldInfo{"fmx", kState | kHaloAfterPass}, p.fmx);  // the open mean-force window
    f(FieldInfo{"fmy", kState | kHaloAfterPass}, p.fmy);
    f(FieldInfo{"fmz", kState | kHaloAfterPass}, p.fmz);
    f(FieldInfo{"drag_c", kScratch}, p.drag_c);  // (0 before the first pass, without fluid)
    f(FieldInfo{"cx", kScratch}, p.cx);
    f(FieldInfo{"cy", kScratch}, p.cy);
    f(FieldInfo{"cz", kScratch}, p.cz);
    f(FieldInfo{"tx", kState}, p.tx);  // the spin predictor's torque
    f(FieldInfo{"ty", kState}, p.ty);
    f(FieldInfo{"tz", kState}, p.tz);
    f(FieldInfo{"ax", kState}, p.ax);  // the first sub-step's acceleration
    f(FieldInfo{"ay", kState}, p.ay);
    f(FieldInfo{"az", kState}, p.az);
    f(FieldInfo{"x0", kScratch}, p.x0);
    f(FieldInfo{"y0", kScratch}, p.y0);
    f(FieldInfo{"z0", kScratch}, p.z0);
    f(FieldInfo{"overlap_max", kScratch}, p.overlap_max);
  }
};

// Every member is a field of the registry (a member added without an entry fails here).
static_assert(sizeof(DemParticles) ==
                  DemParticles::kFieldCount * sizeof(std::vector<double>) + sizeof(std::size_t),
              "DemParticles: list every per-particle array in visit_fields");

}  // namespace sphdem
