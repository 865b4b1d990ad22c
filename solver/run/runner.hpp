#pragma once
// Drives a whole run for the CLI: case.yaml, start-up, the time loop, log.csv and
// terminal progress. Also the derived numbers printed by `sphdem check`.
#include <functional>
#include <ostream>
#include <string>

#include "run/scene.hpp"

namespace sphdem {

class Simulation;

struct RunOptions {
  std::string out_dir = "out";
  std::ostream* progress = nullptr;  // terminal progress lines (nullptr: silent)
  // Called after every log row (in-situ analysis hooks in here later).
  std::function<void(const Simulation&)> on_log;
};

struct RunSummary {
  long steps = 0;
  double simulated_time = 0;
  double wall_seconds = 0;
  double fluid_particle_steps_per_second = 0;
  double sphere_particle_steps_per_second = 0;  // sphere sub-steps counted
};

RunSummary run_scene(const Scene& scene, const RunOptions& options);

// Human-readable derived numbers of a scene (particle counts, h/d, t_c, time steps,
// sub-steps, memory estimate). Builds the initial state to measure them.
std::string describe_scene(const Scene& scene);

}  // namespace sphdem
