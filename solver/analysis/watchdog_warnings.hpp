#pragma once
// The watchdog's warnings: what a run reaches before its alarms (analysis/watchdog.hpp)
// stop it. Each is printed once a run:
//  - the largest density error past the expected one of c0 (scene/sound_speed_rule.hpp)
//    by kDensityWarningMargin (a column's base sits at the expected value itself, and a
//    run's largest error at 0.98-1.3 times it: VALIDATION.md), the alarm at max(1 %,
//    twice the expected) (WatchdogSpec);
//  - the largest overlap past the spring's expected one (scene/contact_stiffness_rule.hpp:
//    contact.max_overlap with stiffness auto), the alarm at 0.1 d;
//  - a safeguard (the voidage floor, the Omega clamp) that bites in every one of
//    kPersistentSafeguardSteps steps in a row: under the alarm's share, but the model is
//    replaced there for good, not for a transient.
// The runner feeds it the step's flags and counts, summed over the ranks.
#include <cstdint>
#include <string>
#include <vector>

#include "scene/scene.hpp"

namespace sphdem {

inline constexpr long kPersistentSafeguardSteps = 100;
inline constexpr double kDensityWarningMargin = 1.5;

// One step, over every rank: whether any rank passed an expected value, and the
// safeguards' hits (particles).
struct WatchdogStepTally {
  bool density_past_expected = false;
  bool overlap_past_expected = false;
  std::uint64_t floor_hits = 0, clamp_hits = 0;
};

class WatchdogWarnings {
 public:
  explicit WatchdogWarnings(const Scene& sc);
  double expected_density_error() const { return expected_density_; }
  // The density error and overlap past which a step counts for the warnings.
  double density_warning() const { return kDensityWarningMargin * expected_density_; }
  double expected_overlap() const { return expected_overlap_; }  // infinity: no contacts
  // The warnings this step raises (none after each kind's first).
  std::vector<std::string> observe(const WatchdogStepTally& t, long step, double time);

 private:
  double expected_density_ = 0, expected_overlap_ = 0;
  double density_alarm_ = 0, overlap_alarm_ = 0;
  std::string sound_speed_advice_;      // twice c0, in the key the user sets
  long floor_run_ = 0, clamp_run_ = 0;  // steps in a row with a hit
  bool density_warned_ = false, overlap_warned_ = false;
  bool floor_warned_ = false, clamp_warned_ = false;
};

}  // namespace sphdem
