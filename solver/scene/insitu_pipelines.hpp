#pragma once
// The one table of the in-situ pipelines: each is pipelines/<name>.py, a Catalyst V2
// script that the adaptor loads by this name (catalyst/insitu.cpp). The scene key
// insitu.pipelines takes these names (its default: all of them), pipelines/README.md's
// table is rendered from here, and a test holds the table to the scripts in pipelines/
// (tests/unit/docs_test.cpp).
#include <string>

namespace sphdem {

struct InSituPipeline {
  const char* name;    // pipelines/<name>.py
  const char* reads;   // the channels it reads (catalyst/insitu.hpp)
  const char* writes;  // what it writes under DIR/insitu/, in one line
  bool renders;        // it draws images: it needs a display (catalyst/headless_display.hpp)
};

inline constexpr InSituPipeline kInSituPipelines[] = {
    {"voidage_height", "voidage",
     "`voidage_height.h5`: `time` (nt), `z` (nz, m), `voidage` (nt × nz), the laterally averaged "
     "voidage ε(z) at each analysis; attributes `column_height`, `reference_interface_velocity` "
     "(m/s, NaN if none)",
     false},
    {"interfaces", "voidage",
     "`interfaces.csv`: `time,z_top,z_bottom` (s, m, m), the clear-liquid interface and the top of "
     "the sediment",
     false},
    {"com_tracks", "particles",
     "`com.csv`: `time`, `com_z:S` per species and `com_z:all` (m, mass-weighted), `vz_mean:S` "
     "(m/s), `front_z:S` (m, species S's front)",
     false},
    {"snapshots", "particles, voidage",
     "`snapshots/column_NNNNNN.png` every `insitu.snapshot_every` analyses (NNNNNN = step)", true},
};

// The row of pipeline `name`; nullptr for another name.
inline const InSituPipeline* find_insitu_pipeline(const std::string& name) {
  for (const InSituPipeline& p : kInSituPipelines)
    if (name == p.name) return &p;
  return nullptr;
}

inline constexpr int kInSituPipelineCount = sizeof(kInSituPipelines) / sizeof(kInSituPipelines[0]);

// The names, null-terminated (the choices of insitu.pipelines).
struct InSituPipelineNames {
  const char* names[kInSituPipelineCount + 1];
};
inline constexpr InSituPipelineNames kInSituPipelineNames = [] {
  InSituPipelineNames n{};
  for (int i = 0; i < kInSituPipelineCount; ++i) n.names[i] = kInSituPipelines[i].name;
  n.names[kInSituPipelineCount] = nullptr;
  return n;
}();

}  // namespace sphdem
