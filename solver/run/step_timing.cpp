#include "run/step_timing.hpp"

#include <omp.h>
#include <time.h>

#include <algorithm>
#include <chrono>
#include <cmath>

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

}  // namespace

double idle_thread_share(int threads) {
  // 2 threads take 0.6 of one thread's step on the shipped scenes; more threads are
  // taken at the same parallel share (Amdahl: p = 0.8).
  constexpr double kParallel = 0.8;
  return threads <= 1 ? 1.0 : (1.0 - kParallel) + kParallel / threads;
}

StepTiming time_steps(Simulation& sim, int steps) {
  StepTiming t;
  t.threads = omp_get_max_threads();
  t.threads_wall = HUGE_VAL;
  for (int k = 0; k < steps; ++k) {
    const double w0 = wall_seconds();
    sim.step();
    t.threads_wall = std::min(t.threads_wall, wall_seconds() - w0);
  }
  t.step = t.threads_wall;
  if (t.threads == 1) {
    t.one_thread_cpu = t.threads_wall;
    return t;
  }
  omp_set_num_threads(1);  // the run's threads back below
  t.one_thread_cpu = HUGE_VAL;
  for (int k = 0; k < steps; ++k) {
    const double c0 = thread_cpu_seconds();
    sim.step();
    t.one_thread_cpu = std::min(t.one_thread_cpu, thread_cpu_seconds() - c0);
  }
  omp_set_num_threads(t.threads);
  t.cores_busy = t.threads_wall > t.one_thread_cpu;
  if (t.cores_busy) t.step = t.one_thread_cpu * idle_thread_share(t.threads);
  return t;
}

}  // namespace sphdem
