#pragma once
// The wall time of one SPH step as a run on idle cores takes it, measured by `sphdem check`
// on a few steps of the scene (its lists in place). Another job on the cores lengthens the
// threads' steps out of proportion: a pass ends at a barrier, and the barrier waits for
// whichever thread the other job holds (a 2-thread step read 16 times its idle time beside
// a second 2-thread process). One thread's CPU time is what the other job does not
// lengthen, so the threads' step is checked against it: threads slower than one thread's
// CPU time say the cores were busy, and the step is then taken from the one thread.
#include "propagator/simulation.hpp"

namespace sphdem {

struct StepTiming {
  int threads = 1;            // OpenMP threads of the run
  double threads_wall = 0;    // the median of the steps on those threads, wall s
  double one_thread_cpu = 0;  // the quickest of the steps on one thread, its CPU s
  bool cores_busy = false;    // the threads took longer than one thread's CPU time
  double step = 0;            // the step on idle cores, s
};

// The share of one thread's step time that `threads` threads take on idle cores, from the
// shipped scenes' steps (bench/RESULTS.md, session 25): what a busy machine's estimate
// uses.
double idle_thread_share(int threads);

// The step on idle cores from the two timings (fills cores_busy and step).
void settle_step(StepTiming& t);

// After 3 steps unmeasured, times `steps` steps (each with the watchdog's check, as in a
// run) on the run's threads, then (with more
// than one) `steps` on one; advances sim by all of them.
StepTiming time_steps(Simulation& sim, int steps = 5);

// The CPU time the process has used so far: before a scene is built, what starting the
// program took (its libraries loaded), which a run pays too.
double process_cpu_seconds();

}  // namespace sphdem
