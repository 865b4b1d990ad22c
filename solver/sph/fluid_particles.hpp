#pragma once
// SPH particles, structure of arrays. Indices [0, n_owned) are owned; the rest are
// halo copies. Wall particles (kind == kWall) are owned but never move.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "domain/field_info.hpp"

namespace sphdem {

enum FluidKind : std::uint8_t { kFluid = 0, kWall = 1 };

struct FluidParticles {
  // Roles (carried state, scratch, halo) are in the registry at the end.
  std::vector<double> x, y, z;     // position (m)
  std::vector<double> vx, vy, vz;  // velocity (m/s)
  std::vector<double> rho;         // superficial density eps*rho_f (kg/m^3)
  std::vector<double> mass;        // constant mass (kg)
  std::vector<std::uint8_t> kind;  // kFluid or kWall
  std::vector<std::int64_t> id;    // global id
  std::vector<double> h, inv_h;    // smoothing length, eq. 2.65, and 1/h
  std::vector<double> drho;        // density rate, eq. 2.53
  std::vector<double> omega;       // grad-h term, eq. 2.54
  std::vector<double> eps;         // voidage, eq. 2.50
  std::vector<double> eps_drag;    // the same with the drag's kernel (coupling.drag_kernel_scale)
  std::vector<double> d_sauter;    // local Sauter mean diameter of the solids (2.80); 0 if none
  std::vector<double> P, cs;       // pressure (2.58) and sound speed (2.59)
  std::vector<double> p_term;      // P / (Omega rho^2), the pressure term of (2.55)
  std::vector<double> thx, thy, thz;  // pressure + viscous acceleration theta, eq. 2.70
  std::vector<double> ax, ay, az;     // total acceleration used by the integrator
  std::vector<double> dt_limit;       // CFL time-step limit per particle, eq. 3.5
  std::vector<double>
      drag_rate;  // K_a, the reaction's relaxation rate (coupling/drag_exchange.hpp)
  std::vector<double> diffusion_psi, diffusion_volume;  // sph/density_diffusion.hpp (if on)
  std::vector<double> diffusion_gx, diffusion_gy, diffusion_gz;  // grad psi, renormalised

  std::size_t n_owned = 0;
  std::size_t size() const { return x.size(); }

  // The field registry: every per-particle array with its name and role
  // (domain/field_info.hpp), for checkpoints, halos, resizing and reordering.
  static constexpr int kFieldCount = 33;
  template <class F>
  void for_each_field(F&& f) {
    visit_fields(*this, f);
  }
  template <class F>
  void for_each_field(F&& f) const {
    visit_fields(*this, f);
  }
  void resize(std::size_t n) {
    for_each_field([n](const FieldInfo&, auto& v) { v.resize(n); });
  }

 private:
  template <class Self, class F>
  static void visit_fields(Self& p, F& f) {
    constexpr unsigned kCarried = kState | kHaloOnBuild;  // positions, velocities, density
    f(FieldInfo{"kind", kState | kConstant | kHaloOnBuild}, p.kind);
    f(FieldInfo{"id", kState | kConstant | kHaloOnBuild}, p.id);
    f(FieldInfo{"x", kCarried | kPosition}, p.x);
    f(FieldInfo{"y", kCarried | kPosition}, p.y);
    f(FieldInfo{"z", kCarried | kPosition}, p.z);
    f(FieldInfo{"vx", kCarried}, p.vx);
    f(FieldInfo{"vy", kCarried}, p.vy);
    f(FieldInfo{"vz", kCarried}, p.vz);
    f(FieldInfo{"rho", kCarried}, p.rho);
    f(FieldInfo{"mass", kState | kConstant | kHaloOnBuild}, p.mass);
    f(FieldInfo{"h", kHaloOnBuild}, p.h);
    f(FieldInfo{"inv_h", kHaloOnBuild}, p.inv_h);
    f(FieldInfo{"drho", kState}, p.drho);  // the predictor's rate
    f(FieldInfo{"omega", kHaloAfterPass}, p.omega);
    f(FieldInfo{"eps", kHaloAfterPass}, p.eps);
    f(FieldInfo{"eps_drag", kScratch}, p.eps_drag);
    f(FieldInfo{"d_sauter", kScratch}, p.d_sauter);
    f(FieldInfo{"P", kHaloAfterPass}, p.P);
    f(FieldInfo{"cs", kHaloAfterPass}, p.cs);
    f(FieldInfo{"p_term", kHaloAfterPass}, p.p_term);
    f(FieldInfo{"thx", kHaloAfterPass}, p.thx);
    f(FieldInfo{"thy", kHaloAfterPass}, p.thy);
    f(FieldInfo{"thz", kHaloAfterPass}, p.thz);
    f(FieldInfo{"ax", kState}, p.ax);  // the predictor's acceleration
    f(FieldInfo{"ay", kState}, p.ay);
    f(FieldInfo{"az", kState}, p.az);
    f(FieldInfo{"dt_limit", kScratch}, p.dt_limit);
    f(FieldInfo{"drag_rate", kScratch}, p.drag_rate);
    f(FieldInfo{"diffusion_psi", kHaloAfterPass}, p.diffusion_psi);
    f(FieldInfo{"diffusion_volume", kHaloAfterPass}, p.diffusion_volume);
    f(FieldInfo{"diffusion_gx", kHaloAfterPass}, p.diffusion_gx);
    f(FieldInfo{"diffusion_gy", kHaloAfterPass}, p.diffusion_gy);
    f(FieldInfo{"diffusion_gz", kHaloAfterPass}, p.diffusion_gz);
  }
};

// Every member is a field of the registry (a member added without an entry fails here).
static_assert(sizeof(FluidParticles) ==
                  FluidParticles::kFieldCount * sizeof(std::vector<double>) + sizeof(std::size_t),
              "FluidParticles: list every per-particle array in visit_fields");

}  // namespace sphdem
