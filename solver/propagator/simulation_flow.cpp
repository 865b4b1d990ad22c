// The imposed flow of a column periodic in z (propagator/flow_controller.hpp): G's start
// at the box's static balance and the controller's correction after each corrector.
#include <array>
#include <vector>

#include "propagator/simulation.hpp"

namespace sphdem {

// An imposed flow starts with G at the static balance of the box, G V_box = -(M_f + M_s) g
// over the fluid and the spheres that can move, so that the first step does not drop the
// column by g dt (the controller would give it back at once, the spheres' share a step late).
void Simulation::start_balanced() {
  std::vector<double> m{0.0};
  for (std::size_t a = 0; a < fluid_.n_owned; ++a)
    if (fluid_.kind[a] == kFluid) m[0] += fluid_.mass[a];
  const DemParticles& s = dem_.spheres();
  const std::vector<char>& fixed = params_.dem.fixed_groups;
  for (std::size_t j = 0; j < s.n_owned; ++j) {
    const int g = s.rigid_group[j];
    if (g < 0 || g >= static_cast<int>(fixed.size()) || !fixed[g]) m[0] += s.mass[j];
  }
  comm_.sum(m);
  const Box& box = params_.box;
  const double volume = box.length(0) * box.length(1) * box.length(2);
  std::array<double, 3> G{};
  for (int k = 0; k < 3; ++k) G[k] = -params_.gravity[k] * m[0] / volume;
  flow_.set_pressure_gradient(G);
  dem_.set_mean_pressure_gradient(G);
}

// The flow controller's correction at the end of a step's corrector (flow_controller.hpp):
// every fluid particle takes du (and the half step's drift of it), every sphere the same
// pressure-gradient impulse rho_f V_j du, and G the rest of the step.
void Simulation::control_flow(double t, double dt, bool hold_spheres) {
  FluidParticles& f = fluid_;
  const long n = static_cast<long>(f.n_owned);
  std::vector<double> sums{0.0, 0.0, 0.0, 0.0};  // momentum and mass of the fluid
  for (long a = 0; a < n; ++a) {
    if (f.kind[a] != kFluid) continue;
    sums[0] += f.mass[a] * f.vx[a];
    sums[1] += f.mass[a] * f.vy[a];
    sums[2] += f.mass[a] * f.vz[a];
    sums[3] += f.mass[a];
  }
  comm_.sum(sums);
  const std::array<double, 3> du = flow_.correct({sums[0], sums[1], sums[2]}, sums[3], t, dt);
  for (long a = 0; a < n; ++a) {
    if (f.kind[a] != kFluid) continue;
    f.vx[a] += du[0];
    f.vy[a] += du[1];
    f.vz[a] += du[2];
    f.x[a] += 0.5 * dt * du[0];
    f.y[a] += 0.5 * dt * du[1];
    f.z[a] += 0.5 * dt * du[2];
  }
  dem_.set_mean_pressure_gradient(flow_.pressure_gradient());
  if (hold_spheres) return;
  DemParticles& s = dem_.spheres();
  const double rho_f = params_.fluid.eos.rho0;
  flow_impulse_.resize(3 * s.n_owned);
  for (std::size_t j = 0; j < s.n_owned; ++j)
    for (int k = 0; k < 3; ++k) flow_impulse_[3 * j + k] = rho_f * s.volume(j) * du[k];
  dem_.add_impulses(flow_impulse_.data());
}

}  // namespace sphdem
