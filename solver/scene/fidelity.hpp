#pragma once
// Fidelity presets (issue 15): `fidelity: fast | balanced | accurate` in a scene (or
// `sphdem run --fidelity ...`) gives the keys below their values where the scene leaves
// them unset; a key the scene sets wins. balanced is the defaults. bench/TRADEOFF.md
// measures what each costs in accuracy and in time; `sphdem check` prints the three side
// by side for the scene at hand.
#include <string>

#include "scene/scene_keys.hpp"

namespace sphdem {

struct FidelityPreset {
  const char* name;
  double resolution;             // fluid.resolution: layers per fluid.spacing (dx = spacing / it)
  double sound_speed_factor;     // fluid.sound_speed_factor: c0 = f max(u_m, sqrt(2 g H))
  double cfl;                    // time.cfl (3.5)
  double dem_steps_per_contact;  // time.dem_steps_per_contact (3.7)
  double max_overlap;            // contact.max_overlap, for contact.stiffness: auto
};

// Expected density error 1/(2 f^2) from the column's weight (bench/TRADEOFF.md). accurate
// keeps the scene's dx: a finer dx brings h towards d, and a lone sphere then sees more
// of its own volume in the voidage its drag reads (bench/TRADEOFF.md). balanced is the
// keys' own defaults (scene/scene_keys.hpp); the names are the choices of `fidelity`.
inline constexpr FidelityPreset kFidelityPresets[] = {
    {"fast", 0.8, 8.0, 0.3, 10, 0.02},
    {"balanced", scene_default("fluid.resolution"), scene_default("fluid.sound_speed_factor"),
     scene_default("time.cfl"), scene_default("time.dem_steps_per_contact"),
     scene_default("contact.max_overlap")},
    {"accurate", 1.0, 20.0, 0.2, 40, 0.005},
};

constexpr bool preset_names_are_the_choices() {
  const char* const* choice = key_choices::kFidelity;
  for (const FidelityPreset& p : kFidelityPresets) {
    if (!*choice || std::string_view(p.name) != *choice) return false;
    ++choice;
  }
  return *choice == nullptr;
}
static_assert(preset_names_are_the_choices(), "kFidelityPresets and the choices of 'fidelity'");

inline const FidelityPreset* find_fidelity_preset(const std::string& name) {
  for (const FidelityPreset& p : kFidelityPresets)
    if (name == p.name) return &p;
  return nullptr;
}

}  // namespace sphdem
