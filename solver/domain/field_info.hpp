#pragma once
// The field registry's tags: what each per-particle array of FluidParticles and
// DemParticles is from one step to the next. Checkpoints write the state fields, halos
// fill the halo fields, resizing and reordering take every field; a unit test
// (field_registry_test) holds each container's list to its members and its halo tags
// to the halo copies after a step.
namespace sphdem {

enum FieldFlags : unsigned {
  kScratch = 0,              // recomputed every step before it is read
  kState = 1u << 0,          // carried from one step to the next: checkpointed
  kConstant = 1u << 1,       // set at the start and never changed (a state field too)
  kHaloOnBuild = 1u << 2,    // halo copies filled when the halo is built (and refreshed)
  kHaloAfterPass = 1u << 3,  // halo copies filled after the pass that computes it
  kPosition = 1u << 4,       // x, y, z: halo copies are shifted images (fill_positions)
};

struct FieldInfo {
  const char* name;
  unsigned flags;
  bool state() const { return (flags & kState) != 0; }
  bool constant() const { return (flags & kConstant) != 0; }
  bool halo() const { return (flags & (kHaloOnBuild | kHaloAfterPass)) != 0; }
  // Filled with the halo's build: every on-build field but the positions.
  bool filled_on_build() const { return (flags & (kHaloOnBuild | kPosition)) == kHaloOnBuild; }
  // Refreshed between builds: the on-build fields that change.
  bool refreshed() const { return filled_on_build() && !constant(); }
};

}  // namespace sphdem
