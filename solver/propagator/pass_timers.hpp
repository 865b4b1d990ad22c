#pragma once
// Wall-clock time spent in each pass of the propagator (printed at the end of a run).
#include <array>
#include <chrono>

namespace sphdem {

struct PassTimers {
  enum Pass {
    kIntegrate,
    kDem,
    kNeighbours,
    kVoidage,
    kDensity,
    kMomentum,
    kInterp,
    kReaction,
    kOther
  };
  static constexpr int kCount = 9;
  static constexpr const char* kNames[kCount] = {"integrate_fluid", "dem_substeps", "neighbours",
                                                 "voidage",         "density_rate", "momentum",
                                                 "interpolation",   "reaction",     "other"};
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
