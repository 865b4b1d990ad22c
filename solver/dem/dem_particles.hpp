#pragma once
// DEM spheres, structure of arrays. [0, n_owned) owned, the rest halo copies.
#include <cstddef>
#include <cstdint>
#include <vector>

namespace sphdem {

// Below this many spheres the sphere loops run on one thread: a parallel region costs
// more than the work (a single settling sphere takes ~10^5 sub-steps).
constexpr long kMinParallelSpheres = 256;

struct DemParticles {
  // state that defines the run (checkpointed)
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
  std::vector<double> cx, cy, cz;     // contact force
  std::vector<double> tx, ty, tz;     // contact torque (tangential and rolling parts; else 0)
  std::vector<double> ax, ay, az;     // acceleration
  std::vector<double> x0, y0, z0;     // positions at the last neighbour-list build
  std::vector<double> overlap_max;    // largest overlap on this sphere (diagnostic)

  std::size_t n_owned = 0;
  std::size_t size() const { return x.size(); }

  // Every per-particle array with its name (output, checkpoint, resizing, reordering).
  template <class F>
  void for_each_field(F&& f) {
    f("species", species);
    f("rigid_group", rigid_group);
    f("id", id);
    f("x", x);
    f("y", y);
    f("z", z);
    f("vx", vx);
    f("vy", vy);
    f("vz", vz);
    f("wx", wx);
    f("wy", wy);
    f("wz", wz);
    f("radius", radius);
    f("mass", mass);
    f("shepard", shepard);
    f("eps", eps);
    f("d_sauter", d_sauter);
    f("ufx", ufx);
    f("ufy", ufy);
    f("ufz", ufz);
    f("gx", gx);
    f("gy", gy);
    f("gz", gz);
    f("fx", fx);
    f("fy", fy);
    f("fz", fz);
    f("fmx", fmx);
    f("fmy", fmy);
    f("fmz", fmz);
    f("cx", cx);
    f("cy", cy);
    f("cz", cz);
    f("tx", tx);
    f("ty", ty);
    f("tz", tz);
    f("ax", ax);
    f("ay", ay);
    f("az", az);
    f("x0", x0);
    f("y0", y0);
    f("z0", z0);
    f("overlap_max", overlap_max);
  }
  void resize(std::size_t n) {
    const std::size_t old = rigid_group.size();
    for_each_field([n](const char*, auto& v) { v.resize(n); });
    for (std::size_t i = old; i < n; ++i)
      rigid_group[i] = -1;  // new spheres belong to no rigid group
  }
  double volume(std::size_t i) const {
    return 4.0 / 3.0 * 3.14159265358979323846 * radius[i] * radius[i] * radius[i];
  }
  // Moment of inertia of a solid sphere, 2/5 m r^2 (kg m^2).
  double inertia(std::size_t i) const { return 0.4 * mass[i] * radius[i] * radius[i]; }
};

}  // namespace sphdem
