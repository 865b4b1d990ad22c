#pragma once
// One coupled SPH-DEM run: the fluid arrays and their neighbour structures, the DEM
// sub-stepper (dem_substepper.hpp) with the spheres, and the coupled step that advances
// them (see advance() for the passes). The passes read compiled StepParams, not the scene.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "coupling/double_smoothing.hpp"
#include "coupling/fluid_sphere_pairs.hpp"
#include "domain/cell_list.hpp"
#include "domain/decomposition.hpp"
#include "domain/halo.hpp"
#include "domain/neighbour_list.hpp"
#include "domain/rank_comm.hpp"
#include "io/checkpoint_file.hpp"
#include "propagator/dem_substepper.hpp"
#include "propagator/flow_controller.hpp"
#include "propagator/pass_timers.hpp"
#include "propagator/step_params.hpp"
#include "scene/scene.hpp"
#include "sph/fluid_particles.hpp"
#include "sph/pair_accumulator.hpp"

namespace sphdem {

class Simulation {
 public:
  // On several ranks (comm), every rank places the same global set and keeps the share
  // its cells hold (domain/decomposition.hpp); one rank runs as without MPI, bit for bit.
  // Spheres on several ranks are not wired yet (issue 36): refused with a clear error.
  explicit Simulation(const Scene& scene, const RankComm& comm = RankComm());
  // A run continued from a checkpoint (scene: the checkpoint's own, see run/checkpoints.hpp).
  Simulation(const Scene& scene, const CheckpointReader& checkpoint,
             const RankComm& comm = RankComm());
  Simulation(const Simulation&) = delete;  // the decomposition refers to comm_
  Simulation& operator=(const Simulation&) = delete;

  // Everything the run carries from one step to the next: the particles' state fields,
  // the contact history, time, step and time step. Written where the next step re-sorts
  // the particles and rebuilds every list (rebuilds_all_next_step()), the run that
  // reads it back repeats the uninterrupted one bit for bit: from there on neither
  // depends on lists built before.
  void write_state(CheckpointWriter& w) const;
  bool rebuilds_all_next_step() const { return steps_since_sort_ + 1 >= sort_interval_; }

  // Start-up: fluid steps with the spheres held, velocities damped (physics.md §4).
  void relax();
  // One SPH step with DEM sub-cycling; time advances by dt_sph().
  void step();
  // On ranks, between steps the spheres' halo copies lag their owners (a step refreshes
  // them for the fluid passes only): this brings them up to date for an analysis that
  // reads them (the runner calls it before its hooks). Collective on ranks.
  void refresh_sphere_copies() { dem_.refresh_halo(); }

  double time() const { return time_; }
  long step_count() const { return steps_; }
  double dt_sph() const { return dt_sph_; }
  double dt_dem() const { return dem_.dt(); }
  double dt_dem_max() const { return params_.dem.dt_max; }
  int dem_substeps() const { return dem_.substeps(); }
  const MultirateTally& multirate_tally() const { return dem_.multirate_tally(); }
  bool multirate() const { return dem_.params().multirate; }
  void set_multirate(bool on) { dem_.set_multirate(on); }
  double contact_time() const { return params_.dem.contact_time; }
  const Scene& scene() const { return scene_; }
  const StepParams& params() const { return params_; }
  const TaitEquationOfState& eos() const { return params_.fluid.eos; }
  // The hydrostatic pressure the variational coupling splits off (coupling.hydrostatic_split;
  // zero without it).
  const HydrostaticPressure& hydrostatic_split() const { return params_.fluid.split; }
  // The imposed flow of a column periodic in z (off otherwise): U, G and the pressure drop.
  const FlowController& flow() const { return flow_; }
  FluidParticles& fluid() { return fluid_; }
  const FluidParticles& fluid() const { return fluid_; }
  DemParticles& spheres() { return dem_.spheres(); }
  const DemParticles& spheres() const { return dem_.spheres(); }
  const DemSubstepper& dem() const { return dem_; }
  const Halo& fluid_halo() const { return fluid_halo_; }
  const RankComm& comm() const { return comm_; }
  // The decomposition over ranks (none on one rank).
  const Decomposition* decomposition() const { return decomposition_ ? &*decomposition_ : nullptr; }
  // Ranks: recut the curve by the counted work every `steps` steps whatever the imbalance
  // (tests of migration; 0, the default: only where max/mean passes 1.10).
  void set_rebalance_interval(int steps) { rebalance_interval_ = steps; }
  const PassTimers& timers() const { return timers_; }
  const ContactLaw& contact_law() const { return params_.dem.law; }
  // Tangential/rolling contact state (empty for the normal-only law), and its records
  // keyed by (sphere id, partner id), as a checkpoint would write them.
  const ContactHistory& contact_history() const { return dem_.contact_history(); }
  std::vector<ContactHistory::Record> contact_records() const { return dem_.contact_records(); }
  // The contact neighbour list of the last build (every pair within the skin; analysis).
  const ContactNeighbourList& contact_list() const { return dem_.contacts(); }
  // Steps between re-sorting the owned particles into cell order (default 100; tests).
  // The particles are re-sorted (and every list rebuilt) every `steps` steps from now.
  void set_sort_interval(int steps) {
    sort_interval_ = steps;
    steps_since_sort_ = 0;
  }
  // Full rebuilds of the fluid's neighbour lists so far (Verlet skin; diagnostics).
  long neighbour_builds() const { return neighbour_builds_; }
  // The fluid's half pair list and its Verlet skin (tests).
  const NeighbourList& fluid_pairs() const { return fluid_pairs_; }
  const FluidSpherePairs& sphere_pairs() const { return sphere_pairs_; }
  double fluid_skin() const { return fluid_skin_; }
  // Skin left (m) of the fluid and the fluid-sphere lists at the current positions: where
  // it is >= 0 the list holds every pair within the kernel support; a negative margin
  // (or a stale list) means the next use rebuilds it.
  struct VerletMargins {
    double fluid = -1, sphere = -1;
  };
  VerletMargins verlet_margins() const;
  std::size_t fluid_count() const;  // mobile fluid particles
  std::size_t wall_count() const;
  // Counters of the last evaluation (log.csv): voidage values raised to the floor,
  // Omega terms bounded, and the wall particles' variational pairs on the spheres (N, z).
  std::size_t voidage_clamped() const { return voidage_clamped_; }
  std::size_t omega_bounded() const { return omega_bounded_; }
  double walls_on_spheres_z() const { return walls_on_spheres_z_; }

