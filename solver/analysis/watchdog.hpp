#pragma once
// The run's watchdog: after every step, checks the state for non-finite values,
// particles that left the domain, overlaps past a bound, density deviations past the
// weakly compressible limit, and the voidage floor or the Omega clamp biting on more
// than a small share of the fluid. The causes it names for the fluid: a sound speed too
// low for the scene, a CFL number past the tested range, the coupling where the fluid
// sits among packed spheres (the interpolated pressure coupling over a bed, the Darcy
// pressure of a dense suspension that c0's rule does not count), a flow past u_m, else
// an unstable SPH step. The first breach is an alarm that names the particle
// (id, species, position), the quantity, its value and bound, the likely cause and the
// key to change (run/runner.cpp stops the run and dumps the neighbourhood).
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>

#include "scene/scene.hpp"

namespace sphdem {

class Simulation;

struct WatchdogAlarm {
  std::string quantity;   // what broke its bound
  bool sphere = false;    // the particle is a sphere (else an SPH particle)
  std::size_t index = 0;  // in the owned arrays
  std::int64_t id = -1;
  std::string kind;  // species name, or "fluid" / "wall"
  double x = 0, y = 0, z = 0;
  double value = 0, limit = 0;
  std::string cause;  // the likely cause and the key to change
};

// A run stopped by its watchdog (the message: describe_alarm, the dump, the checkpoint).
struct WatchdogError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The worst values of a check, for the warnings (analysis/watchdog_warnings.hpp).
struct WatchdogReading {
  double density_error = 0;  // the largest |rho/(eps rho0) - 1| of a fluid particle
  double overlap = 0;        // the largest overlap / d of a sphere
};

// The first breach of the limits in the current state (nullopt: all within); the worst
// values into `reading` when given.
std::optional<WatchdogAlarm> watchdog_check(const Simulation& sim, const WatchdogSpec& limits,
                                            WatchdogReading* reading = nullptr);

// One paragraph for the terminal: step, time, the particle, the quantity, the cause.
std::string describe_alarm(const WatchdogAlarm& alarm, long step, double time);

}  // namespace sphdem
