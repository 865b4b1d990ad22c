#include "analysis/watchdog_warnings.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "scene/contact_stiffness_rule.hpp"
#include "scene/sound_speed_rule.hpp"

namespace sphdem {

namespace {

// The spring's expected largest overlap / d: at impact (k^-1/2) or under the sediment's
// weight (k^-1), as `check` reckons it (scene/scene_limits.cpp); infinity where no
// sphere moves against another (no species, no spring, every group rigid).
double spring_expected_overlap(const Scene& sc) {
  const bool all_rigid = std::all_of(sc.particles.begin(), sc.particles.end(),
                                     [](const ParticleGroupSpec& g) { return g.rigid; });
  if (sc.species.empty() || !(sc.contact.normal.k > 0.0) || all_rigid) return HUGE_VAL;
  return expected_overlaps(sc).worst();
}

}  // namespace

WatchdogWarnings::WatchdogWarnings(const Scene& sc)
    : expected_density_(sc.fluid.enabled ? sound_speed_report(sc).expected_density_error()
                                         : HUGE_VAL),
      expected_overlap_(spring_expected_overlap(sc)),
      density_alarm_(sc.watchdog.density_error),
      overlap_alarm_(sc.watchdog.overlap),
      sound_speed_advice_(sc.fluid.enabled ? twice_the_sound_speed(sc) : std::string()) {}

std::vector<std::string> WatchdogWarnings::observe(const WatchdogStepTally& t, long step,
                                                   double time) {
  std::vector<std::string> out;
  const std::string when = fmt::format("at step {} (t = {:.6g} s)", step, time);
  if (t.density_past_expected && !density_warned_) {
    density_warned_ = true;
    out.push_back(fmt::format(
        "{}: the largest density error passed {:.2g} %, {} times the {:.2g} % that c0 leads to "
        "expect (the alarm is at {:.2g} %): the flow presses the fluid harder than the sound "
        "speed rule counts (a dense bed's Darcy pressure, a fast flow); log.csv "
        "max_density_error follows it; if it keeps growing, {}",
        when, 100 * density_warning(), kDensityWarningMargin, 100 * expected_density_,
        100 * density_alarm_, sound_speed_advice_));
  }
  if (t.overlap_past_expected && !overlap_warned_) {
    overlap_warned_ = true;
    out.push_back(fmt::format(
        "{}: the largest overlap passed the spring's expected {:.3g} d (the alarm is at {:.3g} "
        "d): an impact faster or a load heavier than contact.stiffness was chosen for; "
        "log.csv max_overlap_over_d follows it",
        when, expected_overlap_, overlap_alarm_));
  }
  floor_run_ = t.floor_hits > 0 ? floor_run_ + 1 : 0;
  clamp_run_ = t.clamp_hits > 0 ? clamp_run_ + 1 : 0;
  if (floor_run_ >= kPersistentSafeguardSteps && !floor_warned_) {
    floor_warned_ = true;
    out.push_back(fmt::format(
        "{}: the voidage floor has held fluid particles in each of the last {} steps ({} now): "
        "the model is replaced there for good, not for a transient; a finer fluid.spacing, or "
        "a lower coupling.voidage_floor",
        when, kPersistentSafeguardSteps, t.floor_hits));
  }
  if (clamp_run_ >= kPersistentSafeguardSteps && !clamp_warned_) {
    clamp_warned_ = true;
    out.push_back(fmt::format(
        "{}: the Omega clamp has bounded fluid particles in each of the last {} steps ({} now): "
        "h varies faster than the kernel resolves there for good, not for a transient",
        when, kPersistentSafeguardSteps, t.clamp_hits));
  }
  return out;
}

}  // namespace sphdem
