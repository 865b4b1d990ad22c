#pragma once
// A scene: every parameter of a run, in SI units, as read from cases/*.yaml.
// Plain data; the loader (scene_loader.cpp) fills and validates it.
#include <array>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "coupling/drag_law_table.hpp"
#include "dem/contact_model.hpp"
#include "dem/rolling_model.hpp"
#include "dem/tangential_model.hpp"
#include "domain/box.hpp"
#include "scene/size_distribution.hpp"
#include "sph/kernel.hpp"

namespace sphdem {

struct FluidSpec {
  double density = 1000.0;           // rho_f (kg/m^3)
  double viscosity = 8.9e-4;         // mu (Pa s)
  double spacing = 2.0e-4;           // initial lattice spacing dx (m)
  double smoothing_factor = 1.5;     // sigma in h = sigma (m/rho)^(1/3), eq. 2.65
  double fill_height = 0.0;          // free-surface height (m); 0 = the box height
  double expected_speed = 0.0;       // u_m (m/s) for B, eq. 2.64; 0 = largest terminal speed
  double sound_speed = 0.0;          // c0 (m/s); 0 = auto (scene_loader.cpp, physics.md §1)
  double sound_speed_factor = 10.0;  // that factor (scene/fidelity.hpp)
  double resolution = 1.0;  // layers per `spacing`: dx = spacing / resolution (resolved to 1)
  double alpha_artificial =
      0.0;  // Monaghan alpha on approaching pairs only (off: it adds viscosity)
  double density_diffusion = 0.1;  // delta of the density diffusion (sph/density_diffusion.hpp)
  int gamma = 7;
  int wall_layers = 3;
  bool enabled = true;  // false: spheres only (dry DEM), no SPH particles

  // h of the initial lattice: sigma dx (2.65 with m/rho = dx^3, the hydrostatic start)
  double lattice_h() const { return smoothing_factor * spacing; }
};

// What a periodic width must hold for a kernel of smoothing length h: its support 2h and
// a fifth more for the growth of h and the Verlet skin (the loader's checks of the box).
inline double kernel_reach_with_margin(double h) {
  return 1.2 * kernel::kSupport * h;
}

struct SpeciesSpec {
  std::string name;
  // (m) A single-size species: the diameter of every sphere. With a size law: the Sauter
  // mean d32 of the law, a representative value only (the Kynch line, `check`); each
  // sphere carries its own radius in DemParticles.
  double diameter = 0.0;
  double density = 0.0;   // (kg/m^3)
  SizeDistribution size;  // law kSingle: every sphere has `diameter`

