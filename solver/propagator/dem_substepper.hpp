#pragma once
// The DEM side of the propagator as its own unit: the spheres with their lists
// (dem/sphere_lists.hpp) and the velocity-Verlet sub-steps over half an SPH step with the
// fluid fields at the spheres held (physics.md §4), in one of three schemes: one pass per
// sub-step (its force rows also correct and predict), the predictor a pass apart (rigid
// groups share their force between), or multi-rate (propagator/multirate_half_step.hpp).
// The coupled step (simulation.hpp) writes the fluid fields at the spheres and reads back
// their mean force fm.
#include <algorithm>
#include <cstdint>
#include <vector>

#include "coupling/fluid_force.hpp"
#include "dem/contact_history.hpp"
#include "dem/contact_registry.hpp"
#include "dem/contact_rows.hpp"
#include "dem/dem_particles.hpp"
#include "dem/rigid_groups.hpp"
#include "dem/rotation.hpp"
#include "dem/sphere_lists.hpp"
#include "dem/verlet.hpp"
#include "domain/box.hpp"
#include "domain/measured_shares.hpp"
#include "io/checkpoint_file.hpp"
#include "propagator/multirate_half_step.hpp"
#include "propagator/step_params.hpp"

namespace sphdem {

class DemSubstepper {
 public:
  DemSubstepper(const Box& box, const DemStepParams& params, DemParticles spheres,
                const RankComm& comm = RankComm(MPI_COMM_NULL));
  // Several ranks: the decomposition the fluid shares (the spheres migrate at each list
  // rebuild and the contact rows read halo copies refreshed every sub-step). Rigid groups
  // are refused there (not yet summed over ranks).
  void set_decomposition(const Decomposition* d);
  DemParticles& spheres() { return s_; }
  const DemParticles& spheres() const { return s_; }
  const DemStepParams& params() const { return p_; }
  // time.multirate on or off from the next half step (step_timing times steps without it).
  void set_multirate(bool on) { p_.multirate = on; }
  const SphereLists& lists() const { return lists_; }
  const Halo& halo() const { return lists_.halo(); }
  const ContactNeighbourList& contacts() const { return lists_.contacts(); }
  const ContactHistory& contact_history() const { return lists_.history(); }
  std::vector<ContactHistory::Record> contact_records() const { return lists_.records(s_); }
  double dt() const { return dt_; }  // the last sub-step
  // The largest drag relaxation rate c eps / m over the spheres in the last force pass
  // (0 before the first, and without fluid); carried from one step to the next.
  double drag_rate_max() const { return drag_.rate_max; }
  // The fluid side of the drag exchange is explicit: the fluid a sphere drags relaxes at
  // r times the sphere's rate, r = (1 - eps) rho_p / (eps rho_f). A sphere relaxing toward
  // fluid held over a step, and the fluid getting the impulse back, multiply their slip by
  // 1 - (1 + r)(1 - exp(-dt rate)), which stays in [0, 1) (no overshoot) for
  // dt <= ln(1 + 1/r) / rate, the rate linearised (coupling/drag_linearisation.hpp). The
  // smallest such dt over the spheres at their current slip (infinity without drag): what
  // an explicit exchange would need; `check` prints it (the solver's exchange is
  // semi-implicit, coupling/drag_exchange.hpp).
  double fluid_drag_time() const;
  // d f_j / d u_f = eps_j d|f_j|/d|u_s| (2.68, 2.74, the law linearised) of every sphere,
  // owned and halo images, at its current slip (0 without fluid): the gains of the drag
  // exchange (coupling/drag_exchange.hpp); update_drag_gains() computes them.
  const std::vector<double>& update_drag_gains();
  const std::vector<double>& drag_gains() const { return drag_gain_; }
  // Adds impulse (three values per owned sphere) to the owned spheres' velocities; a
  // rigid group takes the sum of its members' over its mass.
  void add_impulses(const double* impulse);
  void set_mean_pressure_gradient(const std::array<double, 3>& G) { p_.mean_pressure_gradient = G; }
  int substeps() const { return substeps_; }  // per SPH step
  // Every halo copy's position and motion as its owner's now (on ranks a half step leaves
  // them so after the first half only). Collective on ranks.
  void refresh_halo() { lists_.refresh_halo(s_); }
  // The work of owned sphere j in one SPH step, in list entries (the decomposition's
  // counter): its row's cost in every sub-step of the last step.
  std::uint64_t sphere_work(std::size_t j) const {
    const std::uint32_t* row = lists_.contacts().offset.data() + j;
    return static_cast<std::uint64_t>((row[1] - row[0] + row_cost()) * std::max(1, substeps_));
  }
  const MultirateTally& multirate_tally() const { return multirate_.tally(); }
  // Sphere halo and contact list builds so far: a list into the halo is stale once it changes.
  long list_builds() const { return lists_.builds(); }

