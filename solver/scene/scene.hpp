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
#include "scene/scene_keys.hpp"
#include "scene/size_distribution.hpp"
#include "sph/kernel.hpp"

namespace sphdem {

// The keys' meanings, units, ranges and defaults are in the scene key table
// (scene/scene_keys.hpp); the members below start at the table's defaults.
struct FluidSpec {
  double density = scene_default("fluid.density");      // rho_f (kg/m^3)
  double viscosity = scene_default("fluid.viscosity");  // mu (Pa s)
  double spacing = scene_default("fluid.spacing");      // initial lattice spacing dx (m)
  double smoothing_factor = scene_default("fluid.smoothing_factor");  // sigma of (2.65)
  double fill_height = 0;     // free-surface height (m), resolved (0 in a file: the box height)
  double expected_speed = 0;  // u_m (m/s) for B, eq. 2.64, resolved
  double sound_speed = 0;     // c0 (m/s), resolved (scene_loader.cpp, physics.md §1)
  double sound_speed_factor = scene_default("fluid.sound_speed_factor");
  double resolution = 1;  // layers per `spacing`: dx = spacing / resolution (resolved to 1)
  double alpha_artificial = scene_default("fluid.alpha_artificial");    // Monaghan's alpha
  double density_diffusion = scene_default("fluid.density_diffusion");  // delta
  std::string density_diffusion_form = "auto";  // auto | renormalised | hydrostatic
  int gamma = static_cast<int>(scene_default("fluid.gamma"));
  int wall_layers = static_cast<int>(scene_default("fluid.wall_layers"));
  bool enabled = scene_default("fluid.enabled") != 0;  // false: dry DEM, no SPH particles

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
  double voidage = scene_default("particles.N.voidage");  // lattice, random: target voidage
  bool fcc = false;  // lattice: face-centred cubic (4 sites a cell, in (100) layers a/2 apart),
                     // else simple cubic
  std::vector<std::string> mixture;  // random: species names (one or more)
  std::vector<double> fractions;     // random: number fractions of `mixture` (sum 1)
  std::int64_t seed = 0;             // random: seed of the positions and diameters
  std::array<double, 3> velocity{0, 0, 0};
  double velocity_jitter = 0.0;  // each component + uniform in [-jitter, jitter] (m/s)
  std::int64_t velocity_seed =
      static_cast<std::int64_t>(scene_default("particles.N.velocity_seed"));
  bool rigid = false;  // constant-porosity block: moves rigidly (thesis §4.5)
  bool fixed = false;  // never moves (a fixed bed); implies rigid
};

struct ContactSpec {
  // normal.k: a number, or auto (the default; scene/contact_stiffness_rule.hpp), which the
  // loader resolves and records in stiffness_reason.
  LinearSpringDashpot normal;
  double max_overlap = scene_default("contact.max_overlap");  // the overlap / d auto allows
  std::string stiffness_reason;  // what auto chose and why (empty when the file gave k)
  TangentialParams tangential;   // model none unless the scene turns friction on
  RollingParams rolling;         // model none unless the scene turns rolling resistance on
  double skin = scene_default("contact.skin");  // Verlet skin / the largest diameter
};

struct TimeSpec {
  double end = scene_default("time.end");  // simulated time after release (s)
  double cfl = scene_default("time.cfl");  // dt_SPH <= cfl h / v_sig (eq. 3.5 with support 2h)
  double dem_steps_per_contact = scene_default("time.dem_steps_per_contact");  // (3.7)
  // Spheres out of contact take the drag's step, not the contact's (DemSubstepper)
  bool multirate = scene_default("time.multirate") != 0;
  // ... unless a neighbour or the wall is within this many times the farthest a sphere
  // goes in a half step at its start's speed and acceleration (below 2: always sent back)
  double multirate_margin = scene_default("time.multirate_margin");
  double max_dt_sph = scene_default("time.max_dt_sph");  // upper cap (s)
};

struct StartupSpec {
  int relax_steps = static_cast<int>(scene_default("startup.relax_steps"));
  double damping = scene_default("startup.damping");  // of the fluid velocity, per step
};

struct OutputSpec {
  double log_interval = 0;                                               // (s), resolved
  double progress_interval = scene_default("output.progress_interval");  // wall-clock (s)
  double vtk_every = scene_default("output.vtk.every");  // (s) between .vtp snapshots; 0 = none
};

// Checkpoints (run/checkpoints.hpp): DIR/checkpoints/ckpt_<step>.h5, the newest `keep`
// kept. One is due every `every` of simulated time and every `wall_interval` of wall
// time (0: not by that clock), at SIGINT/SIGTERM, and at the end of the run.
struct CheckpointSpec {
  double every = scene_default("checkpoint.every");                  // (s) simulated time
  double wall_interval = scene_default("checkpoint.wall_interval");  // (s) wall-clock time
  int keep = static_cast<int>(scene_default("checkpoint.keep"));
  bool at_end = scene_default("checkpoint.at_end") != 0;
};

// The watchdog's bounds (analysis/watchdog.hpp), checked after every step. The density
// bound's auto: kDensityAlarmFactor x the expected density error of c0, at least the
// weakly compressible limit kDensityAlarmFloor and at most twice it (a c0 past the limit,
// which `check` refuses, still alarms there).
inline constexpr double kDensityAlarmFloor = 0.01;
inline constexpr double kDensityAlarmFactor = 2.0;
struct WatchdogSpec {
  bool enabled = scene_default("watchdog.enabled") != 0;
  // |rho/(eps rho0) - 1|; auto: resolved by the loader (kDensityAlarm*), the floor until then
  double density_error = kDensityAlarmFloor;
  double overlap = scene_default("watchdog.overlap");  // largest overlap / d
  // share of the fluid held by the voidage floor or Omega clamp
  double safeguard_share = scene_default("watchdog.safeguard_share");
};

// In-situ analysis through Catalyst (catalyst/, pipelines/).
struct InSituSpec {
  double every = 0;                    // (s) between analyses, resolved
  std::vector<std::string> pipelines;  // names of kInSituPipelines (scene/insitu_pipelines.hpp)
  int snapshot_every = static_cast<int>(scene_default("insitu.snapshot_every"));  // analyses
  double grid_spacing = 0;        // voidage grid spacing (m), resolved
  double reference_velocity = 0;  // Kynch line (m/s), resolved: < 0 none
  bool enabled = scene_default("insitu.enabled") != 0;
};

// Bidisperse voidage by double smoothing (thesis §3.4, 3.8-3.10): the big species are
// smoothed first with their own kernel, h_j = h_over_d d_j (3.9), onto the SPH
// particles, and that field is smoothed again with the fluid kernel (3.10).
struct DoubleSmoothingSpec {
  bool enabled = false;                  // false: the classic single smoothing (2.50)
  std::vector<std::string> big_species;  // default: the species with the largest diameter
  // h_b / d_big. The thesis takes h_b = 2 d_big with its kernel of support h (eq. 2.11),
  // i.e. h_b/h_s = d_big/dx; with our support 2h and h_s = 1.5 dx that ratio is h_b = 1.5 d_big.
  double h_over_d = scene_default("coupling.big_h_over_d");
};

// How the fluid pressure couples fluid and spheres (coupling.pressure_coupling; the forms
// and why the defaults are what they are: cases/README.md, "drag, coupling").
//  interpolated (thesis 2.68-2.71): each sphere gets V_j (-grad P + div tau) interpolated
//    from the fluid's SPH acceleration, and the fluid gets it back with the drag, as the
//    mean over one SPH step.
//  variational: the pressure forces derive from the fluid's internal energy
//    sum_a m_a e(rho_a / eps_a): the SPH pressure term carries eps P, the fluid gets
//    V_a P_a grad eps_a and the spheres the exact opposite, pair by pair (so
//    rho_sup Du/Dt = -eps grad P, model A); only the drag goes through the step mean.
//    The viscous stress on the spheres, V div tau, is left out (it stays in the fluid).
//  hydrostatic_split (variational only): the pair forces carry P - P_h(z) and P_h's own
//    forces are added analytically (coupling/pressure_coupling.hpp).
//  sphere_kernel_scale H/h: each sphere's volume is spread with the kernel at H = scale
//    h_a in the voidage (2.50), the interpolation (2.69, 2.72), the reaction (2.71) and
//    the variational forces; drag_kernel_scale H_drag/h <= it: the kernel the drag's
//    fields are gathered with (eps_drag, u_f and the Shepard sums at the spheres) and the
//    reaction spreads with.
enum class PressureCoupling { kInterpolated, kVariational };

// The imposed flow of a column periodic in z (flow.*): U(t) piecewise linear through
// (times[k], superficial_velocity[k]), held after the last time.
struct FlowSpec {
  std::vector<double> times{0.0};
  std::vector<double> superficial_velocity{0.0};
  bool distributor = false;  // the spheres' bottom wall at z = 0
  double top_plane = 0;      // height of the plane holding what the flow lifts (0: none)
};

struct Scene {
  std::string name{scene_key("name").text};
  std::string description;
  std::string source = "<defaults>";  // file it came from (for error messages)
  Box box;
  std::array<double, 3> gravity{0, 0, -9.81};
  FluidSpec fluid;
  std::vector<SpeciesSpec> species;
  std::vector<ParticleGroupSpec> particles;
  ContactSpec contact;
  drag::DragLaw drag = drag::drag_law_named(std::string(scene_key("drag.law").text));
  double voidage_floor = scene_default("coupling.voidage_floor");
  DoubleSmoothingSpec double_smoothing;
  PressureCoupling pressure_coupling = PressureCoupling::kInterpolated;
  bool hydrostatic_split = false;
  double sphere_kernel_scale = 1;      // H / h, see PressureCoupling (resolved)
  double drag_kernel_scale = 1;        // H_drag / h, see PressureCoupling (resolved)
  bool drag_upstream = false;          // coupling.drag_upstream (interpolation.hpp)
  bool drag_voidage_upstream = false;  // coupling.drag_voidage_upstream (voidage.hpp)
  // The loader's record of coupling.sphere_kernel_scale: auto (scene/kernel_width_rule.hpp):
  // what it chose and why (empty when the file gave a number).
  std::string sphere_kernel_reason;
  std::string fidelity{scene_key("fidelity").text};  // the preset (scene/fidelity.hpp)
  std::string fidelity_note;  // what the preset's resolution did to fluid.spacing
  TimeSpec time;
  StartupSpec startup;
  OutputSpec output;
  CheckpointSpec checkpoint;
  WatchdogSpec watchdog;
  InSituSpec insitu;
  FlowSpec flow;  // read only with box.periodic[2]

  bool periodic_z() const { return box.periodic[2]; }
  double fill_height() const { return fluid.fill_height > 0 ? fluid.fill_height : box.length(2); }
  // Resolved by the loader in a column periodic in z with a distributor: the bed's buoyant
  // weight per area as a height of fluid, sum_groups (1 - eps_g) V_g (rho_p - rho_f) / (rho_f A).
  // The mean gradient G carries the column's mean load; the SPH pressure carries the bed's
  // share of it, which it can only do within its density error (c0, `check`).
  double bed_head = 0;
  // The height of fluid whose weight the SPH pressure carries (the hydrostatic start,
  // sqrt(2 g H) in c0): the column's fill height, or in a column periodic in z the bed's
  // head (0 without a distributor: a suspension's weight is all G's).
  double hydrostatic_height() const { return periodic_z() ? bed_head : fill_height(); }
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
