#pragma once
// The DEM side of the propagator as its own unit: the spheres, their halo and contact
// list, the contact history, and the velocity-Verlet sub-steps over half an SPH step with
// the fluid fields at the spheres held (physics.md §4). The coupled step (simulation.hpp)
// writes the fluid fields at the spheres and reads back their mean force fm.
#include <cstdint>
#include <vector>

#include "dem/contact_forces.hpp"
#include "dem/contact_history.hpp"
#include "dem/contact_registry.hpp"
#include "dem/dem_particles.hpp"
#include "dem/rotation.hpp"
#include "domain/box.hpp"
#include "domain/cell_list.hpp"
#include "domain/measured_shares.hpp"
#include "domain/periodic_halo.hpp"
#include "io/checkpoint_file.hpp"
#include "propagator/step_params.hpp"
#include "sph/pair_isa.hpp"

namespace sphdem {

// How far the fluid side reaches into the sphere halo: `needed` and `wanted` (with the
// fluid's Verlet skin) from the fluid particles, `sphere_kernel` a kernel centred on the
// spheres (double smoothing's big spheres, 3.9), which the contact skin extends.
struct FluidReach {
  double needed = 0, wanted = 0, sphere_kernel = 0;
};

// How the half steps went with time.multirate (printed at the end of a run).
struct MultirateTally {
  long half_steps = 0;       // with spheres
  long multirate = 0;        // of which the spheres out of contact took the fluid's step
  long sent_back = 0;        // tried, and started again with every sphere sub-stepped
  double near_spheres = 0;   // summed over the multirate half steps: the spheres sub-stepped
  double owned_spheres = 0;  // ... and all of them
};

class DemSubstepper {
 public:
  DemSubstepper(const Box& box, const DemStepParams& params, DemParticles spheres);

  DemParticles& spheres() { return s_; }
  const DemParticles& spheres() const { return s_; }
  const DemStepParams& params() const { return p_; }
  // time.multirate on or off from the next half step (step_timing times steps without it).
  void set_multirate(bool on) { p_.multirate = on; }
  const PeriodicHalo& halo() const { return halo_; }
  const ContactNeighbourList& contacts() const { return contacts_; }
  const ContactHistory& contact_history() const { return history_; }
  std::vector<ContactHistory::Record> contact_records() const {
    return history_.records(s_, contacts_);
  }
  double dt() const { return dt_; }  // the last sub-step
  // The largest drag relaxation rate c eps / m over the spheres in the last force pass
  // (0 before the first, and without fluid); carried from one step to the next.
  double drag_rate_max() const { return drag_rate_max_; }
  // The fluid side of the drag exchange is explicit: the fluid a sphere drags relaxes at
  // r times the sphere's rate, r = (1 - eps) rho_p / (eps rho_f). A sphere relaxing toward
  // fluid held over a step, and the fluid getting the impulse back, multiply their slip by
  // 1 - (1 + r)(1 - exp(-dt rate)), which stays in [0, 1) (no overshoot) for
  // dt <= ln(1 + 1/r) / rate. The smallest such dt over the spheres of the last force pass
  // (infinity without drag): what an explicit exchange would need; `check` prints it (the
  // solver's exchange is semi-implicit, coupling/drag_exchange.hpp).
  double fluid_drag_time() const;
  // d f_j / d u_f = c_j eps_j (2.68, 2.74) of every sphere, owned and halo images, at the
  // last force pass (0 before the first and without fluid): the gains of the drag
  // exchange (coupling/drag_exchange.hpp); update_drag_gains() computes them.
  const std::vector<double>& update_drag_gains();
  const std::vector<double>& drag_gains() const { return drag_gain_; }
  // Adds impulse (three values per owned sphere) to the owned spheres' velocities; a
  // rigid group takes the sum of its members' over its mass.
  void add_impulses(const double* impulse);
  int substeps() const { return substeps_; }  // per SPH step
  const MultirateTally& multirate_tally() const { return tally_; }
  // Sphere halo and contact list builds so far: a list into the halo is stale once it changes.
  long list_builds() const { return list_builds_; }

  void set_fluid_reach(const FluidReach& reach) { reach_ = reach; }
  // The sphere halo (wide enough for the fluid's reach and for contacts) and the contact
  // list at its cut-off; the contact history follows the new list.
  void rebuild_lists();
  // Owned spheres re-sorted into cells of this size (memory locality), then the lists.
  void sort_by_cell(double cell_size);
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
    return axis == 0 ? g_old_x_ : axis == 1 ? g_old_y_ : g_old_z_;
  }
  void clear_mean_force();

