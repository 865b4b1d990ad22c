#pragma once
// Drives a whole run for the CLI: case.yaml, start-up, the time loop, log.csv and
// terminal progress. Also the derived numbers printed by `sphdem check`.
#include <functional>
#include <ostream>
#include <string>
#include <vector>

#include "run/safeguard_tally.hpp"
#include "scene/scene.hpp"

namespace sphdem {

class Simulation;

class CheckpointReader;

// Something to do every `interval` of simulated time (from t = 0, release). `call` counts
// its calls from 0 over the whole run, across resumes.
struct PeriodicHook {
  std::string name;
  double interval = 0;
  std::function<void(const Simulation&, long call)> action;
  double seconds = 0;  // wall time spent in it (filled by run_scene)
};

struct RunOptions {
  std::string out_dir = "out";
  std::ostream* progress = nullptr;  // terminal progress lines (nullptr: silent)
  std::vector<PeriodicHook> hooks;   // in-situ analysis, snapshots
  // Continue the run of out_dir from this checkpoint (`sphdem resume`): no start-up;
  // log.csv keeps its rows up to the checkpoint; hooks, log and checkpoint clocks go on
  // where they were.
  const CheckpointReader* resume = nullptr;
  // Polled after every step: non-zero (the number of a signal) asks the run to stop at
  // its next checkpoint, written within 100 steps (run_scene returns).
  std::function<int()> stop_requested;
};

struct RunSummary {
  long steps = 0;
  double step_seconds = 0;          // wall time in Simulation::step
  std::vector<PeriodicHook> hooks;  // with their wall times
  double simulated_time = 0;
  double wall_seconds = 0;
  double fluid_particle_steps_per_second = 0;
  double sphere_particle_steps_per_second = 0;  // sphere sub-steps counted
  SafeguardTally safeguards;                    // every step's floor and clamp counts
  double largest_overlap = 0;                   // / d, over the logged steps
  double largest_density_error = 0;             // |rho/rho0 - 1|, over the logged steps
  int stopped_by = 0;                           // the stop request that ended the run (0: none)
  std::string checkpoint;                       // the last checkpoint written ("" if none)
  int checkpoints_written = 0;
  double checkpoint_seconds = 0;  // wall time spent writing them
};

// Runs a scene, or continues it from options.resume. Throws CheckpointError when a
// checkpoint cannot be written (the previous one stays whole).
RunSummary run_scene(const Scene& scene, RunOptions options);

// Human-readable derived numbers of a scene (particle counts, h/d, t_c, time steps,
// sub-steps, memory estimate). Builds the initial state to measure them and times a step.
// With `presets` (the same scene file loaded at each fidelity), the presets side by side:
// their settings, expected density error and overlap, and wall time estimated from the
// timed step scaled by each preset's fluid particles and acoustic steps.
// ranks > 1: also the scene on that many MPI ranks (run/rank_forecast.hpp).
std::string describe_scene(const Scene& scene, const std::vector<Scene>& presets = {},
                           int ranks = 1);

}  // namespace sphdem
