#include "run/simulation.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <variant>

#include "coupling/fluid_force.hpp"
#include "coupling/pressure_coupling.hpp"
#include "coupling/interpolation.hpp"
#include "coupling/reaction.hpp"
#include "coupling/double_smoothing.hpp"
#include "coupling/voidage.hpp"
#include "dem/rotation.hpp"
#include "domain/reorder.hpp"
#include "run/initial_state.hpp"
#include "run/pore_pressure.hpp"
#include "sph/density_rate.hpp"
#include "sph/kernel.hpp"
#include "sph/momentum.hpp"

namespace sphdem {

namespace {

using Clock = std::chrono::steady_clock;

// Adds the time since `start` to one pass timer, and restarts it.
struct Lap {
  PassTimers& t;
  Clock::time_point start = Clock::now();
  void operator()(int pass) {
    const auto now = Clock::now();
    t.seconds[pass] += std::chrono::duration<double>(now - start).count();
    start = now;
  }
};
enum Pass { kIntegrate, kDem, kNeighbours, kVoidage, kDensity, kMomentum, kInterp, kReaction, kOther };

// Verlet skin of the fluid's lists (fluid-fluid and fluid-sphere), in units of the
// largest h at the build: the lists hold the pairs within support + skin and are rebuilt
// once the particles' displacements and the growth of h have used the skin up.
constexpr double kFluidSkin = 0.2;
// Below this many spheres the DEM sub-step loops run on one thread: a parallel region
// costs more than the work (a single settling sphere takes ~10^5 sub-steps).
constexpr long kMinParallelSpheres = 256;

}  // namespace

Simulation::Simulation(const Scene& scene) : scene_(scene) {
  const FluidSpec& fs = scene_.fluid;
  eos_ = TaitEquationOfState::from_sound_speed(fs.density, fs.sound_speed, fs.gamma);
  drag_fluid_ = drag::Fluid{fs.density, fs.viscosity};
  place_particles(scene_, fluid_, dem_);

  // DEM time step: dt_DEM <= t_c / 20 over every pair of species and the wall (3.7),
  // and well below the Stokes relaxation time m/(3 pi mu d) of the lightest sphere.
  // A species with a size law counts with its smallest sphere (shortest t_c, 2.44).
  const LinearSpringDashpot& law = scene_.contact.normal;
  t_contact_ = std::numeric_limits<double>::infinity();
  double t_drag = std::numeric_limits<double>::infinity();
  std::vector<double> masses;
  for (const auto& sp : scene_.species) {
    const double d = sp.d_min();
    const double m = sp.density * M_PI * std::pow(d, 3) / 6.0;
    masses.push_back(m);
    t_drag = std::min(t_drag, m / (3.0 * M_PI * fs.viscosity * d));
  }
  for (std::size_t a = 0; a < masses.size(); ++a) {
    auto consider = [&](double m12) {
      const ContactClosedForm c(law.k, law.beta_for(m12), m12);
      if (!(c.omega > 0))
        throw SceneError(fmt::format("{}: key 'contact.damping': overdamped contact (eta >= omega0) "
                                     "for species '{}'", scene_.source, scene_.species[a].name));
      t_contact_ = std::min(t_contact_, c.contact_time());
    };
    consider(masses[a]);  // wall
    for (std::size_t b = a; b < masses.size(); ++b) consider(masses[a] * masses[b] / (masses[a] + masses[b]));
  }
  // The contact law (contact_registry.hpp); tangential or rolling parts turn on the
  // contact history and the spheres' rotation.
  try {
    contact_law_ = make_contact_law(ContactParams{law, scene_.contact.tangential, scene_.contact.rolling});
  } catch (const std::invalid_argument& e) {
    throw SceneError(fmt::format("{}: key 'contact.rolling': {}", scene_.source, e.what()));
  }
  rotation_ = contact_law_has_history(contact_law_);
  // With tangential friction, dt_DEM also resolves the undamped period of a sticking
  // contact, pi sqrt(m_t/k_t) with m_t = 2/7 m12 (the normal one for k_t = 2/7 k). The
  // rolling spring is slower (k_r/I_r <= 0.8 mu_r^2 k/m for equal spheres).
  if (scene_.contact.tangential.model != TangentialParams::Model::kNone) {
    const double kt = scene_.contact.tangential.stiffness_ratio * law.k;
    for (std::size_t a = 0; a < masses.size(); ++a) {
      t_contact_ = std::min(t_contact_, M_PI * std::sqrt(2.0 / 7.0 * masses[a] / kt));  // wall
      for (std::size_t b = a; b < masses.size(); ++b)
        t_contact_ = std::min(t_contact_, M_PI * std::sqrt(2.0 / 7.0 * masses[a] * masses[b] / (masses[a] + masses[b]) / kt));
    }
  }
  dt_dem_max_ = std::min(t_contact_ / scene_.time.dem_steps_per_contact, 0.1 * t_drag);
  if (scene_.double_smoothing.enabled) {  // (3.8-3.10)
    is_big_species_.assign(scene_.species.size(), 0);
    double d_big = 0.0;
    for (const auto& name : scene_.double_smoothing.big_species) {
      const int k = scene_.species_index(name);
      is_big_species_[k] = 1;
      d_big = std::max(d_big, scene_.species[k].d_max());
    }
    big_cutoff_ = kernel::kSupport * scene_.double_smoothing.h_over_d * d_big;
  }

  n_groups_ = 0;
  for (std::size_t i = 0; i < dem_.size(); ++i) n_groups_ = std::max(n_groups_, dem_.rigid_group[i] + 1);
  group_fx_.assign(n_groups_, 0);
  group_fy_.assign(n_groups_, 0);
  group_fz_.assign(n_groups_, 0);
  group_m_.assign(n_groups_, 0);

  build_initial_state();
}

std::size_t Simulation::fluid_count() const {
  return static_cast<std::size_t>(std::count(fluid_.kind.begin(), fluid_.kind.begin() + fluid_.n_owned, kFluid));
}
std::size_t Simulation::wall_count() const { return fluid_.n_owned - fluid_count(); }

double Simulation::fluid_cutoff() const {
  double hmax = 0;
  for (std::size_t a = 0; a < fluid_.n_owned; ++a) hmax = std::max(hmax, fluid_.h[a]);
  if (hmax == 0.0) {  // no fluid (dry DEM): bin at the contact reach instead
    double rmax = 0;
    for (std::size_t i = 0; i < dem_.n_owned; ++i) rmax = std::max(rmax, dem_.radius[i]);
    return std::max(2.0 * rmax * (1.0 + scene_.contact.skin), 1e-12);
  }
  return kernel::kSupport * hmax;
}

// Hydrostatic start (replaces most of the thesis' ~1000 relaxation steps): on the
// lattice, m_a/rho_a = dx^3 exactly, and rho_a = eps_a rho0 (1 + rho0 g (H - z)/B)^(1/gamma)
// is the Tait density of the hydrostatic pressure at the particle's voidage.
void Simulation::build_initial_state() {
  const double dx = scene_.fluid.spacing, dx3 = dx * dx * dx;
  const double g = std::abs(scene_.gravity[2]);
  const double H = scene_.fill_height();
  for (std::size_t a = 0; a < fluid_.n_owned; ++a) {
    fluid_.h[a] = scene_.fluid.smoothing_factor * dx;
    fluid_.inv_h[a] = 1.0 / fluid_.h[a];
    fluid_.eps[a] = 1.0;
  }
  for (std::size_t a = 0; a < fluid_.n_owned; ++a) {  // m/rho = dx^3 for the double smoothing (3.10)
    fluid_.rho[a] = eos_.rho0;
    fluid_.mass[a] = eos_.rho0 * dx3;
  }
  rebuild_neighbours();
  compute_voidage();
  for (std::size_t a = 0; a < fluid_.n_owned; ++a) {
    const double P = eos_.rho0 * g * (H - fluid_.z[a]);
    fluid_.rho[a] = eos_.density(P, fluid_.eps[a]);
    fluid_.mass[a] = fluid_.rho[a] * dx3;
  }
  refresh();
  next_dt();
}

// A halo of at least `needed`, and up to `wanted` where the periodic box allows.
double Simulation::halo_width(double needed, double wanted) const {
  double width = std::max(needed, wanted);
  for (int d = 0; d < 3; ++d)
    if (scene_.box.periodic[d]) width = std::min(width, std::max(needed, scene_.box.length(d)));
  return width;
}

// Every list anew: the fluid's halo, cells and half pair list at 2 h_max + skin, then the
// spheres' (rebuild_contact_neighbours) and the fluid-sphere pairs.
void Simulation::rebuild_neighbours() {
  FluidParticles& f = fluid_;
  const Box& box = scene_.box;
  // Owned particles back into the box; halo copies of those near periodic faces.
  for (std::size_t a = 0; a < f.n_owned; ++a) {
    f.x[a] = box.wrap(0, f.x[a]);
    f.y[a] = box.wrap(1, f.y[a]);
  }
  const double support = fluid_cutoff();
  hmax_at_build_ = f.n_owned > 0 ? support / kernel::kSupport : 0.0;
  fluid_skin_ = kFluidSkin * hmax_at_build_;
  cell_size_ = support + fluid_skin_;
  f.resize(f.n_owned);
  fluid_halo_.build(box, halo_width(support, cell_size_), f.x.data(), f.y.data(), f.z.data(),
                    f.n_owned);
  f.resize(f.n_owned + fluid_halo_.n_ghost());
  fluid_halo_.fill_positions(f.x.data(), f.y.data(), f.z.data());
  for (auto* v : {&f.vx, &f.vy, &f.vz, &f.mass, &f.h, &f.inv_h, &f.rho, &f.eps}) fluid_halo_.fill(*v);
  fluid_halo_.fill(f.kind);
  fluid_halo_.fill(f.id);
  fluid_cells_.build(f.x.data(), f.y.data(), f.z.data(), f.size(), cell_size_, 2);
  fluid_pairs_.build(fluid_cells_, f.x.data(), f.y.data(), f.z.data(), f.n_owned, cell_size_, true, /*half=*/true);
  xr_.assign(f.x.begin(), f.x.begin() + f.n_owned);
  yr_.assign(f.y.begin(), f.y.begin() + f.n_owned);
  zr_.assign(f.z.begin(), f.z.begin() + f.n_owned);
  fluid_lists_stale_ = false;
  ++neighbour_builds_;
  rebuild_contact_neighbours();
  build_sphere_pairs();
}

// Verlet criteria (the lists were built at 2 h_max + skin, the fluid-sphere pairs at
// 2 H_max + skin with H = scale h):
//  - fluid pairs: 2 max|x - x_build| + 2 (h_max - h_max,build) <= skin;
//  - fluid-sphere pairs: max|x - x_build| + max|x_j - x_j,halo| + 2 scale (h_max - h_max,build)
//    <= skin, with the spheres' displacement since their halo was built;
// otherwise the lists are rebuilt. Between rebuilds the halo copies are refreshed.
void Simulation::update_neighbours() {
  FluidParticles& f = fluid_;
  const DemParticles& s = dem_;
  const long nf = static_cast<long>(f.n_owned), ns = static_cast<long>(s.n_owned);
  if (fluid_lists_stale_ || static_cast<long>(xr_.size()) != nf) {
    rebuild_neighbours();
    return;
  }
  double hmax = 0.0, df2 = 0.0, ds2 = 0.0;
#pragma omp parallel for schedule(static) reduction(max : hmax, df2)
  for (long a = 0; a < nf; ++a) {
    hmax = std::max(hmax, f.h[a]);
    const double dx = f.x[a] - xr_[a], dy = f.y[a] - yr_[a], dz = f.z[a] - zr_[a];
    df2 = std::max(df2, dx * dx + dy * dy + dz * dz);
  }
#pragma omp parallel for schedule(static) reduction(max : ds2) if (ns > kMinParallelSpheres)
  for (long j = 0; j < ns; ++j) {
    const double dx = s.x[j] - s.x0[j], dy = s.y[j] - s.y0[j], dz = s.z[j] - s.z0[j];
    ds2 = std::max(ds2, dx * dx + dy * dy + dz * dz);
  }
  const double growth = kernel::kSupport * std::max(0.0, hmax - hmax_at_build_);
  const double df = std::sqrt(df2), ds = std::sqrt(ds2);
  if (2.0 * df + growth > fluid_skin_) {
    rebuild_neighbours();
    return;
  }
  fluid_halo_.fill_positions(f.x.data(), f.y.data(), f.z.data());
  for (auto* v : {&f.vx, &f.vy, &f.vz, &f.h, &f.inv_h, &f.rho}) fluid_halo_.fill(*v);
  if (scene_.double_smoothing.enabled)  // its re-smoothing walks the fluid's cells (3.10)
    fluid_cells_.build(f.x.data(), f.y.data(), f.z.data(), f.size(), cell_size_, 2);
  if (nf > 0 && !sphere_pairs_stale_ && df + ds + scene_.sphere_kernel_scale * growth > fluid_skin_)
    rebuild_contact_neighbours();  // a new sphere halo, so that it covers the new pairs
  if (sphere_pairs_stale_) build_sphere_pairs();
}

// The fluid-sphere Verlet list, from the spheres (owned + halo) binned now.
void Simulation::build_sphere_pairs() {
  const DemParticles& s = dem_;
  sphere_pairs_stale_ = false;
  if (fluid_.n_owned == 0) return;  // dry DEM
  const double cut = fluid_sphere_cutoff();
  dem_cells_.build(s.x.data(), s.y.data(), s.z.data(), s.size(), cut, 2);
  sphere_pairs_.build_list(fluid_, dem_cells_, scene_.sphere_kernel_scale, cut);
}

double Simulation::fluid_sphere_cutoff() const {
  return scene_.sphere_kernel_scale * kernel::kSupport * hmax_at_build_ + fluid_skin_;
}

// Sphere halo (wide enough for the fluid kernel and for contacts), the sphere cells
// at the fluid cut-off, and the contact list at its own cut-off.
// With tangential or rolling parts, the contact history goes to its id-keyed store
// before the list changes and comes back aligned with the new list.
void Simulation::rebuild_contact_neighbours() {
  DemParticles& s = dem_;
  const Box& box = scene_.box;
  if (rotation_) contact_history_.save(s, contacts_);  // no-op if already saved (a sort)
  for (std::size_t i = 0; i < s.n_owned; ++i) {
    s.x[i] = box.wrap(0, s.x[i]);
    s.y[i] = box.wrap(1, s.y[i]);
    s.x0[i] = s.x[i];
    s.y0[i] = s.y[i];
    s.z0[i] = s.z[i];
  }
  double rmax = 0;
  for (std::size_t i = 0; i < s.n_owned; ++i) rmax = std::max(rmax, s.radius[i]);
  const double skin = scene_.contact.skin * 2.0 * rmax;
  const double contact_cut = 2.0 * rmax + skin;
  s.resize(s.n_owned);
  // (the big spheres' own kernel of the double smoothing reaches further, plus the skin
  // they may move before the next rebuild)
  const double needed = std::max(
      {scene_.sphere_kernel_scale * kernel::kSupport * hmax_at_build_, 2.0 * rmax, big_cutoff_});
  const double wanted =
      std::max({fluid_sphere_cutoff(), contact_cut, big_cutoff_ > 0 ? big_cutoff_ + skin : 0.0});
  dem_halo_.build(box, halo_width(needed, wanted), s.x.data(), s.y.data(), s.z.data(), s.n_owned);
  s.resize(s.n_owned + dem_halo_.n_ghost());
  dem_halo_.fill_positions(s.x.data(), s.y.data(), s.z.data());
  for (auto* v : {&s.vx, &s.vy, &s.vz, &s.radius, &s.mass}) dem_halo_.fill(*v);
  dem_halo_.fill(s.id);
  if (rotation_)
    for (auto* v : {&s.wx, &s.wy, &s.wz}) dem_halo_.fill(*v);
  if (s.n_owned > 0) {
    contact_cells_.build(s.x.data(), s.y.data(), s.z.data(), s.size(), contact_cut);
    contacts_.build(s, contact_cells_, skin);
  }
  if (rotation_) contact_history_.load(s, contacts_);
  sphere_pairs_stale_ = true;  // its indices point into the old halo
}

// The fluid-sphere pairs of this step and the voidage (2.50), or with double smoothing
// the small spheres' part (3.8) plus the big spheres smoothed apart (3.9) and again
// with the fluid kernel (3.10).
void Simulation::compute_voidage() {
  FluidParticles& f = fluid_;
  const DemParticles& s = dem_;
  sphere_pairs_.evaluate(f, s, scene_.pressure_coupling == PressureCoupling::kVariational);
  if (!scene_.double_smoothing.enabled) {
    voidage_clamped_ = compute_fluid_voidage(f, s, sphere_pairs_, scene_.voidage_floor);
    return;
  }
  big_cells_.build(s.x.data(), s.y.data(), s.z.data(), s.size(), big_cutoff_);
  smooth_big_spheres(f, s, big_cells_, is_big_species_, scene_.double_smoothing.h_over_d, big_fraction_);
  fluid_halo_.fill(big_fraction_.phi);
  fluid_halo_.fill(big_fraction_.phi_over_d);
  resmooth_with_fluid_kernel(f, fluid_cells_, big_fraction_, big_solid_, big_solid_over_d_);
  const BigSpheresSmoothedApart big{is_big_species_, big_solid_, big_solid_over_d_};
  voidage_clamped_ = compute_fluid_voidage(f, s, sphere_pairs_, scene_.voidage_floor, &big);
}

void Simulation::update_smoothing_length() {
  FluidParticles& f = fluid_;
  const double sigma = scene_.fluid.smoothing_factor;
  const long n = static_cast<long>(f.n_owned);
#pragma omp parallel for schedule(static)
  for (long a = 0; a < n; ++a) {
    f.h[a] = sigma * std::cbrt(f.mass[a] / f.rho[a]);  // (2.65)
    f.inv_h[a] = 1.0 / f.h[a];
  }
}

void Simulation::update_pressure() {
  FluidParticles& f = fluid_;
  const long n = static_cast<long>(f.n_owned);
#pragma omp parallel for schedule(static)
  for (long a = 0; a < n; ++a) {
    f.P[a] = eos_.pressure(f.rho[a], f.eps[a]);      // (2.58)
    f.cs[a] = eos_.sound_speed(f.rho[a], f.eps[a]);  // (2.59)
  }
  fluid_halo_.fill(f.P);
  fluid_halo_.fill(f.cs);
}

void Simulation::refresh() {
  fluid_lists_stale_ = true;
  compute_fluid_side(true);
  dem_forces(false, 0.0);
}

// Passes that follow the drift: voidage -> density rate -> pressure -> theta ->
// interpolation at spheres -> reaction on the fluid. Leaves (ax, ay, az) complete.
void Simulation::compute_fluid_side(bool hold_spheres) {
  FluidParticles& f = fluid_;
  DemParticles& s = dem_;
  Lap lap{timers_};
  update_smoothing_length();
  lap(kIntegrate);
  update_neighbours();
  lap(kNeighbours);
  compute_voidage();
  fluid_halo_.fill(f.eps);
  lap(kVoidage);
  update_pressure();
  const bool variational = scene_.pressure_coupling == PressureCoupling::kVariational;
  omega_bounded_ = compute_density_rate(f, fluid_pairs_, pair_scratch_, variational, hydrostatic_split());
  fluid_halo_.fill(f.omega);
  fluid_halo_.fill(f.p_term);
  lap(kDensity);
  compute_fluid_acceleration(f, fluid_pairs_,
                             MomentumParams{scene_.fluid.viscosity, scene_.fluid.alpha_artificial, scene_.time.cfl},
                             pair_scratch_);
  for (auto* v : {&f.thx, &f.thy, &f.thz}) fluid_halo_.fill(*v);
  const auto& g = scene_.gravity;
  const long n = static_cast<long>(f.n_owned);
#pragma omp parallel for schedule(static)
  for (long a = 0; a < n; ++a) {
    const bool mobile = f.kind[a] == kFluid;
    f.ax[a] = mobile ? f.thx[a] + g[0] : 0.0;
    f.ay[a] = mobile ? f.thy[a] + g[1] : 0.0;
    f.az[a] = mobile ? f.thz[a] + g[2] : 0.0;
  }
  lap(kMomentum);
  interpolate_fluid_at_spheres(s, f, sphere_pairs_, dem_halo_.source(), sphere_scratch_);
  if (variational) apply_variational_pressure(hold_spheres);
  lap(kInterp);
  if (hold_spheres) {
    // Held spheres: the force they feel now is what the fluid gets back (with the
    // variational coupling the pressure part has been returned already, pair by pair).
    dem_forces(false, 0.0);
    for (std::size_t j = 0; j < s.n_owned; ++j) {
      const double vp = variational ? s.volume(j) : 0.0;
      s.fmx[j] = s.fx[j] - vp * s.gx[j];
      s.fmy[j] = s.fy[j] - vp * s.gy[j];
      s.fmz[j] = s.fz[j] - vp * s.gz[j];
    }
  }
  for (auto* v : {&s.fmx, &s.fmy, &s.fmz, &s.shepard}) dem_halo_.fill(*v);
  add_reaction_on_fluid(f, s, sphere_pairs_);
  lap(kReaction);
}

// Sums force(j) over the spheres of each rigid group into group_f*_, and their masses
// into group_m_.
template <class Force>
void Simulation::sum_over_rigid_groups(Force force) {
  const DemParticles& s = dem_;
  std::fill(group_fx_.begin(), group_fx_.end(), 0.0);
  std::fill(group_fy_.begin(), group_fy_.end(), 0.0);
  std::fill(group_fz_.begin(), group_fz_.end(), 0.0);
  std::fill(group_m_.begin(), group_m_.end(), 0.0);
  for (long j = 0; j < static_cast<long>(s.n_owned); ++j) {
    const int gr = s.rigid_group[j];
    if (gr < 0) continue;
    double fx, fy, fz;
    force(j, fx, fy, fz);
    group_fx_[gr] += fx;
    group_fy_[gr] += fy;
    group_fz_[gr] += fz;
    group_m_[gr] += s.mass[j];
  }
}

// The hydrostatic pressure the variational coupling splits off (scene key
// coupling.hydrostatic_split), the one of the hydrostatic start; zero without the key.
HydrostaticPressure Simulation::hydrostatic_split() const {
  if (!scene_.hydrostatic_split) return {};
  return HydrostaticPressure{eos_.rho0, scene_.gravity[2], scene_.fill_height()};
}

// Variational pressure coupling (coupling/pressure_coupling.hpp): the fluid gets its
// share now, the spheres' g becomes their pressure force / V. Between two evaluations
// a sphere must feel one constant pressure force, so that what it receives over the
// window of the step mean is what the fluid got: the force and acceleration of the last
// sub-step (the 'old' ones of the next trapezoid) switch to the new g here.
void Simulation::apply_variational_pressure(bool hold_spheres) {
  DemParticles& s = dem_;
  const long n = static_cast<long>(s.n_owned);
  g_old_x_.assign(s.gx.begin(), s.gx.begin() + n);
  g_old_y_.assign(s.gy.begin(), s.gy.begin() + n);
  g_old_z_.assign(s.gz.begin(), s.gz.begin() + n);
  walls_on_spheres_z_ =
      couple_pressure_variationally(fluid_, s, sphere_pairs_, dem_halo_.source(), sphere_scratch_, hydrostatic_split());
  if (hold_spheres) return;
#pragma omp parallel for schedule(static) if (n > kMinParallelSpheres)
  for (long j = 0; j < n; ++j) {
    const double V = s.volume(j), inv_m = 1.0 / s.mass[j];
    const double dfx = V * (s.gx[j] - g_old_x_[j]), dfy = V * (s.gy[j] - g_old_y_[j]),
                 dfz = V * (s.gz[j] - g_old_z_[j]);
    s.fx[j] += dfx;
    s.fy[j] += dfy;
    s.fz[j] += dfz;
    if (s.rigid_group[j] >= 0) continue;  // below: the group's share
    s.ax[j] += dfx * inv_m;
    s.ay[j] += dfy * inv_m;
    s.az[j] += dfz * inv_m;
  }
  if (n_groups_ == 0) return;
  sum_over_rigid_groups([&](long j, double& fx, double& fy, double& fz) {
    const double V = s.volume(j);
    fx = V * (s.gx[j] - g_old_x_[j]);
    fy = V * (s.gy[j] - g_old_y_[j]);
    fz = V * (s.gz[j] - g_old_z_[j]);
  });
  for (long j = 0; j < n; ++j) {
    const int gr = s.rigid_group[j];
    if (gr < 0) continue;
    s.ax[j] += group_fx_[gr] / group_m_[gr];
    s.ay[j] += group_fy_[gr] / group_m_[gr];
    s.az[j] += group_fz_[gr] / group_m_[gr];
  }
}

// Fluid force (2.68) and contact force (2.36, with the tangential and rolling parts of
// the scene's contact law) on each owned sphere, then the acceleration (2.35); rigid
// groups share their total force equally (thesis §4.5). With accumulate_mean, adds
// weight * (fluid force) to the step-mean force fm. dt_springs: time by which the
// tangential and rolling springs advance (the sub-step; 0 for an evaluation that is
// not a step).
void Simulation::dem_forces(bool accumulate_mean, double weight, double dt_springs) {
  DemParticles& s = dem_;
  if (s.n_owned == 0) return;
  compute_contact_forces(s, contacts_, contact_law_, contact_history_, dem_halo_.images(), 0.0, dt_springs);
  const long n = static_cast<long>(s.n_owned);
  const bool variational = scene_.pressure_coupling == PressureCoupling::kVariational;
  const auto& g = scene_.gravity;
  std::visit(
      [&](const auto& law) {
#pragma omp parallel for schedule(static) if (n > kMinParallelSpheres)
        for (long j = 0; j < n; ++j) {
          double fx, fy, fz;
          fluid_force_on_sphere(s, j, law, drag_fluid_, fx, fy, fz);
          if (accumulate_mean) {  // trapezoidal impulse of this sub-step: 0.5 dt (f_old + f_new)
            // (with the variational coupling the constant pressure part 2 V g is not in it)
            const double vp2 = variational ? 2.0 * s.volume(j) : 0.0;
            s.fmx[j] += weight * (s.fx[j] + fx - vp2 * s.gx[j]);
            s.fmy[j] += weight * (s.fy[j] + fy - vp2 * s.gy[j]);
            s.fmz[j] += weight * (s.fz[j] + fz - vp2 * s.gz[j]);
          }
          s.fx[j] = fx;
          s.fy[j] = fy;
          s.fz[j] = fz;
          const double inv_m = 1.0 / s.mass[j];
          s.ax[j] = (s.cx[j] + fx) * inv_m + g[0];
          s.ay[j] = (s.cy[j] + fy) * inv_m + g[1];
          s.az[j] = (s.cz[j] + fz) * inv_m + g[2];
        }
      },
      scene_.drag);
  if (n_groups_ == 0) return;
  sum_over_rigid_groups([&](long j, double& fx, double& fy, double& fz) {
    fx = s.ax[j] * s.mass[j];
    fy = s.ay[j] * s.mass[j];
    fz = s.az[j] * s.mass[j];
  });
  for (long j = 0; j < n; ++j) {
    const int gr = s.rigid_group[j];
    if (gr < 0) continue;
    s.ax[j] = group_fx_[gr] / group_m_[gr];
    s.ay[j] = group_fy_[gr] / group_m_[gr];
    s.az[j] = group_fz_[gr] / group_m_[gr];
  }
}

// DEM over one half of an SPH step: velocity-Verlet sub-steps with the fluid fields
// at the spheres held fixed (physics.md §4). The fluid impulse of the second half of
// one step and the first half of the next make the mean force fm that the fluid gets
// back at the next evaluation, so every impulse is returned exactly once.
void Simulation::dem_half(double dt, bool first_half) {
  DemParticles& s = dem_;
  if (s.n_owned == 0) return;
  const long n = static_cast<long>(s.n_owned);
  const int per_half = std::max(1, static_cast<int>(std::ceil(0.5 * dt / dt_dem_max_)));
  const double h = 0.5 * dt / per_half;
  dt_dem_ = h;
  dem_substeps_ = 2 * per_half;
  if (!first_half) {  // start the window of the next mean force
    std::fill(s.fmx.begin(), s.fmx.end(), 0.0);
    std::fill(s.fmy.begin(), s.fmy.end(), 0.0);
    std::fill(s.fmz.begin(), s.fmz.end(), 0.0);
  }
  const double half_skin = 0.5 * contacts_.skin;
  a_old_x_.resize(n);
  a_old_y_.resize(n);
  a_old_z_.resize(n);
  for (int k = 0; k < per_half; ++k) {
    double max_disp2 = 0.0;
    const double finish = k > 0 ? 0.5 * h : 0.0;  // the previous sub-step's corrector, fused
#pragma omp parallel for schedule(static) reduction(max : max_disp2) if (n > kMinParallelSpheres)
    for (long j = 0; j < n; ++j) {
      // v_n + h (a_old + a_new)/2 of the sub-step before (below for the last one)
      s.vx[j] += finish * (s.ax[j] - a_old_x_[j]);
      s.vy[j] += finish * (s.ay[j] - a_old_y_[j]);
      s.vz[j] += finish * (s.az[j] - a_old_z_[j]);
      // x += h (v + h a/2); v -> v + h a_old, the predicted end-of-step velocity at which
      // the velocity-dependent forces (dashpot, drag) are evaluated: second order, where
      // the half-step velocity would make the dashpot first order (e_n off by ~eta h/2).
      s.x[j] += h * (s.vx[j] + 0.5 * h * s.ax[j]);
      s.y[j] += h * (s.vy[j] + 0.5 * h * s.ay[j]);
      s.z[j] += h * (s.vz[j] + 0.5 * h * s.az[j]);
      s.vx[j] += h * s.ax[j];
      s.vy[j] += h * s.ay[j];
      s.vz[j] += h * s.az[j];
      a_old_x_[j] = s.ax[j];
      a_old_y_[j] = s.ay[j];
      a_old_z_[j] = s.az[j];
      const double dx = s.x[j] - s.x0[j], dy = s.y[j] - s.y0[j], dz = s.z[j] - s.z0[j];
      max_disp2 = std::max(max_disp2, dx * dx + dy * dy + dz * dz);
    }
    if (rotation_) {
      if (k > 0) correct_spin(s, h, torque_old_);
      predict_spin(s, h, torque_old_);
    }
    if (max_disp2 > half_skin * half_skin) {
      rebuild_contact_neighbours();
    } else {
      dem_halo_.fill_positions(s.x.data(), s.y.data(), s.z.data());
      for (auto* v : {&s.vx, &s.vy, &s.vz}) dem_halo_.fill(*v);
      if (rotation_)
        for (auto* v : {&s.wx, &s.wy, &s.wz}) dem_halo_.fill(*v);
    }
    dem_forces(true, 0.5 * h / dt, h);
  }
#pragma omp parallel for schedule(static) if (n > kMinParallelSpheres)
  for (long j = 0; j < n; ++j) {  // the last sub-step's v_n + h (a_old + a_new)/2
    s.vx[j] += 0.5 * h * (s.ax[j] - a_old_x_[j]);
    s.vy[j] += 0.5 * h * (s.ay[j] - a_old_y_[j]);
    s.vz[j] += 0.5 * h * (s.az[j] - a_old_z_[j]);
  }
  if (rotation_) correct_spin(s, h, torque_old_);
}

void Simulation::relax() {
  for (int k = 0; k < scene_.startup.relax_steps; ++k) advance(true);
  // Release at t = 0: spheres start from rest relative to their initial velocity.
  time_ = 0.0;
  steps_ = 0;
  dem_forces(false, 0.0);
  DemParticles& s = dem_;
  std::fill(s.fmx.begin(), s.fmx.end(), 0.0);  // the first mean-force window opens now
  std::fill(s.fmy.begin(), s.fmy.end(), 0.0);
  std::fill(s.fmz.begin(), s.fmz.end(), 0.0);
}

void Simulation::step() { advance(false); }

// One SPH step, symplectic position-Verlet (the scheme of DualSPHysics, which keeps
// density and pressure in step with the positions; a kick-drift-kick with the
// pressure half a step behind the positions anti-damps acoustic modes):
//   1. predictor: x, u, rho to n+1/2 with the rates of the last evaluation
//   2. DEM sub-steps over the first half (fluid fields at the spheres held)
//   3. neighbours at n+1/2; voidage -> density rate -> h, P -> theta -> interpolation
//      at spheres -> reaction of the spheres' mean force on the fluid
//   4. corrector: u^{n+1} = u^n + dt a^{n+1/2}, x^{n+1} = x^{n+1/2} + dt/2 u^{n+1},
//      rho^{n+1} = rho^n (2 - e)/(2 + e), e = -dt drho/rho
//   5. DEM sub-steps over the second half with the new fluid fields; next dt (CFL)
void Simulation::advance(bool hold_spheres) {
  FluidParticles& f = fluid_;
  const double dt = dt_sph_;
  const long n = static_cast<long>(f.n_owned);
  Lap lap{timers_};
  u0x_.resize(n);
  u0y_.resize(n);
  u0z_.resize(n);
  rho0_.resize(n);
  const double keep = hold_spheres ? 1.0 - scene_.startup.damping : 1.0;
  if (++steps_since_sort_ >= sort_interval_) {  // keep neighbours close in memory
    steps_since_sort_ = 0;
    f.resize(f.n_owned);
    sort_owned_by_cell(f, cell_size_ / 2);
    fluid_lists_stale_ = true;
    if (rotation_) contact_history_.save(dem_, contacts_);  // while the list matches the arrays
    dem_.resize(dem_.n_owned);
    if (dem_.n_owned > 0) sort_owned_by_cell(dem_, cell_size_ / 2);
    rebuild_contact_neighbours();  // the DEM sub-steps below use the halo and contact list
  }
#pragma omp parallel for schedule(static)
  for (long a = 0; a < n; ++a) {
    rho0_[a] = f.rho[a];
    f.rho[a] += 0.5 * dt * f.drho[a];
    u0x_[a] = f.vx[a] * keep;
    u0y_[a] = f.vy[a] * keep;
    u0z_[a] = f.vz[a] * keep;
    if (f.kind[a] != kFluid) continue;
    f.x[a] += 0.5 * dt * u0x_[a];
    f.y[a] += 0.5 * dt * u0y_[a];
    f.z[a] += 0.5 * dt * u0z_[a];
    f.vx[a] = u0x_[a] + 0.5 * dt * f.ax[a];
    f.vy[a] = u0y_[a] + 0.5 * dt * f.ay[a];
    f.vz[a] = u0z_[a] + 0.5 * dt * f.az[a];
  }
  lap(kIntegrate);
  if (!hold_spheres) dem_half(dt, /*first_half=*/true);
  lap(kDem);
  compute_fluid_side(hold_spheres);
  lap.start = Clock::now();  // compute_fluid_side timed its own passes
#pragma omp parallel for schedule(static)
  for (long a = 0; a < n; ++a) {
    const double e = -dt * f.drho[a] / f.rho[a];
    f.rho[a] = rho0_[a] * (2.0 - e) / (2.0 + e);
    if (f.kind[a] != kFluid) continue;
    f.vx[a] = u0x_[a] + dt * f.ax[a];
    f.vy[a] = u0y_[a] + dt * f.ay[a];
    f.vz[a] = u0z_[a] + dt * f.az[a];
    f.x[a] += 0.5 * dt * f.vx[a];
    f.y[a] += 0.5 * dt * f.vy[a];
    f.z[a] += 0.5 * dt * f.vz[a];
  }
  lap(kIntegrate);
  if (!hold_spheres) dem_half(dt, /*first_half=*/false);
  lap(kDem);
  check_finite();
  if (!hold_spheres) {
    time_ += dt;
    ++steps_;
  }
  next_dt();
  lap(kOther);
}

void Simulation::next_dt() {
  const FluidParticles& f = fluid_;
  double dt = scene_.time.max_dt_sph;
  const double nu = scene_.fluid.viscosity / scene_.fluid.density;
  for (std::size_t a = 0; a < f.n_owned; ++a) {
    if (f.kind[a] != kFluid) continue;
    dt = std::min(dt, f.dt_limit[a]);                     // CFL (3.5)
    dt = std::min(dt, 0.125 * f.h[a] * f.h[a] / nu);      // viscous diffusion
    const double acc = std::sqrt(f.ax[a] * f.ax[a] + f.ay[a] * f.ay[a] + f.az[a] * f.az[a]);
    if (acc > 0) dt = std::min(dt, 0.25 * std::sqrt(f.h[a] / acc));  // force
  }
  dt_sph_ = dt;
}

void Simulation::check_finite() const {
  const FluidParticles& f = fluid_;
  for (std::size_t a = 0; a < f.n_owned; ++a)
    if (!std::isfinite(f.x[a] + f.y[a] + f.z[a] + f.vx[a] + f.vy[a] + f.vz[a] + f.rho[a]))
      throw std::runtime_error(fmt::format("step {} (t = {:.6g} s): fluid particle id {} has a non-finite "
                                           "state; reduce time.cfl or raise fluid.sound_speed",
                                           steps_, time_, f.id[a]));
  const DemParticles& s = dem_;
  for (std::size_t j = 0; j < s.n_owned; ++j)
    if (!std::isfinite(s.x[j] + s.y[j] + s.z[j] + s.vx[j] + s.vy[j] + s.vz[j] + s.wx[j] + s.wy[j] + s.wz[j]))
      throw std::runtime_error(fmt::format("step {} (t = {:.6g} s): sphere id {} has a non-finite state; "
                                           "raise time.dem_steps_per_contact",
                                           steps_, time_, s.id[j]));
}

std::vector<double> Simulation::voidage_on_grid(const GridSpec& grid, double h) const {
  // Fresh bins: the spheres have moved since the step's neighbour rebuild, and the halo
  // must reach the analysis kernel (checked).
  if (kernel::kSupport * h > dem_halo_.width())
    throw std::runtime_error("voidage grid: kernel support exceeds the sphere halo width");
  CellList cells;
  cells.build(dem_.x.data(), dem_.y.data(), dem_.z.data(), dem_.size(), kernel::kSupport * h, 2);
  return compute_voidage_grid(dem_, cells, grid, h);
}

std::vector<int> Simulation::contact_counts() const {
  const DemParticles& s = dem_;
  std::vector<int> count(s.n_owned, 0);
  for (std::size_t i = 0; i < s.n_owned; ++i) {
    for (std::uint32_t k = contacts_.offset[i]; k < contacts_.offset[i + 1]; ++k) {
      const std::uint32_t j = contacts_.neighbour[k];
      const double dx = s.x[i] - s.x[j], dy = s.y[i] - s.y[j], dz = s.z[i] - s.z[j];
      const double rs = s.radius[i] + s.radius[j];
      count[i] += dx * dx + dy * dy + dz * dz < rs * rs;
    }
    count[i] += s.z[i] < s.radius[i];  // the bottom wall at z = 0
  }
  return count;
}

Diagnostics Simulation::diagnostics() const {
  Diagnostics d;
  const FluidParticles& f = fluid_;
  const DemParticles& s = dem_;
  d.time = time_;
  d.step = steps_;
  d.dt_sph = dt_sph_;
  d.dt_dem = dt_dem_;
  d.voidage_clamped = voidage_clamped_;
  d.omega_bounded = omega_bounded_;
  const BasePorePressure base{eos_.rho0, std::abs(scene_.gravity[2]), scene_.fill_height(), scene_.fluid.spacing};
  d.excess_pore_pressure_base = excess_pore_pressure_base(f, base);
  const double k = std::visit([](const auto& law) { return law.normal.k; }, contact_law_);
  const double area = scene_.box.length(0) * scene_.box.length(1);
  d.wall_load_base = wall_load_base(s, k, area, base);
  d.fluid_load_base = fluid_load_base(f, s, walls_on_spheres_z_, hydrostatic_split(), area, base);
  for (std::size_t a = 0; a < f.n_owned; ++a) {
    if (f.kind[a] != kFluid) continue;
    d.fluid_mass += f.mass[a];
    d.kinetic_energy_fluid += 0.5 * f.mass[a] * (f.vx[a] * f.vx[a] + f.vy[a] * f.vy[a] + f.vz[a] * f.vz[a]);
    d.max_density_error = std::max(d.max_density_error, std::abs(f.rho[a] / (f.eps[a] * eos_.rho0) - 1.0));
  }
  const std::size_t ns = scene_.species.size();
  d.vz_mean.assign(ns, 0.0);
  d.slip_z_mean.assign(ns, 0.0);
  d.com_z.assign(ns, 0.0);
  d.count.assign(ns, 0);
  std::vector<double> mass(ns, 0.0);
  for (std::size_t j = 0; j < s.n_owned; ++j) {
    const int sp = s.species[j];
    d.kinetic_energy_solid += 0.5 * s.mass[j] * (s.vx[j] * s.vx[j] + s.vy[j] * s.vy[j] + s.vz[j] * s.vz[j]);
    d.max_overlap_over_d = std::max(d.max_overlap_over_d, s.overlap_max[j] / (2.0 * s.radius[j]));
    d.vz_mean[sp] += s.vz[j];
    d.slip_z_mean[sp] += s.eps[j] * (s.ufz[j] - s.vz[j]);
    d.com_z[sp] += s.mass[j] * s.z[j];
    mass[sp] += s.mass[j];
    ++d.count[sp];
  }
  for (std::size_t sp = 0; sp < ns; ++sp) {
    if (d.count[sp] == 0) continue;
    d.vz_mean[sp] /= d.count[sp];
    d.slip_z_mean[sp] /= d.count[sp];
    d.com_z[sp] /= mass[sp];
  }
  return d;
}

}  // namespace sphdem
