#pragma once
// Contact history: the state a contact carries from step to step (the tangential spring
// xi and the rolling spring torque), keyed by the pair of sphere ids, apart from the
// neighbour list.
//
// Two representations:
//  - keyed(): the store, one Record per (id, partner id) in contact, sorted by
//    (id, partner). Nothing in it refers to array positions, so it survives the
//    re-sorting of the sphere arrays, a neighbour-list rebuild and (later) migration
//    of a sphere to another rank (its records go with its id) and a checkpoint.
//  - pair / wall: a working copy aligned with the current ContactNeighbourList, used by
//    the contact pass: pair[k] for list entry k, wall[i] for owned sphere i and the
//    bottom wall. No search in the hot loop.
// save() moves the working copy into the store (before the list or the arrays change),
// load() fills the working copy of a new list from it.
//
// Thread safety with the full neighbour list: each owned sphere writes only its own
// entries (pair[k] for its k, wall[i]), so a pair has two copies, one on each side.
// Both sides evaluate the pair in one canonical orientation (from the sphere with the
// lower id to the other, contact_forces.cpp) from bit-identical inputs, and store the
// state in that orientation: the two copies are equal bit for bit, which is the state
// of each side exactly antisymmetric, and the forces are negatives bit for bit.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "dem/dem_particles.hpp"

namespace sphdem {

struct ContactNeighbourList;

// State of one contact in its canonical orientation (zero = no history).
struct ContactState {
  double xi[3] = {0, 0, 0};  // elastic tangential displacement (m)
  double mr[3] = {0, 0, 0};  // rolling spring torque on the lower-id sphere (N m)
  bool active() const {
    return xi[0] != 0.0 || xi[1] != 0.0 || xi[2] != 0.0 || mr[0] != 0.0 || mr[1] != 0.0 ||
           mr[2] != 0.0;
  }
};

class ContactHistory {
 public:
  // Partner key of the flat bottom wall (sphere ids are >= 0).
  static constexpr std::int64_t kBottomWall = -1;

  struct Record {
    std::int64_t id, partner;
    ContactState state;
  };

  // Working copy, aligned with the current list.
  std::vector<ContactState> pair, wall;

  // Working copy -> store, keeping only contacts with a non-zero state. Needs the list
  // and the ids (owned and halo) the working copy was built with. A no-op when the store
  // is already current (nothing loaded since the last save).
  void save(const DemParticles& s, const ContactNeighbourList& list);
  // Store -> working copy for a newly built list (halo ids filled); empties the store.
  // Records whose partner is not in the new list are dropped (no longer in contact).
  void load(const DemParticles& s, const ContactNeighbourList& list);
  bool loaded() const { return loaded_; }
  // Throws std::logic_error unless the working copy is aligned with `list` over n_owned
  // spheres (a contact pass with history needs it).
  void require_aligned(const ContactNeighbourList& list, std::size_t n_owned) const;

  // The store; current after save(), empty after load().
  const std::vector<Record>& keyed() const { return keyed_; }
  // The id-keyed records whichever copy is current (what a checkpoint writes): the
  // store, or the working copy read through the list it is aligned with. Sorted.
  std::vector<Record> records(const DemParticles& s, const ContactNeighbourList& list) const;
  // Replaces the store (checkpoint restart, tests); sorts it.
  void set_keyed(std::vector<Record> records);
  // Looks a contact up in the store (nullptr if it has no history).
  const ContactState* find(std::int64_t id, std::int64_t partner) const;

 private:
  std::vector<Record> keyed_;
  bool loaded_ = false;
};

}  // namespace sphdem
