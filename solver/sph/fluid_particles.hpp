#pragma once
// SPH particles, structure of arrays. Indices [0, n_owned) are owned; the rest are
// halo copies. Wall particles (kind == kWall) are owned but never move.
#include <cstddef>
#include <cstdint>
#include <vector>

namespace sphdem {

enum FluidKind : std::uint8_t { kFluid = 0, kWall = 1 };

struct FluidParticles {
  // state that defines the run (checkpointed)
  std::vector<double> x, y, z;     // position (m)
  std::vector<double> vx, vy, vz;  // velocity (m/s)
  std::vector<double> rho;         // superficial density eps*rho_f (kg/m^3)
  std::vector<double> mass;        // constant mass (kg)
  std::vector<std::uint8_t> kind;  // kFluid or kWall
  std::vector<std::int64_t> id;    // global id
  // derived per step
  std::vector<double> h, inv_h;  // smoothing length, eq. 2.65, and 1/h
  std::vector<double> drho;      // density rate, eq. 2.53
  std::vector<double> omega;     // grad-h term, eq. 2.54
  std::vector<double> eps;       // voidage, eq. 2.50
  std::vector<double> eps_drag;  // the same with the drag's kernel (coupling.drag_kernel_scale)
  std::vector<double> d_sauter;  // local Sauter mean diameter of the solids (2.80); 0 if none
  std::vector<double> P, cs;     // pressure (2.58) and sound speed (2.59)
  std::vector<double> p_term;    // P / (Omega rho^2), the pressure term of (2.55)
  std::vector<double> thx, thy, thz;  // pressure + viscous acceleration theta, eq. 2.70
  std::vector<double> ax, ay, az;     // total acceleration used by the integrator
  std::vector<double> dt_limit;       // CFL time-step limit per particle, eq. 3.5
  std::vector<double> diffusion_psi, diffusion_volume;  // sph/density_diffusion.hpp (if on)

  std::size_t n_owned = 0;
  std::size_t size() const { return x.size(); }

  // Every per-particle array with its name (output, checkpoint, resizing, reordering).
  template <class F>
  void for_each_field(F&& f) {
    f("kind", kind);
    f("id", id);
    f("x", x);
    f("y", y);
    f("z", z);
    f("vx", vx);
    f("vy", vy);
    f("vz", vz);
    f("rho", rho);
    f("mass", mass);
    f("h", h);
    f("inv_h", inv_h);
    f("drho", drho);
    f("omega", omega);
    f("eps", eps);
    f("eps_drag", eps_drag);
    f("d_sauter", d_sauter);
    f("P", P);
    f("cs", cs);
    f("p_term", p_term);
    f("thx", thx);
    f("thy", thy);
    f("thz", thz);
    f("ax", ax);
    f("ay", ay);
    f("az", az);
    f("dt_limit", dt_limit);
    f("diffusion_psi", diffusion_psi);
    f("diffusion_volume", diffusion_volume);
  }
  void resize(std::size_t n) {
    for_each_field([n](const char*, auto& v) { v.resize(n); });
  }
};

}  // namespace sphdem