  void set_fluid_reach(const FluidReach& reach) { lists_.set_fluid_reach(reach); }
  // The sphere halo (wide enough for the fluid's reach and for contacts) and the contact
  // list at its cut-off; the contact history follows the new list.
  void rebuild_lists() { lists_.rebuild(s_); }
  // Owned spheres re-sorted into cells of this size (memory locality), then the lists.
  void sort_by_cell(double cell_size) { lists_.sort_by_cell(s_, cell_size); }
  // Sub-steps over one half of an SPH step of length dt.
  void half_step(double dt, bool first_half);
  // Fluid force (2.68) and contact force (2.36) on each owned sphere, then its
  // acceleration (2.35). With accumulate_mean, adds weight * (fluid force) to fm;
  // dt_springs: time by which the tangential and rolling springs advance.
  void forces(bool accumulate_mean, double weight, double dt_springs = 0.0);
  // The variational coupling switches the spheres' pressure force: keep g before the
  // pass, then add V (g - g_kept) to the force and acceleration of the last sub-step.
  void keep_pressure_gradient();
  void switch_pressure_force();
  // The g kept by the last keep_pressure_gradient, axis 0-2 (tests).
  const std::vector<double>& kept_pressure_gradient(int axis) const {
    return axis == 0 ? g_old_.x : axis == 1 ? g_old_.y : g_old_.z;
  }
  void clear_mean_force();

  // Checkpoints: the spheres' state fields and what the sub-steps carry from one SPH step
  // to the next besides them (the lists' contact history by id pairs and the fluid's
  // reach, the drag relaxation rate that sets the next sub-step). Read back into a
  // substepper made with the checkpoint's spheres (read_spheres).
  void write_state(CheckpointWriter& w) const;
  static DemParticles read_spheres(const CheckpointReader& r);
  void read_state(const CheckpointReader& r);

 private:
  // The cost of a sphere in its force pass, in contact-list entries: each thread takes
  // the spheres of one equal share (domain/row_partition.hpp) in every pass of a sub-step.
  double row_cost() const { return kContactRowCost + (p_.fluid_force ? kDragRowCost : 0.0); }
  // a drag law's evaluation, the fluid force and the sub-step's update of one sphere, in
  // list entries (where the two threads' samples in these passes even out, bench/RESULTS.md)
  static constexpr double kDragRowCost = 40.0;
  // What the force pass does with a sphere once it has its new acceleration a: nothing
  // (the sub-step's passes apart), or the corrector v += h/2 (a - a_old) and, with
  // `predict`, the next sub-step's predictor (x += h (v + h a / 2), v += h a), both into the
  // next buffers (the rows still to come read this sub-step's x and v); the spin likewise
  // with the torque (rotation.hpp).
  struct Advance {
    bool correct = false, predict = false;
    double h = 0;
  };
  // The next sub-step's positions, velocities and spins (the fused passes' second buffers).
  struct NextSubstep {
    std::vector<double> x, y, z, vx, vy, vz, wx, wy, wz;
  };
  // returns the largest predictor step squared (0 without `predict`)
  double forces_advancing(bool accumulate_mean, double weight, double dt_springs,
                          const Advance& advance);
  // kFluid false: a dry scene, no fluid force to evaluate (the law is not read)
  template <bool kFluid, class Contact>
  double force_rows(const Contact& contact, bool accumulate_mean, double weight, double dt_springs,
                    const Advance& advance);
  // The sub-steps of a half step with the corrector and predictor (of the velocity and
  // the spin) in the force pass: one pass over the spheres per sub-step (without rigid
  // groups).
  void substeps_fused(double h, int count, double weight);
  // ... and with the predictor a pass of its own (the rigid groups' shared force comes
  // between)
  void substeps_apart(double h, int count, double weight);

  DemStepParams p_;
  DemParticles s_;
  SphereLists lists_;
  RigidGroups groups_;
  SphereDrag drag_;  // the last force pass's drag coefficients and rate
  std::vector<double> drag_gain_;
  MultirateHalfStep multirate_;
  NextSubstep next_;
  SphereVectors a_old_;             // accelerations of the previous sub-step
  OldTorque torque_old_;            // torques of the previous sub-step
  SphereVectors g_old_;             // g before a variational coupling pass
  MeasuredShares measured_shares_;  // the dry force pass's rows per thread
  double dt_ = 0;
  int substeps_ = 0;
  bool any_spheres_ = false;  // on any rank
};

}  // namespace sphdem
