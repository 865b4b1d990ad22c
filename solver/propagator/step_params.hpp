#pragma once
// The parameters of the passes, compiled once from the scene: the propagator reads
// these plain structs, never the scene's input schema.
#include <array>
#include <cstdint>
#include <vector>

#include "coupling/distributor_mirror.hpp"
#include "coupling/drag_law_table.hpp"
#include "coupling/voidage.hpp"
#include "dem/contact_registry.hpp"
#include "dem/sphere_walls.hpp"
#include "domain/box.hpp"
#include "scene/scene.hpp"
#include "sph/density_diffusion.hpp"
#include "sph/equation_of_state.hpp"
#include "sph/hydrostatic_pressure.hpp"
#include "sph/momentum.hpp"

namespace sphdem {

struct FluidStepParams {
  TaitEquationOfState eos;         // (2.58-2.59)
  double smoothing_factor = 1.5;   // sigma of (2.65)
  double spacing = 0;              // lattice dx of the hydrostatic start
  double fill_height = 0;          // H of the hydrostatic start
  MomentumParams momentum;         // mu, alpha, cfl (2.55-2.57, 3.5)
  double kinematic_viscosity = 0;  // nu = mu / rho_f, the viscous time-step limit
  double max_dt = 0;               // cap of dt_SPH
  int relax_steps = 0;             // start-up: fluid steps with the spheres held
  double relax_damping = 0;        // fraction of the fluid velocity removed per such step
  HydrostaticPressure split;       // split off by the variational coupling (zero without)
  DensityDiffusion diffusion;      // delta-SPH (off unless fluid.density_diffusion > 0)
};

struct CouplingParams {
  bool variational = false;        // coupling.pressure_coupling
  double sphere_kernel_scale = 1;  // H / h of the spheres' kernel
  double drag_kernel_scale = 1;    // H_drag / h of the drag's kernel (<= the spheres')
  // coupling.drag_upstream: gravity's unit vector, the side of a sphere its drag's fields are
  // read from (FluidSpherePairs::upstream); zero: the whole kernel
  std::array<double, 3> drag_upstream{};
  // coupling.drag_voidage_upstream: the fluid's drag voidage from the spheres below it
  VoidageUpstream voidage_upstream;
  double voidage_floor = 0.3;
  bool double_smoothing = false;  // (3.8-3.10)
  double big_h_over_d = 1.5;
  std::vector<std::uint8_t> is_big_species;
  double big_cutoff = 0;  // support of the big species' own kernel (3.9); 0 when off
  // A bed on flow.distributor: the drag's weights continue it below the plate
  // (coupling/distributor_mirror.hpp); off elsewhere.
  DistributorPlane distributor;
};

struct DemStepParams {
  ContactLaw law;         // normal, tangential and rolling parts (contact_registry.hpp)
  bool rotation = false;  // tangential or rolling parts: contact history and spin on
  double skin = 0.3;      // contact Verlet skin / largest diameter
  double contact_time = 0, dt_max = 0;  // scene/time_step.hpp
  double free_dt_max = 0;               // (scene/time_step.hpp) with multirate
  bool multirate = false;               // time.multirate
  double multirate_margin = 4;          // time.multirate_margin
  // A sub-step also stays below this fraction of the shortest drag relaxation time
  // m / (c eps) at the spheres' own voidage and Reynolds number (as dt_max does of the
  // Stokes time): a sediment's drag is ~10 times Stokes'.
  double drag_time_fraction = 0.1;
  std::array<double, 3> gravity{};
  // The spheres' bottom wall and top plane (a column periodic in z: the distributor or
  // none, and the plane that holds what the flow carries up; dem/sphere_walls.hpp).
  SphereWalls walls;
  // The mean pressure gradient G (Pa/m) of an imposed flow, on each sphere as G V_j
  // (propagator/flow_controller.hpp); set each step.
  std::array<double, 3> mean_pressure_gradient{0.0, 0.0, 0.0};
  std::vector<char> fixed_groups;  // per rigid group, in the scene's order: never moves
  bool fluid_force = true;         // false: dry DEM, no fluid and so no fluid force
  drag::DragLaw drag;
  drag::Fluid fluid;
  bool variational = false;  // the pressure force is switched per evaluation, not in fm
};

// V / m of a sphere of radius r: the share of the mean pressure gradient G in its
// acceleration, G V / m.
inline double mean_gradient_share(double r, double inv_m) {
  return 4.0 / 3.0 * 3.14159265358979323846 * r * r * r * inv_m;
}

struct StepParams {
  Box box;
  std::array<double, 3> gravity{};
  FluidStepParams fluid;
  CouplingParams coupling;
  DemStepParams dem;
};

// Throws SceneError (naming the file and key) for a contact law the solver cannot run.
StepParams compile_step_params(const Scene& scene);

}  // namespace sphdem