  // Exposed for tests and benchmarks: rebuild neighbours and recompute every
  // derived field (voidage, density rate, pressure, theta, interpolation) at the
  // current positions, without advancing time.
  void refresh();

 private:
  void build_initial_state();
  void decompose(double cell, bool keep_cells);
  void resume_share(const CheckpointReader& r);
  void distribute_fluid();
  bool lists_stale() const;
  void advance(bool hold_spheres);
  void rebuild_neighbours();
  void update_neighbours();
  struct Displacements {
    double fluid = 0, sphere = 0;                          // since the fluid lists / sphere halo
    double fluid_since_pairs = 0, sphere_since_pairs = 0;  // since the fluid-sphere pairs
    double growth = 0;       // 2 max_a (h_a - h_a at the fluid lists' build)
    double pair_growth = 0;  // 2 max_a (h_a - h_a at the fluid-sphere pairs' build)
  };
  Displacements displacements() const;
  VerletMargins verlet_margins(const Displacements& d) const;
  void build_sphere_pairs();
  bool sphere_pairs_stale() const { return sphere_pairs_built_at_ != dem_.list_builds(); }
  double fluid_sphere_cutoff() const;
  void update_smoothing_length();
  void compute_voidage();
  void update_pressure();
  void compute_fluid_side(bool hold_spheres);
  void apply_variational_pressure(bool hold_spheres);
  double fluid_cutoff() const;
  void next_dt();
  void control_flow(double t, double dt, bool hold_spheres);
  void start_balanced();

  Scene scene_;
  RankComm comm_;
  StepParams params_;
  FluidParticles fluid_;
  DemSubstepper dem_;
  std::optional<Decomposition> decomposition_;  // on several ranks
  double grid_cell_ = 0;                        // the decomposition's smallest cell
  int rebalance_interval_ = 0;
  long balanced_at_ = 0;  // the step of the last balance
  bool force_rebalance_ = false;
  bool in_step_ = false;  // between a step's predictor and corrector
  Halo fluid_halo_;
  CellList fluid_cells_, sphere_cells_;
  NeighbourList fluid_pairs_;  // fluid-fluid pairs within the cell size, each owned pair once
  PairAccumulator pair_scratch_;
  FluidSpherePairs sphere_pairs_;  // fluid-sphere pairs of the step with their kernel values
  // double smoothing of the big species (3.8-3.10)
  CellList big_cells_;
  BigSphereFraction big_fraction_;
  std::vector<double> big_solid_, big_solid_over_d_;
  PairAccumulator sphere_scratch_;
  std::vector<double> u0x_, u0y_, u0z_, rho0_;   // state at the start of a step
  std::vector<double> drag_phi_, drag_impulse_;  // the drag exchange's phi_a and J_j
  double time_ = 0, dt_sph_ = 0;
  double cell_size_ = 0;
  int sort_interval_ = 100;  // steps between re-sorts (bench/RESULTS.md, session 25)
  int steps_since_sort_ = sort_interval_ - 1;  // the first step sorts (placement order)
  // Verlet lists: positions and h at the last fluid build, h_max then, the skin, whether
  // the fluid lists must be rebuilt before their next use, and the sphere list build the
  // fluid-sphere pairs index into. Each list holds a particle's pairs within its own
  // reach (its h's support plus the skin), not h_max's: in a bed h grows as 1/eps^(1/3).
  std::vector<double> xr_, yr_, zr_, hr_;
  std::vector<double> xp_, yp_, zp_, hp_, sxp_, syp_, szp_;  // at the pairs' build
  std::vector<double> list_reach_;  // scratch: each particle's cut-off at a build
  double hmax_at_build_ = 0, fluid_skin_ = 0, sphere_pair_skin_ = 0;
  bool fluid_lists_stale_ = true;
  long sphere_pairs_built_at_ = -1;
  long neighbour_builds_ = 0;
  long steps_ = 0;
  std::size_t voidage_clamped_ = 0, omega_bounded_ = 0;
  double walls_on_spheres_z_ = 0.0;
  FlowController flow_;
  std::vector<double> flow_impulse_;  // the spheres' share of a flow correction
  PassTimers timers_;
};

}  // namespace sphdem
