#pragma once
// One coupled SPH-DEM run: the state (fluid and sphere arrays), the neighbour
// structures, and the propagator that advances them (see step() for the passes).
#include <array>
#include <chrono>
#include <cstddef>
#include <string>
#include <vector>

#include "coupling/double_smoothing.hpp"
#include "coupling/fluid_sphere_pairs.hpp"
#include "coupling/voidage_grid.hpp"
#include "dem/contact_forces.hpp"
#include "dem/contact_history.hpp"
#include "dem/contact_registry.hpp"
#include "dem/dem_particles.hpp"
#include "dem/rotation.hpp"
#include "domain/cell_list.hpp"
#include "domain/neighbour_list.hpp"
#include "domain/periodic_halo.hpp"
#include "run/scene.hpp"
#include "sph/equation_of_state.hpp"
#include "sph/fluid_particles.hpp"
#include "sph/hydrostatic_pressure.hpp"
#include "sph/pair_accumulator.hpp"

namespace sphdem {

// Per-species and global observables (the columns of log.csv).
struct Diagnostics {
  double time = 0;
  long step = 0;
  double dt_sph = 0, dt_dem = 0;
  double fluid_mass = 0;
  double kinetic_energy_fluid = 0, kinetic_energy_solid = 0;
  double max_overlap_over_d = 0;
  double max_density_error = 0;  // max |rho/(eps rho0) - 1| over mobile fluid
  std::size_t voidage_clamped = 0, omega_bounded = 0;
  double excess_pore_pressure_base = 0;  // run/pore_pressure.hpp: u_base / (rho_f |g| H)
  double wall_load_base = 0;             // run/pore_pressure.hpp: the spheres' load on the wall, same unit
  double fluid_load_base = 0;            // run/pore_pressure.hpp: the fluid's excess load on the wall, same unit
  std::vector<double> vz_mean, slip_z_mean, com_z;  // per species
  std::vector<std::size_t> count;                    // spheres per species
};

// Wall-clock time spent in each pass of the propagator.
struct PassTimers {
  static constexpr int kCount = 9;
  static constexpr const char* kNames[kCount] = {"integrate_fluid", "dem_substeps", "neighbours",
                                                 "voidage", "density_rate", "momentum",
                                                 "interpolation", "reaction", "other"};
  std::array<double, kCount> seconds{};
};

class Simulation {
 public:
  explicit Simulation(const Scene& scene);

  // Start-up: fluid steps with the spheres held, velocities damped (physics.md §4).
  void relax();
  // One SPH step with DEM sub-cycling; time advances by dt_sph().
  void step();

  double time() const { return time_; }
  long step_count() const { return steps_; }
  double dt_sph() const { return dt_sph_; }
  double dt_dem() const { return dt_dem_; }
  double dt_dem_max() const { return dt_dem_max_; }
  int dem_substeps() const { return dem_substeps_; }
  double contact_time() const { return t_contact_; }
  const Scene& scene() const { return scene_; }
  const TaitEquationOfState& eos() const { return eos_; }
  // The hydrostatic pressure the variational coupling splits off (coupling.hydrostatic_split;
  // zero without it).
  HydrostaticPressure hydrostatic_split() const;
  FluidParticles& fluid() { return fluid_; }
  const FluidParticles& fluid() const { return fluid_; }
  DemParticles& spheres() { return dem_; }
  const DemParticles& spheres() const { return dem_; }
  const PassTimers& timers() const { return timers_; }
  const ContactLaw& contact_law() const { return contact_law_; }
  // Tangential/rolling contact state (empty for the normal-only law), and its records
  // keyed by (sphere id, partner id), as a checkpoint would write them.
  const ContactHistory& contact_history() const { return contact_history_; }
  std::vector<ContactHistory::Record> contact_records() const { return contact_history_.records(dem_, contacts_); }
  // Steps between re-sorting the owned particles into cell order (default 20; tests).
  void set_sort_interval(int steps) { sort_interval_ = steps; }
  // Full rebuilds of the fluid's neighbour lists so far (Verlet skin; diagnostics).
  long neighbour_builds() const { return neighbour_builds_; }
  Diagnostics diagnostics() const;
  std::size_t fluid_count() const;  // mobile fluid particles
  std::size_t wall_count() const;