  bool monodisperse() const { return size.law == SizeLaw::kSingle; }
  double d_min() const { return monodisperse() ? diameter : size.min; }
  double d_max() const { return monodisperse() ? diameter : size.max; }
};

struct ParticleGroupSpec {
  enum class Kind { kSingle, kLattice, kRandom };
  Kind kind = Kind::kSingle;
  std::string species;                             // the species (random: the first of `mixture`)
  std::array<double, 3> position{0, 0, 0};         // single: centre
  std::array<double, 3> lo{0, 0, 0}, hi{0, 0, 0};  // lattice, random: region
  double voidage = 0.9;                            // lattice, random: target voidage of the region
  bool fcc = false;  // lattice: face-centred cubic (4 sites a cell, in (100) layers a/2 apart),
                     // else simple cubic
  std::vector<std::string> mixture;  // random: species names (one or more)
  std::vector<double> fractions;     // random: number fractions of `mixture` (sum 1)
  std::int64_t seed = 0;             // random: seed of the positions and diameters
  std::array<double, 3> velocity{0, 0, 0};
  double velocity_jitter = 0.0;    // each component + uniform in [-jitter, jitter] (m/s)
  std::int64_t velocity_seed = 1;  // seed of the jitter
  bool rigid = false;              // constant-porosity block: moves rigidly (thesis §4.5)
};

struct ContactSpec {
  // normal.k: a number, or auto (the default; scene/contact_stiffness_rule.hpp), which the
  // loader resolves and records in stiffness_reason.
  LinearSpringDashpot normal{10.0, 0.0, -1.0, false};
  double max_overlap = 0.01;     // the largest overlap / d the automatic stiffness allows
  std::string stiffness_reason;  // what auto chose and why (empty when the file gave k)
  TangentialParams tangential;   // model none unless the scene turns friction on
  RollingParams rolling;         // model none unless the scene turns rolling resistance on
  double skin = 0.3;             // Verlet skin as a fraction of the largest diameter
};

struct TimeSpec {
  double end = 0.02;                  // simulated time after release (s)
  double cfl = 0.25;                  // dt_SPH <= cfl h / v_sig (eq. 3.5 with support 2h)
  double dem_steps_per_contact = 20;  // dt_DEM <= t_c / this (eq. 3.7)
  // Spheres out of contact take the drag's step, not the contact's (DemSubstepper)
  bool multirate = true;
  // ... unless a neighbour or the wall is within this many times the farthest a sphere
  // goes in a half step at its start's speed and acceleration (below 2: always sent back)
  double multirate_margin = 4;
  double max_dt_sph = 1e-3;  // upper cap (s)
};

struct StartupSpec {
  int relax_steps = 200;  // fluid-only steps with spheres held, before t = 0
  double damping = 0.02;  // fraction of fluid velocity removed per relaxation step
};

struct OutputSpec {
  double log_interval = 0.0;       // (s); 0 = end / 200
  double progress_interval = 2.0;  // wall-clock seconds between terminal progress lines
  double vtk_every = 0.0;          // (s) between full .vtp snapshots + .pvd; 0 = none
};

// Checkpoints (run/checkpoints.hpp): DIR/checkpoints/ckpt_<step>.h5, the newest `keep`
// kept. One is due every `every` of simulated time and every `wall_interval` of wall
// time (0: not by that clock), at SIGINT/SIGTERM, and at the end of the run.
struct CheckpointSpec {
  double every = 0.0;             // (s) simulated time
  double wall_interval = 1800.0;  // (s) wall-clock time
  int keep = 2;
  bool at_end = true;
};

// The watchdog's bounds (analysis/watchdog.hpp), checked after every step.
struct WatchdogSpec {
  bool enabled = true;
  double density_error = 0.05;    // |rho/(eps rho0) - 1|: 5 times the weakly compressible 1 %
  double overlap = 0.2;           // largest overlap / d (the model's limit refuses 0.1 d expected)
  double safeguard_share = 0.01;  // share of the fluid held by the voidage floor or Omega clamp
};

// In-situ analysis through Catalyst (catalyst/, pipelines/).
struct InSituSpec {
  double every = 0.0;  // (s) between analyses; 0 = end / 50
  std::vector<std::string> pipelines{"voidage_height", "interfaces", "com_tracks", "snapshots"};
  int snapshot_every = 5;     // analyses between PNG snapshots
  double grid_spacing = 0.0;  // voidage grid spacing (m); 0 = fluid.spacing
  double reference_velocity =
      -1.0;  // Kynch line (m/s); < 0: none, 0: Di Felice of the first block or suspension
  bool enabled = true;
};

// Bidisperse voidage by double smoothing (thesis §3.4, 3.8-3.10): the big species are
// smoothed first with their own kernel, h_j = h_over_d d_j (3.9), onto the SPH
// particles, and that field is smoothed again with the fluid kernel (3.10).
struct DoubleSmoothingSpec {
  bool enabled = false;                  // false: the classic single smoothing (2.50)
  std::vector<std::string> big_species;  // default: the species with the largest diameter
  // h_b / d_big. The thesis takes h_b = 2 d_big with its kernel of support h (eq. 2.11),
  // i.e. h_b/h_s = d_big/dx; with our support 2h and h_s = 1.5 dx that ratio is h_b = 1.5 d_big.
  double h_over_d = 1.5;
};

// How the fluid pressure couples fluid and spheres.
//  interpolated (thesis 2.68-2.71): each sphere gets V_j (-grad P + div tau) interpolated
//    from the fluid's SPH acceleration, and the fluid gets it back with the drag, as the
//    mean over one SPH step. Where the voidage varies strongly (eps < ~0.75 next to clear
//    fluid: a packed bed) the fluid's SPH pressure term and the returned share do not
//    cancel at the kernel scale and the fluid is linearly unstable (ARCHITECTURE.md).
//  variational: the pressure forces derive from the fluid's internal energy
//    sum_a m_a e(rho_a / eps_a): the SPH pressure term carries eps P, the fluid gets
//    V_a P_a grad eps_a and the spheres the exact opposite, pair by pair, at once (so
//    rho_sup Du/Dt = -eps grad P, model A); only the drag goes through the step mean.
//    The viscous stress on the spheres, V div tau, is left out (it stays in the fluid).
//  hydrostatic_split (variational only): the pair forces carry P - P_h(z), the departure
//    from the hydrostatic pressure P_h = rho0 |g| (z_s - z), and P_h's own forces are
//    added analytically (-grad P_h / rho_intrinsic on the fluid, rho0 |g| V on a sphere).
//    Still the gradient of an energy, U + sum_a m_a P_h/rho_a' + sum_j V_j P_h(z_j), which
//    differs from U by the constant integral of P_h; the kernel-sum errors of the pair
//    forces then scale with P - P_h instead of the absolute P (coupling/pressure_coupling.hpp).
//  sphere_kernel_scale H/h (both couplings; default auto, scene/kernel_width_rule.hpp: h
//    for the interpolated coupling, 1, 1.25 or 1.5 for the variational one from the
//    scene's extra-drag ratio): each sphere's volume is spread with the kernel
//    at H = scale h_a in the voidage (2.50), the interpolation (2.69, 2.72), the reaction
//    (2.71) and the variational forces. Above 1 it smooths the hole a moving sphere carries
//    through the fluid particles: with the variational coupling a 2.8 mm grain's extra
//    drag, -8.3 % at c0 = 34 m/s with 1, is -0.5 % with 1.5; the price is smoother
//    voidage edges (cases/README.md).
//  drag_kernel_scale H_drag/h (<= sphere_kernel_scale; default equal to a given
//    sphere_kernel_scale, 1 under auto): the kernel the drag's
//    fields are gathered with -- the voidage it reads (2.50 again, as eps_drag), the fluid
//    velocity and the Shepard sums at the spheres (2.69, 2.72) -- and the reaction (2.71)
//    spreads with. The fluid's own voidage and the variational pressure forces keep
//    sphere_kernel_scale. The drag dissipates energy, so its kernel need not be the one
//    the pressure forces derive from.
enum class PressureCoupling { kInterpolated, kVariational };

struct Scene {
  std::string name = "scene";
  std::string description;
  std::string source = "<defaults>";  // file it came from (for error messages)
  Box box;
  std::array<double, 3> gravity{0, 0, -9.81};
  FluidSpec fluid;
  std::vector<SpeciesSpec> species;
  std::vector<ParticleGroupSpec> particles;
  ContactSpec contact;
  drag::DragLaw drag = drag::DiFeliceDallavalle{};  // drag.law, default di_felice
  double voidage_floor = 0.3;
  DoubleSmoothingSpec double_smoothing;
  PressureCoupling pressure_coupling = PressureCoupling::kInterpolated;
  bool hydrostatic_split = false;
  double sphere_kernel_scale = 1.0;  // H / h, see PressureCoupling
  double drag_kernel_scale = 1.0;    // H_drag / h, see PressureCoupling
  // The loader's record of coupling.sphere_kernel_scale: auto (scene/kernel_width_rule.hpp):
  // what it chose and why (empty when the file gave a number).
  std::string sphere_kernel_reason;
  std::string fidelity = "balanced";  // the preset (scene/fidelity.hpp)
  std::string fidelity_note;          // what the preset's resolution did to fluid.spacing
  TimeSpec time;
  StartupSpec startup;
  OutputSpec output;
  CheckpointSpec checkpoint;
  WatchdogSpec watchdog;
  InSituSpec insitu;

  double fill_height() const { return fluid.fill_height > 0 ? fluid.fill_height : box.length(2); }
  double gravity_magnitude() const {
    return std::sqrt(gravity[0] * gravity[0] + gravity[1] * gravity[1] + gravity[2] * gravity[2]);
  }
  int species_index(const std::string& name) const;
};

// A bad scene: names the file, the key and what is allowed.
struct SceneError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Reads and validates a scene; overrides are "key.path=value" (YAML value syntax).
Scene load_scene(const std::string& path, const std::vector<std::string>& overrides = {});
Scene load_scene_text(const std::string& yaml, const std::string& source_name,
                      const std::vector<std::string>& overrides = {});
// The fully resolved scene as YAML (written to DIR/case.yaml).
std::string scene_to_yaml(const Scene& scene);

}  // namespace sphdem