  // Checkpoints: the spheres' state fields and what the sub-steps carry from one SPH step
  // to the next besides them (the contact history by id pairs, the drag relaxation rate
  // that sets the next sub-step, the fluid's reach into the halo). Read back into a
  // substepper made with the checkpoint's spheres (read_spheres).
  void write_state(CheckpointWriter& w) const;
  static DemParticles read_spheres(const CheckpointReader& r);
  void read_state(const CheckpointReader& r);

 private:
  template <class Force>
  void sum_over_rigid_groups(Force force);
  // Adds each rigid group's summed value over its mass to (x, y, z) of its members.
  void add_group_shares(std::vector<double>& x, std::vector<double>& y,
                        std::vector<double>& z) const;
  // The cost of a sphere in its force pass, in contact-list entries: each thread takes
  // the spheres of one equal share (domain/row_partition.hpp) in every pass of a sub-step.
  double row_cost() const { return kContactRowCost + (p_.fluid_force ? kDragRowCost : 0.0); }
  // a drag law's evaluation, the fluid force and the sub-step's update of one sphere, in
  // list entries (where the two threads' samples in these passes even out, bench/RESULTS.md)
  static constexpr double kDragRowCost = 40.0;
  // spheres per block of the force pass: the fluid forces of a block are still in the
  // cache when its contact rows add them to the accelerations
  static constexpr std::size_t kForceBlock = 256;
  // What the force pass does with a sphere once it has its new acceleration a: nothing
  // (the sub-step's passes apart), or the corrector v += h/2 (a - a_old) and, with
  // `predict`, the next sub-step's predictor (x += h (v + h a / 2), v += h a), both into the
  // next buffers (the rows still to come read this sub-step's x and v); the spin likewise
  // with the torque (rotation.hpp).
  struct Advance {
    bool correct = false, predict = false;
    double h = 0;
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
  // Spheres out of contact take the fluid's step, the others the contact sub-steps; false
  // where that does not pay or cannot be trusted (the half step is then as it was).
  bool substeps_multirate(double dt, double h, int count);
  double free_step(double h, double weight, bool fresh);
  template <class Contact>
  double near_substeps(const Contact& contact, double h, int count, double weight);
  // ... and with the predictor a pass of its own (the rigid groups' shared force comes
  // between)
  void substeps_apart(double h, int count, double weight);
  // Adds the largest step of a predictor to the drift, and rebuilds the lists once the
  // drift has used up half the skin: where the bound says it may have, the drift becomes
  // the largest displacement since the build (in a bed the spheres' largest steps do not
  // add up to anyone's displacement).
  void drifted(double max_step2);
  double displacement_since_build() const;

  Box box_;
  DemStepParams p_;
  DemParticles s_;
  PeriodicHalo halo_;
  CellList cells_;
  ContactNeighbourList contacts_;
  ContactHistory history_;
  FluidReach reach_;
  std::vector<double> a_old_x_, a_old_y_, a_old_z_;  // accelerations of the previous sub-step
  std::vector<double> x_next_, y_next_, z_next_;     // positions and velocities of the
  std::vector<double> vx_next_, vy_next_, vz_next_;  // next sub-step (fused passes)
  std::vector<double> wx_next_, wy_next_, wz_next_;  // ... and spins
  std::vector<std::uint32_t> near_;                  // multirate: the spheres near a contact
  std::vector<double> saved_;                // multirate: the state at the start of the half step
  std::vector<ContactState> history_saved_;  // ... and the near spheres' contact history
  MultirateTally tally_;
  std::vector<double> g_old_x_, g_old_y_, g_old_z_;  // g before a variational coupling pass
  std::vector<double> drag_c_;      // drag coefficient of each sphere in this force pass (scratch)
  PairIsa isa_ = best_pair_isa();   // the drag coefficients' instruction set
  MeasuredShares measured_shares_;  // the dry force pass's rows per thread
  OldTorque torque_old_;            // torques of the previous sub-step
  std::vector<double> group_fx_, group_fy_, group_fz_, group_m_;
  int n_groups_ = 0;
  double dt_ = 0;
  std::vector<double> drag_gain_;
  double drag_rate_max_ = 0;  // sets the next half step's sub-step with dt_max
  // a bound on every sphere's displacement since the last list build: the largest
  // displacement when last measured plus the largest step of each sub-step since (the
  // Verlet skin's test without reading the positions at the build every sub-step)
  double drift_ = 0;
  int substeps_ = 0;
  long list_builds_ = 0;
};

}  // namespace sphdem
