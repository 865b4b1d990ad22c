#pragma once
// How often the run's safeguards bit, over every step (log.csv samples only its logged
// steps): the voidage floor (fluid particles whose eps was raised to it, 2.50) and the
// Omega clamp (terms of the Omega correction bounded). Both replace the model where they
// act, so a run reports them at its end and the validation report reads that line.
#include <fmt/format.h>

#include <algorithm>
#include <cstddef>
#include <string>

namespace sphdem {

struct SafeguardTally {
  long steps = 0;
  long floor_steps = 0, clamp_steps = 0;             // steps in which any particle was hit
  std::size_t floor_largest = 0, clamp_largest = 0;  // most particles hit in one step
  double floor_particle_steps = 0, clamp_particle_steps = 0;

  void add(std::size_t voidage_clamped, std::size_t omega_bounded) {
    ++steps;
    floor_steps += voidage_clamped > 0;
    clamp_steps += omega_bounded > 0;
    floor_largest = std::max(floor_largest, voidage_clamped);
    clamp_largest = std::max(clamp_largest, omega_bounded);
    floor_particle_steps += static_cast<double>(voidage_clamped);
    clamp_particle_steps += static_cast<double>(omega_bounded);
  }
  bool hit() const { return floor_steps > 0 || clamp_steps > 0; }

  // One line, parsed by validation/report.py (keep the words and their order).
  std::string describe(std::size_t fluid_particles) const {
    const double per = std::max<double>(1.0, static_cast<double>(steps) * fluid_particles);
    return fmt::format(
        "safeguards over {} steps: voidage floor hit in {} steps (largest {} particles, "
        "{:.3g} % of particle-steps), Omega clamp hit in {} steps (largest {} particles, "
        "{:.3g} % of particle-steps)",
        steps, floor_steps, floor_largest, 100.0 * floor_particle_steps / per, clamp_steps,
        clamp_largest, 100.0 * clamp_particle_steps / per);
  }
};

}  // namespace sphdem
