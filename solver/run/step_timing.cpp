#include "run/step_timing.hpp"

#include <omp.h>
#include <time.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <vector>

#include "analysis/watchdog.hpp"

namespace sphdem {

namespace {

double thread_cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

double wall_seconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

// A step as the run's loop takes it: the step, then the watchdog's look at it.
void run_step(Simulation& sim) {
  sim.step();
  (void)watchdog_check(sim, sim.scene().watchdog);
}

}  // namespace

double idle_thread_share(int threads) {
  // 2 threads take 0.54-0.63 of one thread's CPU step on the ten shipped scenes (median
  // 0.57, bench/RESULTS.md); more threads at the same parallel share (Amdahl, p = 0.86).
  constexpr double kParallel = 0.86;
  return threads <= 1 ? 1.0 : (1.0 - kParallel) + kParallel / threads;
}

StepTiming time_steps(Simulation& sim, int steps) {
  StepTiming t;
  t.threads = omp_get_max_threads();
  // With time.multirate the spheres at rest, out of contact, all take the fluid's step;
  // once they move many are sub-stepped (the two-density suspension: 24 % over its first
  // 0.05 s). Timed with every sphere sub-stepped, as the run's steps are nearer to
  // (bench/RESULTS.md, session 26).
  const bool multirate = sim.multirate();
  sim.set_multirate(false);
  for (int k = 0; k < 3; ++k) run_step(sim);  // lists and scratch grown, memory touched
  // the median: a run's steps are not its quickest ones, and one that rebuilt its lists
  // or met a page fault is not the typical one either
  std::vector<double> wall(steps);
  for (double& w : wall) {
    const double w0 = wall_seconds();
    run_step(sim);
    w = wall_seconds() - w0;
  }
  std::sort(wall.begin(), wall.end());
  t.threads_wall = wall[wall.size() / 2];
  t.step = t.threads_wall;
  if (t.threads == 1) {
    t.one_thread_cpu = t.threads_wall;
    sim.set_multirate(multirate);
    return t;
  }
  omp_set_num_threads(1);  // the run's threads back below
  t.one_thread_cpu = HUGE_VAL;
  for (int k = 0; k < steps; ++k) {
    const double c0 = thread_cpu_seconds();
    run_step(sim);
    t.one_thread_cpu = std::min(t.one_thread_cpu, thread_cpu_seconds() - c0);
  }
  omp_set_num_threads(t.threads);
  sim.set_multirate(multirate);
  settle_step(t);
  return t;
}

void settle_step(StepTiming& t) {
  t.cores_busy = t.threads > 1 && t.threads_wall > t.one_thread_cpu;
  t.step = t.cores_busy ? t.one_thread_cpu * idle_thread_share(t.threads) : t.threads_wall;
}

double process_cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

}  // namespace sphdem