  // The voidage on a regular grid (analysis), with the solver's kernel at length h.
  std::vector<double> voidage_on_grid(const GridSpec& grid, double h) const;
  // The contact neighbour list of the last build (every pair within the skin; analysis).
  const ContactNeighbourList& contact_list() const { return contacts_; }
  // Number of touching neighbours (spheres and the wall) of each owned sphere.
  std::vector<int> contact_counts() const;

  // Exposed for tests and benchmarks: rebuild neighbours and recompute every
  // derived field (voidage, density rate, pressure, theta, interpolation) at the
  // current positions, without advancing time.
  void refresh();

 private:
  void build_initial_state();
  void advance(bool hold_spheres);
  void rebuild_neighbours();
  void update_neighbours();
  void rebuild_contact_neighbours();
  void build_sphere_pairs();
  double fluid_sphere_cutoff() const;
  double halo_width(double needed, double wanted) const;
  void update_smoothing_length();
  void compute_voidage();
  void update_pressure();
  void compute_fluid_side(bool hold_spheres);
  void dem_half(double dt, bool first_half);
  void dem_forces(bool accumulate_mean, double weight, double dt_springs = 0.0);
  void apply_variational_pressure(bool hold_spheres);
  template <class Force>
  void sum_over_rigid_groups(Force force);
  void check_finite() const;
  double fluid_cutoff() const;
  void next_dt();

  Scene scene_;
  TaitEquationOfState eos_;
  drag::Fluid drag_fluid_;
  FluidParticles fluid_;
  DemParticles dem_;
  PeriodicHalo fluid_halo_, dem_halo_;
  CellList fluid_cells_, dem_cells_, contact_cells_;
  NeighbourList fluid_pairs_;  // fluid-fluid pairs within the cell size, each owned pair once
  PairAccumulator pair_scratch_;
  FluidSpherePairs sphere_pairs_;  // fluid-sphere pairs of the step with their kernel values
  // double smoothing of the big species (3.8-3.10); big_cutoff_ = 0 when off
  std::vector<std::uint8_t> is_big_species_;
  double big_cutoff_ = 0.0;
  CellList big_cells_;
  BigSphereFraction big_fraction_;
  std::vector<double> big_solid_, big_solid_over_d_;
  PairAccumulator sphere_scratch_;
  ContactNeighbourList contacts_;
  ContactLaw contact_law_;
  ContactHistory contact_history_;
  bool rotation_ = false;  // tangential or rolling parts: history and spin on
  std::vector<double> u0x_, u0y_, u0z_, rho0_;  // state at the start of a step
  std::vector<double> a_old_x_, a_old_y_, a_old_z_;  // sphere accelerations of the previous sub-step
  std::vector<double> g_old_x_, g_old_y_, g_old_z_;  // spheres' g before a variational coupling pass
  OldTorque torque_old_;                              // sphere torques of the previous sub-step
  std::vector<double> group_fx_, group_fy_, group_fz_, group_m_;
  int n_groups_ = 0;
  double time_ = 0, dt_sph_ = 0, dt_dem_ = 0, dt_dem_max_ = 0, t_contact_ = 0;
  double cell_size_ = 0;
  int dem_substeps_ = 0;
  int steps_since_sort_ = 0;
  int sort_interval_ = 20;
  // Verlet lists: positions and h_max at the last fluid build, the skin, and whether a
  // list must be rebuilt before its next use.
  std::vector<double> xr_, yr_, zr_;
  double hmax_at_build_ = 0, fluid_skin_ = 0;
  bool fluid_lists_stale_ = true, sphere_pairs_stale_ = true;
  long neighbour_builds_ = 0;
  long steps_ = 0;
  std::size_t voidage_clamped_ = 0, omega_bounded_ = 0;
  double walls_on_spheres_z_ = 0.0;  // the wall particles' variational pairs on the spheres, last evaluation (N)
  PassTimers timers_;
};

}  // namespace sphdem
