#include "propagator/flow_controller.hpp"

#include <algorithm>
#include <stdexcept>

#include "scene/scene.hpp"

namespace sphdem {

FlowSchedule::FlowSchedule(std::vector<double> times, std::vector<double> velocity)
    : t_(std::move(times)), u_(std::move(velocity)) {
  if (t_.empty() || t_.size() != u_.size())
    throw std::invalid_argument("a flow schedule needs one velocity per time, at least one");
  for (std::size_t k = 1; k < t_.size(); ++k)
    if (!(t_[k] > t_[k - 1])) throw std::invalid_argument("a flow schedule's times must increase");
}

double FlowSchedule::at(double t) const {
  if (t <= t_.front()) return u_.front();
  if (t >= t_.back()) return u_.back();
  const std::size_t k = static_cast<std::size_t>(std::upper_bound(t_.begin(), t_.end(), t) -
                                                 t_.begin());  // t_[k-1] <= t < t_[k]
  const double w = (t - t_[k - 1]) / (t_[k] - t_[k - 1]);
  return u_[k - 1] + w * (u_[k] - u_[k - 1]);
}

FlowController::FlowController(const FlowSpec& spec, const Box& box, double rho_f)
    : on_(box.periodic[2]),
      schedule_(spec.times, spec.superficial_velocity),
      rho_f_(rho_f),
      volume_(box.length(0) * box.length(1) * box.length(2)),
      length_z_(box.length(2)) {}

double FlowController::pressure_drop(double gravity_z) const {
  return (G_[2] + rho_f_ * gravity_z) * length_z_;
}

std::array<double, 3> FlowController::correct(const std::array<double, 3>& momentum, double mass,
                                              double t, double dt) {
  std::array<double, 3> du{0.0, 0.0, 0.0};
  if (!on_ || !(mass > 0.0)) return du;
  const std::array<double, 3> target{0.0, 0.0, schedule_.at(t)};
  const double to_u = 1.0 / (rho_f_ * volume_);  // U = momentum / (rho_f V_box)
  measured_ = momentum[2] * to_u;
  for (int k = 0; k < 3; ++k) {
    // M du = rho_f V_box (U_target - U): the fluid's mean momentum on the target at once
    du[k] = (target[k] - momentum[k] * to_u) * rho_f_ * volume_ / mass;
    G_[k] += rho_f_ * du[k] / dt;
  }
  corrected_ = target[2];
  return du;
}

}  // namespace sphdem
