#pragma once
// Multi-rate sub-steps over half an SPH step (the r-RESPA idea, Tuckerman, Berne & Martyna
// 1992). A sphere whose neighbours and wall are all farther than a margin m at the start of
// the half step feels no contact in it as long as no sphere moves m/2 or more: it takes the
// step of its fluid force and gravity (free_dt_max and the drag's relaxation bound), the
// spheres near a contact take the contact sub-steps. m is time.multirate_margin times the
// largest distance a sphere would cover at the start's speeds and accelerations; if any
// sphere moved m/2 or more (a bound: the sums of the largest steps), the half step starts
// again from the saved state with every sphere sub-stepped. Both kinds add their
// trapezoids to fm over the same window. With friction a free sphere keeps its spin (no
// contact, no torque) and the near ones sub-step theirs; only their rows advance the
// contact history, so only theirs is kept for a restart. The state is saved by the field
// registry's tags (domain/state_snapshot.hpp).
#include <cstdint>
#include <vector>

#include "coupling/fluid_force.hpp"
#include "dem/dem_particles.hpp"
#include "dem/rotation.hpp"
#include "dem/sphere_lists.hpp"
#include "dem/verlet.hpp"
#include "domain/state_snapshot.hpp"
#include "propagator/step_params.hpp"

namespace sphdem {

// How the half steps went with time.multirate (printed at the end of a run).
struct MultirateTally {
  long half_steps = 0;       // with spheres
  long multirate = 0;        // of which the spheres out of contact took the fluid's step
  long sent_back = 0;        // tried, and started again with every sphere sub-stepped
  double near_spheres = 0;   // summed over the multirate half steps: the spheres sub-stepped
  double owned_spheres = 0;  // ... and all of them
};

class MultirateHalfStep {
 public:
  // The half step of length dt/2 (count contact sub-steps of h for the near spheres);
  // false where it does not pay or cannot be trusted, the spheres then as they were.
  bool take(const DemStepParams& p, DemParticles& s, SphereLists& lists, SphereDrag& drag,
            double dt, double h, int count);
  const MultirateTally& tally() const { return tally_; }
  MultirateTally& tally() { return tally_; }

 private:
  // One step of length h of every sphere under its fluid force and gravity alone; returns
  // the largest step squared.
  double free_step(const DemStepParams& p, DemParticles& s, SphereDrag& drag, double h,
                   double weight, bool fresh);
  // The contact sub-steps of the near spheres; returns the sum of the largest steps.
  template <class Contact>
  double near_substeps(const Contact& contact, const DemStepParams& p, DemParticles& s,
                       SphereLists& lists, SphereDrag& drag, double h, int count, double weight);
  // the near spheres' contact history at the start, or back to it
  void keep_near_history(const SphereLists& lists);
  void restore_near_history(SphereLists& lists) const;

  std::vector<std::uint32_t> near_;          // the spheres near a contact
  StateSnapshot saved_;                      // the state at the start of the half step
  std::vector<ContactState> history_saved_;  // ... and the near spheres' contact history
  SphereVectors a_old_;                      // the near spheres' sub-step start
  OldTorque torque_old_;
  MultirateTally tally_;
};

}  // namespace sphdem
