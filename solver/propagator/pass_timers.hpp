#pragma once
// Wall-clock time spent in each pass of the propagator (printed at the end of a run).
#include <array>
#include <chrono>

namespace sphdem {

// The one table of the passes: PASS(enumerator, name as printed). Adding a pass is a row
// here and a lap() where it ends (Simulation::advance).
#define SPHDEM_PASSES(PASS)           \
  PASS(kIntegrate, "integrate_fluid") \
  PASS(kDem, "dem_substeps")          \
  PASS(kNeighbours, "neighbours")     \
  PASS(kVoidage, "voidage")           \
  PASS(kDensity, "density_rate")      \
  PASS(kMomentum, "momentum")         \
  PASS(kInterp, "interpolation")      \
  PASS(kReaction, "reaction")         \
  PASS(kOther, "other")

struct PassTimers {
#define SPHDEM_PASS_ENUMERATOR(e, name) e,
  enum Pass { SPHDEM_PASSES(SPHDEM_PASS_ENUMERATOR) kCount };
#undef SPHDEM_PASS_ENUMERATOR
#define SPHDEM_PASS_NAME(e, name) name,
  static constexpr const char* kNames[kCount] = {SPHDEM_PASSES(SPHDEM_PASS_NAME)};
#undef SPHDEM_PASS_NAME
  std::array<double, kCount> seconds{};
};

// Adds the time since `start` to one pass timer, and restarts it.
struct Lap {
  using Clock = std::chrono::steady_clock;
  PassTimers& t;
  Clock::time_point start = Clock::now();
  void operator()(PassTimers::Pass pass) {
    const auto now = Clock::now();
    t.seconds[pass] += std::chrono::duration<double>(now - start).count();
    start = now;
  }
  void restart() { start = Clock::now(); }
};

}  // namespace sphdem
