#pragma once
// The imposed flow of a column periodic in z (flow.*): a uniform body force, the mean
// pressure gradient G = -<grad p> (Pa/m), acts on the fluid (G / rho_f a unit mass: its
// volume is its mass over rho_f, not the SPH density's, so that the force on the fluid does
// not follow the density's acoustic noise) and on every sphere (G V_j), as the mean
// pressure gradient of the locally averaged equations acts on both phases (physics.md
// 2.68). The pressure itself is
// periodic, so the column's pressure drop is G's: (G_z + rho_f g_z) L_z is the frictional
// drop, the mean gradient less the fluid's own weight.
//
// G is set so that the fluid's superficial velocity U = sum_a m_a u_a / (rho_f V_box)
// follows the schedule U(t) (`flow.times`, `flow.superficial_velocity`, along z; x and y
// held at 0): after each step's corrector the shortfall is made up at once by a uniform
// velocity increment du of the fluid, whose impulse rho_f du per unit volume of the box
// also goes to the spheres and joins G (G += rho_f du / dt), as OpenFOAM's
// meanVelocityForce does. Only external forces change U (pair forces are
// antisymmetric), so du is what the drag and gravity did to the mean flow in one step, and G
// settles where they balance.
#include <array>
#include <vector>

#include "domain/box.hpp"

namespace sphdem {

struct FlowSpec;

// U(t): linear between the schedule's points, held outside them.
class FlowSchedule {
 public:
  FlowSchedule() = default;
  FlowSchedule(std::vector<double> times, std::vector<double> velocity);
  double at(double t) const;

 private:
  std::vector<double> t_{0.0}, u_{0.0};
};

class FlowController {
 public:
  FlowController() = default;  // off: no body force
  FlowController(const FlowSpec& spec, const Box& box, double rho_f);

  bool on() const { return on_; }
  const std::array<double, 3>& pressure_gradient() const { return G_; }  // G (Pa/m)
  // G / rho_f, the fluid's acceleration (0 when off: adding it leaves the bits alone)
  std::array<double, 3> fluid_acceleration() const {
    if (!on_) return {0.0, 0.0, 0.0};
    return {G_[0] / rho_f_, G_[1] / rho_f_, G_[2] / rho_f_};
  }
  void set_pressure_gradient(const std::array<double, 3>& G) { G_ = G; }  // (a checkpoint's)
  double target(double t) const { return schedule_.at(t); }
  // The fluid's superficial velocity along z before the last correction, and after it.
  double measured_velocity() const { return measured_; }
  double superficial_velocity() const { return corrected_; }
  // The frictional pressure drop over the column, (G_z + rho_f g_z) L_z (Pa).
  double pressure_drop(double gravity_z) const;

  // After a step of dt that ends at t: the fluid's momentum and mass (summed over ranks)
  // give U; returns the uniform increment du every fluid particle takes (rho_f du the
  // impulse per unit volume the spheres take too) and adds rho_f du / dt to G.
  std::array<double, 3> correct(const std::array<double, 3>& momentum, double mass, double t,
                                double dt);

 private:
  bool on_ = false;
  FlowSchedule schedule_;
  double rho_f_ = 0.0, volume_ = 0.0, length_z_ = 0.0;
  std::array<double, 3> G_{0.0, 0.0, 0.0};
  double measured_ = 0.0, corrected_ = 0.0;
};

}  // namespace sphdem
