#pragma once
// The spheres' neighbourhood: their halo (periodic images, and the copies an MPI rank will
// receive), the cells, the contact Verlet list and the contact history aligned with it,
// and the Verlet skin's bookkeeping (rebuilt once the spheres' displacement since the
// build has used half the skin). The contact passes read it; the sub-step schemes report
// their steps to it. What a rank extends: its halo sources.
#include <cstdint>
#include <vector>

#include "dem/contact_history.hpp"
#include "dem/contact_list.hpp"
#include "dem/dem_particles.hpp"
#include "domain/box.hpp"
#include "domain/cell_list.hpp"
#include "domain/decomposition.hpp"
#include "domain/halo.hpp"
#include "io/checkpoint_file.hpp"

namespace sphdem {

// How far the fluid side reaches into the sphere halo: `needed` and `wanted` (with the
// fluid's Verlet skin) from the fluid particles, `sphere_kernel` a kernel centred on the
// spheres (double smoothing's big spheres, 3.9), which the contact skin extends.
struct FluidReach {
  double needed = 0, wanted = 0, sphere_kernel = 0;
};

class SphereLists {
 public:
  // skin_fraction: the Verlet skin over the largest diameter; history: the contact model
  // carries state (tangential or rolling springs) that follows the list.
  SphereLists(const Box& box, double skin_fraction, bool history,
              const RankComm& comm = RankComm(MPI_COMM_NULL))
      : box_(box), skin_fraction_(skin_fraction), history_on_(history), halo_(comm) {}

  // Several ranks: the decomposition the fluid shares; each rebuild migrates the owned
  // spheres to the ranks that own their cells, with their contact history.
  void set_decomposition(const Decomposition* d) { decomposition_ = d; }
  const Halo& halo() const { return halo_; }
  const ContactNeighbourList& contacts() const { return contacts_; }
  ContactHistory& history() { return history_; }
  const ContactHistory& history() const { return history_; }
  std::vector<ContactHistory::Record> records(const DemParticles& s) const {
    return history_.records(s, contacts_);
  }
  double skin() const { return contacts_.skin; }
  // Sphere halo and contact list builds so far: a list into the halo is stale once it changes.
  long builds() const { return builds_; }
  void set_fluid_reach(const FluidReach& reach) { reach_ = reach; }

  // The owned spheres wrapped into the box, the halo (wide enough for the fluid's reach
  // and for contacts) and the contact list at its cut-off; the contact history follows
  // the new list.
  void rebuild(DemParticles& s);
  // Owned spheres re-sorted into cells of this size (memory locality), then rebuild.
  void sort_by_cell(DemParticles& s, double cell_size);
  // A sub-step moved no sphere farther than sqrt(max_step2): rebuilds once the bound on
  // the displacement since the build has used half the skin (where the bound says it may
  // have, it becomes the largest displacement measured: in a bed the spheres' largest
  // steps do not add up to anyone's displacement).
  void moved(DemParticles& s, double max_step2);
  // Whether the list holds while every sphere moves `reach` more (rebuilds first if that
  // makes it hold); moved_by(reach) once they have.
  bool holds_for(DemParticles& s, double reach);
  void moved_by(double reach) { drift_ += reach; }
  // The halo copies' positions and changing fields as the passes read them.
  void refresh_halo(DemParticles& s) const;
  // Before a contact pass: on ranks the contact rows read the copies themselves (one rank
  // reads their owned source and needs nothing), so the motion of the copies in the
  // contact list is refreshed (the others wait for refresh_halo). Collective.
  void refresh_for_contacts(DemParticles& s) const {
    if (halo_.ranks()) refresh_selected_copies(halo_, s);
  }

  // Checkpoints: the contact history by id pairs and the fluid's reach.
  void write(CheckpointWriter& w, const DemParticles& s) const;
  void read(const CheckpointReader& r);

 private:
  double displacement_since_build(const DemParticles& s) const;
  void distribute(DemParticles& s);

  Box box_;
  double skin_fraction_;
  bool history_on_;
  Halo halo_;
  const Decomposition* decomposition_ = nullptr;
  CellList cells_;
  ContactNeighbourList contacts_;
  ContactHistory history_;
  FluidReach reach_;
  // a bound on every sphere's displacement since the last build: the largest displacement
  // when last measured plus the largest step of each sub-step since (the Verlet skin's
  // test without reading the positions at the build every sub-step)
  double drift_ = 0;
  long builds_ = 0;
};

}  // namespace sphdem
