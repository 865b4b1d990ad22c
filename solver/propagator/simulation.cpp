#include "propagator/simulation.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "coupling/distributor_mirror.hpp"
#include "coupling/drag_exchange.hpp"
#include "coupling/interpolation.hpp"
#include "coupling/pressure_coupling.hpp"
#include "coupling/reaction.hpp"
#include "coupling/voidage.hpp"
#include "domain/reorder.hpp"
#include "domain/sfc_grid.hpp"
#include "io/particle_state.hpp"
#include "scene/initial_state.hpp"
#include "sph/density_rate.hpp"
#include "sph/diffusion_gradient.hpp"
#include "sph/kernel.hpp"
#include "sph/momentum.hpp"

namespace sphdem {

namespace {

// Verlet skins of the fluid's lists, in units of the largest h at the build: the lists
// hold the pairs within support + skin and are rebuilt once the particles' displacements
// and the growth of h have used the skin up. The fluid pairs' is thin (every pass over
// them evaluates the skin's entries too); the fluid-sphere pairs' is wider (the spheres
// move faster than the fluid, and a rebuild of those pairs renews the sphere lists).
constexpr double kFluidSkin = 0.1;
constexpr double kFluidSphereSkin = 0.2;

DemParticles placed_spheres(const Scene& scene, FluidParticles& fluid) {
  DemParticles spheres;
  place_particles(scene, fluid, spheres);
  return spheres;
}

}  // namespace

Simulation::Simulation(const Scene& scene, const RankComm& comm)
    : scene_(scene),
      comm_(comm),
      params_(compile_step_params(scene_)),
      dem_(params_.box, params_.dem, placed_spheres(scene_, fluid_), comm_),
      fluid_halo_(comm_),
      flow_(scene_.flow, params_.box, params_.fluid.eos.rho0) {
  build_initial_state();
}

Simulation::Simulation(const Scene& scene, const CheckpointReader& r, const RankComm& comm)
    : scene_(scene),
      comm_(comm),
      params_(compile_step_params(scene_)),
      fluid_(read_particle_state<FluidParticles>(r, "fluid/")),
      dem_(params_.box, params_.dem, DemSubstepper::read_spheres(r), comm_),
      fluid_halo_(comm_),
      flow_(scene_.flow, params_.box, params_.fluid.eos.rho0) {
  dem_.read_state(r);
  if (flow_.on() && r.has("run/flow_pressure_gradient")) {
    const std::vector<double> G = r.array<double>("run/flow_pressure_gradient");
    flow_.set_pressure_gradient({G.at(0), G.at(1), G.at(2)});
    dem_.set_mean_pressure_gradient(flow_.pressure_gradient());
  }
  time_ = r.scalar<double>("run/time");
  dt_sph_ = r.scalar<double>("run/dt_sph");
  steps_ = r.scalar<std::int64_t>("run/step");
  cell_size_ = r.scalar<double>("run/cell_size");
  sort_interval_ = static_cast<int>(r.scalar<std::int64_t>("run/sort_interval"));
  neighbour_builds_ = r.scalar<std::int64_t>("run/neighbour_builds");
  // The next step re-sorts and rebuilds every list (as the run that wrote it did).
  steps_since_sort_ = sort_interval_ - 1;
  fluid_lists_stale_ = true;
  if (comm_.parallel()) resume_share(r);  // every rank read the whole file
}

// Whether the fluid lists must be rebuilt before their next use; on ranks, whether any
// rank's must (a rebuild is collective).
bool Simulation::lists_stale() const {
  const bool stale = fluid_lists_stale_ || xr_.size() != fluid_.n_owned;
  return comm_.parallel() ? comm_.max(stale ? 1.0 : 0.0) > 0.0 : stale;
}

void Simulation::write_state(CheckpointWriter& w) const {
  // each rank's slice of the particle datasets, in rank order
  w.distributed("ranks/fluid_count",
                std::vector<std::int64_t>{static_cast<std::int64_t>(fluid_.n_owned)}, 1);
  w.distributed("ranks/sphere_count",
                std::vector<std::int64_t>{static_cast<std::int64_t>(dem_.spheres().n_owned)}, 1);
  if (decomposition_) {  // the cuts and the work counted since the last balance
    w.scalar("ranks/grid_cell", grid_cell_);
    const std::vector<std::uint32_t>& first = decomposition_->partition().first;
    w.array("ranks/cuts", std::vector<std::int64_t>(first.begin(), first.end()));
    const std::vector<std::uint64_t> work = decomposition_->summed_counts();
    w.array("ranks/work", std::vector<std::int64_t>(work.begin(), work.end()));
  }
  write_particle_state(w, "fluid/", fluid_);
  dem_.write_state(w);
  w.scalar("run/time", time_);
  w.scalar("run/dt_sph", dt_sph_);
  w.scalar<std::int64_t>("run/step", steps_);
  w.scalar("run/cell_size", cell_size_);
  w.scalar<std::int64_t>("run/sort_interval", sort_interval_);
  w.scalar<std::int64_t>("run/neighbour_builds", neighbour_builds_);
  if (flow_.on()) {
    const auto& G = flow_.pressure_gradient();
    w.array("run/flow_pressure_gradient", std::vector<double>(G.begin(), G.end()));
  }
  w.scalar<std::int64_t>("run/rebuilds_all_next_step", rebuilds_all_next_step());
}

std::size_t Simulation::fluid_count() const {
  return static_cast<std::size_t>(
      std::count(fluid_.kind.begin(), fluid_.kind.begin() + fluid_.n_owned, kFluid));
}
std::size_t Simulation::wall_count() const {
  return fluid_.n_owned - fluid_count();
}

double Simulation::fluid_cutoff() const {
  double hmax = 0;
  for (std::size_t a = 0; a < fluid_.n_owned; ++a) hmax = std::max(hmax, fluid_.h[a]);
  hmax = comm_.max(hmax);
  if (hmax == 0.0) {  // no fluid (dry DEM): bin at the contact reach instead
    const DemParticles& s = dem_.spheres();
    double rmax = 0;
    for (std::size_t i = 0; i < s.n_owned; ++i) rmax = std::max(rmax, s.radius[i]);
    return std::max(2.0 * rmax * (1.0 + params_.dem.skin), 1e-12);
  }
  return kernel::kSupport * hmax;
}

// Hydrostatic start (replaces most of the thesis' ~1000 relaxation steps): on the
// lattice, m_a/rho_a = dx^3 exactly, and rho_a = eps_a rho0 (1 + rho0 g (H - z)/B)^(1/gamma)
// is the Tait density of the hydrostatic pressure at the particle's voidage (P = 0 in a
// column periodic in z: the flow's body force carries the weight).
void Simulation::build_initial_state() {
  const FluidStepParams& p = params_.fluid;
  const double dx = p.spacing, dx3 = dx * dx * dx;
  const double g = std::abs(params_.gravity[2]);
  const double H = p.fill_height;
  for (std::size_t a = 0; a < fluid_.n_owned; ++a) {
    fluid_.h[a] = p.smoothing_factor * dx;
    fluid_.inv_h[a] = 1.0 / fluid_.h[a];
    fluid_.eps[a] = 1.0;
  }
  if (comm_.parallel())
    decompose(
        decomposition_cell(params_.box, fluid_cutoff() * (1.0 + kFluidSkin / kernel::kSupport),
                           comm_.size()),
        /*keep_cells=*/true);
  // m/rho = dx^3 for the double smoothing (3.10)
  for (std::size_t a = 0; a < fluid_.n_owned; ++a) {
    fluid_.rho[a] = p.eos.rho0;
    fluid_.mass[a] = p.eos.rho0 * dx3;
  }
  rebuild_neighbours();
  compute_voidage();
  for (std::size_t a = 0; a < fluid_.n_owned; ++a) {
    const double P = params_.box.periodic[2] ? 0.0 : p.eos.rho0 * g * (H - fluid_.z[a]);
    fluid_.rho[a] = p.eos.density(P, fluid_.eps[a]);
    fluid_.mass[a] = fluid_.rho[a] * dx3;
  }
  if (flow_.on()) start_balanced();
  refresh();
  next_dt();
}

// Every list anew: the fluid's halo and cells at 2 h_max + skin, its half pair list at each
// pair's max(2 h_a, 2 h_b) + skin, then the spheres' halo and contact list and the
// fluid-sphere pairs.
void Simulation::rebuild_neighbours() {
  FluidParticles& f = fluid_;
  const Box& box = params_.box;
  // Owned particles back into the box; halo copies of those near periodic faces.
  for (std::size_t a = 0; a < f.n_owned; ++a) {
    f.x[a] = box.wrap(0, f.x[a]);
    f.y[a] = box.wrap(1, f.y[a]);
    f.z[a] = box.wrap(2, f.z[a]);  // a column periodic in z
  }
  const double support = fluid_cutoff();
  hmax_at_build_ = f.n_owned > 0 ? support / kernel::kSupport : 0.0;
  fluid_skin_ = kFluidSkin * hmax_at_build_;
  sphere_pair_skin_ = kFluidSphereSkin * hmax_at_build_;
  cell_size_ = support + fluid_skin_;
  f.resize(f.n_owned);
  if (decomposition_) {
    distribute_fluid();
    fluid_halo_.build(*decomposition_, cell_size_, f.x.data(), f.y.data(), f.z.data(), f.n_owned);
  } else {
    fluid_halo_.build(box, box.halo_width(support, cell_size_), f.x.data(), f.y.data(), f.z.data(),
                      f.n_owned);
  }
  f.resize(f.n_owned + fluid_halo_.n_ghost());
  fluid_halo_.fill_positions(f.x.data(), f.y.data(), f.z.data());
  f.for_each_field([&](const FieldInfo& field, auto& v) {
    if (field.filled_on_build()) fluid_halo_.fill(v);
  });
  fluid_cells_.build(f.x.data(), f.y.data(), f.z.data(), f.size(), cell_size_, 2);
  list_reach_.resize(f.size());  // owned and halo copies: 2 h_a + skin <= cell_size_
  for (std::size_t a = 0; a < f.size(); ++a)
    list_reach_[a] = kernel::kSupport * f.h[a] + fluid_skin_;
  fluid_pairs_.build_half_within(fluid_cells_, f.x.data(), f.y.data(), f.z.data(), f.n_owned,
                                 list_reach_.data());
  if (decomposition_)  // the work a rank's cells take: the pairs each particle evaluates
    for (std::size_t a = 0; a < f.n_owned; ++a)
      decomposition_->count(f.x[a], f.y[a], f.z[a],
                            fluid_pairs_.end(a) - fluid_pairs_.begin(a) + 1);
  xr_.assign(f.x.begin(), f.x.begin() + f.n_owned);
  yr_.assign(f.y.begin(), f.y.begin() + f.n_owned);
  zr_.assign(f.z.begin(), f.z.begin() + f.n_owned);
  hr_.assign(f.h.begin(), f.h.begin() + f.n_owned);
  fluid_lists_stale_ = false;
  ++neighbour_builds_;
  // The sphere halo must cover the fluid-sphere kernel (with the skin) and the double
  // smoothing's big-sphere kernel.
  const CouplingParams& c = params_.coupling;
  dem_.set_fluid_reach({c.sphere_kernel_scale * kernel::kSupport * hmax_at_build_,
                        fluid_sphere_cutoff(), c.big_cutoff});
  dem_.rebuild_lists();
  if (decomposition_) {  // the spheres' work in the cells they are in now
    const DemParticles& s = dem_.spheres();
    for (std::size_t j = 0; j < s.n_owned; ++j)
      decomposition_->count(s.x[j], s.y[j], s.z[j], dem_.sphere_work(j));
  }
  build_sphere_pairs();
}

// Displacements since the builds: max|x - x_build| of the fluid since its lists, and of
// the fluid and the spheres since the fluid-sphere pairs and since the sphere halo, and
// the growth 2 (h_max - h_max,build).
Simulation::Displacements Simulation::displacements() const {
  const FluidParticles& f = fluid_;
  const DemParticles& s = dem_.spheres();
  const long nf = static_cast<long>(f.n_owned), ns = static_cast<long>(s.n_owned);
  const bool pairs = nf > 0 && xp_.size() == f.n_owned && sxp_.size() == s.n_owned;
  double grown = 0.0, pair_grown = 0.0, df2 = 0.0, dfp2 = 0.0, ds2 = 0.0, dsp2 = 0.0;
#pragma omp parallel for schedule(static) reduction(max : grown, pair_grown, df2, dfp2)
  for (long a = 0; a < nf; ++a) {
    grown = std::max(grown, f.h[a] - hr_[a]);
    const double dx = f.x[a] - xr_[a], dy = f.y[a] - yr_[a], dz = f.z[a] - zr_[a];
    df2 = std::max(df2, dx * dx + dy * dy + dz * dz);
    if (!pairs) continue;
    pair_grown = std::max(pair_grown, f.h[a] - hp_[a]);
    const double px = f.x[a] - xp_[a], py = f.y[a] - yp_[a], pz = f.z[a] - zp_[a];
    dfp2 = std::max(dfp2, px * px + py * py + pz * pz);
  }
#pragma omp parallel for schedule(static) reduction(max : ds2, dsp2) if (ns > kMinParallelSpheres)
  for (long j = 0; j < ns; ++j) {
    const double dx = s.x[j] - s.x0[j], dy = s.y[j] - s.y0[j], dz = s.z[j] - s.z0[j];
    ds2 = std::max(ds2, dx * dx + dy * dy + dz * dz);
    if (!pairs) continue;
    const double px = s.x[j] - sxp_[j], py = s.y[j] - syp_[j], pz = s.z[j] - szp_[j];
    dsp2 = std::max(dsp2, px * px + py * py + pz * pz);
  }
  std::vector<double> m{df2, ds2, dfp2, dsp2, grown, pair_grown};
  comm_.max(m);  // every rank the same rebuild decision
  return {std::sqrt(m[0]), std::sqrt(m[1]),         std::sqrt(m[2]),
          std::sqrt(m[3]), kernel::kSupport * m[4], kernel::kSupport * m[5]};
}

// Verlet criteria (the fluid pairs were listed within max(2 h_a, 2 h_b) + skin, the
// fluid-sphere pairs within 2 H_a + skin with H = scale h, each h as at the build):
//  - fluid pairs: 2 max|x - x_build| + 2 max_a (h_a - h_a,build) <= skin;
//  - fluid-sphere pairs: the displacements of both sides since the pairs were built, and
//    since the fluid and sphere halos were built (a pair with an image outside the halo),
//    plus 2 scale max_a (h_a - h_a,build), <= skin;
// a negative margin: the lists are rebuilt at their next use.
Simulation::VerletMargins Simulation::verlet_margins(const Displacements& d) const {
  VerletMargins m;
  m.fluid = fluid_skin_ - (2.0 * d.fluid + d.growth);
  const double moved = std::max(d.fluid + d.sphere, d.fluid_since_pairs + d.sphere_since_pairs);
  m.sphere =
      sphere_pairs_stale()
          ? -1.0
          : sphere_pair_skin_ - (moved + params_.coupling.sphere_kernel_scale * d.pair_growth);
  return m;
}

Simulation::VerletMargins Simulation::verlet_margins() const {
  if (lists_stale()) return {-1.0, -1.0};
  return verlet_margins(displacements());
}

// The lists are rebuilt where their margin is used up; otherwise the halo copies are
// refreshed.
void Simulation::update_neighbours() {
  FluidParticles& f = fluid_;
  if (lists_stale()) {
    rebuild_neighbours();
    return;
  }
  const VerletMargins margin = verlet_margins(displacements());
  if (margin.fluid < 0) {
    rebuild_neighbours();
    return;
  }
  refresh_copies(fluid_halo_, f);
  if (params_.coupling.double_smoothing)  // its re-smoothing walks the fluid's cells (3.10)
    fluid_cells_.build(f.x.data(), f.y.data(), f.z.data(), f.size(), cell_size_, 2);
  if (f.n_owned > 0 && !sphere_pairs_stale() && margin.sphere < 0)
    dem_.rebuild_lists();  // a new sphere halo, so that it covers the new pairs
  if (sphere_pairs_stale()) build_sphere_pairs();
}

// The fluid-sphere Verlet list, from the spheres (owned + halo) binned now.
void Simulation::build_sphere_pairs() {
  const DemParticles& s = dem_.spheres();
  sphere_pairs_built_at_ = dem_.list_builds();
  if (fluid_.n_owned == 0) return;  // dry DEM
  const std::size_t nf = fluid_.n_owned;
  xp_.assign(fluid_.x.begin(), fluid_.x.begin() + nf);
  yp_.assign(fluid_.y.begin(), fluid_.y.begin() + nf);
  zp_.assign(fluid_.z.begin(), fluid_.z.begin() + nf);
  hp_.assign(fluid_.h.begin(), fluid_.h.begin() + nf);
  sxp_.assign(s.x.begin(), s.x.begin() + s.n_owned);
  syp_.assign(s.y.begin(), s.y.begin() + s.n_owned);
  szp_.assign(s.z.begin(), s.z.begin() + s.n_owned);
  const double cut = fluid_sphere_cutoff();
  sphere_cells_.build(s.x.data(), s.y.data(), s.z.data(), s.size(), cut, 2);
  list_reach_.resize(nf);  // each fluid particle's: 2 scale h_a + skin <= cut
  for (std::size_t a = 0; a < nf; ++a)
    list_reach_[a] =
        params_.coupling.sphere_kernel_scale * kernel::kSupport * fluid_.h[a] + sphere_pair_skin_;
  sphere_pairs_.keep_drag_weights = params_.coupling.distributor.on();
  sphere_pairs_.upstream = params_.coupling.drag_upstream;
  sphere_pairs_.build_list(fluid_, sphere_cells_, params_.coupling.sphere_kernel_scale,
                           list_reach_.data(), params_.coupling.drag_kernel_scale);
}

double Simulation::fluid_sphere_cutoff() const {
  return params_.coupling.sphere_kernel_scale * kernel::kSupport * hmax_at_build_ +
         sphere_pair_skin_;
}

// The fluid-sphere pairs' kernel values of this step and the voidage (2.50), or with
// double smoothing the small spheres' part (3.8) plus the big spheres smoothed apart
// (3.9) and again with the fluid kernel (3.10).
void Simulation::compute_voidage() {
  FluidParticles& f = fluid_;
  const DemParticles& s = dem_.spheres();
  const CouplingParams& c = params_.coupling;
  sphere_pairs_.evaluate(f, s, c.variational);
  continue_bed_below_distributor(sphere_pairs_, f, s, c.distributor);
  if (!c.double_smoothing) {
    voidage_clamped_ =
        compute_fluid_voidage(f, s, sphere_pairs_, c.voidage_floor, nullptr, c.voidage_upstream);
    return;
  }
  big_cells_.build(s.x.data(), s.y.data(), s.z.data(), s.size(), c.big_cutoff);
  smooth_big_spheres(f, s, big_cells_, c.is_big_species, c.big_h_over_d, big_fraction_);
  fluid_halo_.fill(big_fraction_.phi);
  fluid_halo_.fill(big_fraction_.phi_over_d);
  resmooth_with_fluid_kernel(f, fluid_cells_, big_fraction_, big_solid_, big_solid_over_d_);
  const BigSpheresSmoothedApart big{c.is_big_species, big_solid_, big_solid_over_d_};
  voidage_clamped_ = compute_fluid_voidage(f, s, sphere_pairs_, c.voidage_floor, &big);
}

void Simulation::update_smoothing_length() {
  FluidParticles& f = fluid_;
  const double sigma = params_.fluid.smoothing_factor;
  const long n = static_cast<long>(f.n_owned);
#pragma omp parallel for schedule(static)
  for (long a = 0; a < n; ++a) {
    f.h[a] = sigma * std::cbrt(f.mass[a] / f.rho[a]);  // (2.65)
    f.inv_h[a] = 1.0 / f.h[a];
  }
}

void Simulation::update_pressure() {
  FluidParticles& f = fluid_;
  const TaitEquationOfState& eos = params_.fluid.eos;
  const long n = static_cast<long>(f.n_owned);
#pragma omp parallel for schedule(static)
  for (long a = 0; a < n; ++a) {
    f.P[a] = eos.pressure(f.rho[a], f.eps[a]);      // (2.58)
    f.cs[a] = eos.sound_speed(f.rho[a], f.eps[a]);  // (2.59)
  }
  fluid_halo_.fill(f.P);
  fluid_halo_.fill(f.cs);
}

void Simulation::refresh() {
  fluid_lists_stale_ = true;
  compute_fluid_side(true);
  dem_.forces(false, 0.0);
}

// Passes that follow the drift: voidage -> density rate -> pressure -> theta ->
// interpolation at spheres -> reaction on the fluid. Leaves (ax, ay, az) complete.
void Simulation::compute_fluid_side(bool hold_spheres) {
  FluidParticles& f = fluid_;
  DemParticles& s = dem_.spheres();
  const bool variational = params_.coupling.variational;
  Lap lap{timers_};
  update_smoothing_length();
  lap(PassTimers::kIntegrate);
  update_neighbours();
  lap(PassTimers::kNeighbours);
  compute_voidage();
  fluid_halo_.fill(f.eps);
  lap(PassTimers::kVoidage);
  update_pressure();
  const DensityDiffusion& dd = params_.fluid.diffusion;
  if (dd.on()) {
    prepare_density_diffusion(f, dd);
    fluid_halo_.fill(f.diffusion_psi);
    fluid_halo_.fill(f.diffusion_volume);
    if (dd.renormalised) {
      compute_diffusion_gradient(f, fluid_pairs_, pair_scratch_);
      for (auto* g : {&f.diffusion_gx, &f.diffusion_gy, &f.diffusion_gz}) fluid_halo_.fill(*g);
    }
  }
  omega_bounded_ =
      compute_density_rate(f, fluid_pairs_, pair_scratch_, variational, params_.fluid.split, dd);
  fluid_halo_.fill(f.omega);
  fluid_halo_.fill(f.p_term);
  lap(PassTimers::kDensity);
  compute_fluid_acceleration(f, fluid_pairs_, params_.fluid.momentum, pair_scratch_);
  for (auto* v : {&f.thx, &f.thy, &f.thz}) fluid_halo_.fill(*v);
  const auto& g = params_.gravity;
  // the mean pressure gradient of an imposed flow: G / rho_f a unit mass (0 without one)
  const std::array<double, 3> bg = flow_.fluid_acceleration();
  const long n = static_cast<long>(f.n_owned);
#pragma omp parallel for schedule(static)
  for (long a = 0; a < n; ++a) {
    const bool mobile = f.kind[a] == kFluid;
    f.ax[a] = mobile ? f.thx[a] + g[0] + bg[0] : 0.0;
    f.ay[a] = mobile ? f.thy[a] + g[1] + bg[1] : 0.0;
    f.az[a] = mobile ? f.thz[a] + g[2] + bg[2] : 0.0;
  }
  lap(PassTimers::kMomentum);
  if (variational)
    apply_variational_pressure(hold_spheres);  // with the interpolation, in one pass
  else
    interpolate_fluid_at_spheres(s, f, sphere_pairs_, dem_.halo(), sphere_scratch_);
  lap(PassTimers::kInterp);
  if (hold_spheres) {
    // Held spheres: the force they feel now is what the fluid gets back (with the
    // variational coupling the pressure part has been returned already, pair by pair).
    dem_.forces(false, 0.0);
    for (std::size_t j = 0; j < s.n_owned; ++j) {
      const double vp = variational ? s.volume(j) : 0.0;
      s.fmx[j] = s.fx[j] - vp * s.gx[j];
      s.fmy[j] = s.fy[j] - vp * s.gy[j];
      s.fmz[j] = s.fz[j] - vp * s.gz[j];
    }
  }
  const Halo& sphere_halo = dem_.halo();
  for (auto* v : {&s.fmx, &s.fmy, &s.fmz, &s.shepard}) sphere_halo.fill(*v);
  add_reaction_on_fluid(f, s, sphere_pairs_, sphere_scratch_, dem_.update_drag_gains().data());
  lap(PassTimers::kReaction);
}

// Variational pressure coupling (coupling/pressure_coupling.hpp) and the interpolation
// at the spheres: the fluid gets its share now, the spheres' g becomes their pressure
// force / V, and unless they are held their force of the last sub-step switches to it
// from the g they felt (kept before the pass overwrites it;
// DemSubstepper::switch_pressure_force).
void Simulation::apply_variational_pressure(bool hold_spheres) {
  dem_.keep_pressure_gradient();
  walls_on_spheres_z_ = couple_pressure_variationally(
      fluid_, dem_.spheres(), sphere_pairs_, dem_.halo(), sphere_scratch_, params_.fluid.split);
  if (!hold_spheres) dem_.switch_pressure_force();
}

void Simulation::relax() {
  for (int k = 0; k < params_.fluid.relax_steps; ++k) advance(true);
  // Release at t = 0: spheres start from rest relative to their initial velocity.
  time_ = 0.0;
  steps_ = 0;
  dem_.forces(false, 0.0);
  dem_.clear_mean_force();  // the first mean-force window opens now
}

void Simulation::step() {
  advance(false);
}

// One SPH step, symplectic position-Verlet (the scheme of DualSPHysics, which keeps
// density and pressure in step with the positions; a kick-drift-kick with the
// pressure half a step behind the positions anti-damps acoustic modes):
//   1. predictor: x, u, rho to n+1/2 with the rates of the last evaluation
//   2. DEM sub-steps over the first half (fluid fields at the spheres held)
//   3. neighbours at n+1/2; voidage -> density rate -> h, P -> theta -> interpolation
//      at spheres -> reaction of the spheres' mean force on the fluid
//   4. corrector: u^{n+1} = u^n + dt a^{n+1/2}, x^{n+1} = x^{n+1/2} + dt/2 u^{n+1},
//      rho^{n+1} = rho^n (2 - e)/(2 + e), e = -dt drho/rho; where the drag pulls the
//      fluid faster than dt allows, a divided by 1 + dt K' and the rest of the impulse
//      given to the spheres (coupling/drag_exchange.hpp)
//   5. DEM sub-steps over the second half with the new fluid fields; next dt (CFL)
void Simulation::advance(bool hold_spheres) {
  FluidParticles& f = fluid_;
  const double dt = dt_sph_;
  long n = static_cast<long>(f.n_owned);  // changes where a rebuild migrates
  Lap lap{timers_};
  u0x_.resize(n);
  u0y_.resize(n);
  u0z_.resize(n);
  rho0_.resize(n);
  const double keep = hold_spheres ? 1.0 - params_.fluid.relax_damping : 1.0;
  if (rebalance_interval_ > 0 && decomposition_ && steps_ % rebalance_interval_ == 0) {
    force_rebalance_ = true;  // at the rebuild this step makes
    fluid_lists_stale_ = true;
  }
  if (++steps_since_sort_ >= sort_interval_) {  // keep neighbours close in memory
    steps_since_sort_ = 0;
    f.resize(f.n_owned);
    sort_owned_by_cell(f, cell_size_ / 2);
    fluid_lists_stale_ = true;
    dem_.sort_by_cell(cell_size_ / 2);  // the DEM sub-steps below use its halo and contact list
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
  lap(PassTimers::kIntegrate);
  if (!hold_spheres) dem_.half_step(dt, /*first_half=*/true);
  lap(PassTimers::kDem);
  in_step_ = true;  // a rebuild on ranks migrates u^n and rho^n with their particles
  compute_fluid_side(hold_spheres);
  in_step_ = false;
  n = static_cast<long>(f.n_owned);
  lap.restart();  // compute_fluid_side timed its own passes
  drag_phi_.resize(3 * n);
  bool exchange = false;
#pragma omp parallel for schedule(static) reduction(|| : exchange)
  for (long a = 0; a < n; ++a) {
    const double volume = f.mass[a] / f.rho[a];  // at n+1/2, as the reaction's
    const double e = -dt * f.drho[a] / f.rho[a];
    f.rho[a] = rho0_[a] * (2.0 - e) / (2.0 + e);
    double* phi = drag_phi_.data() + 3 * a;
    if (f.kind[a] != kFluid) {
      phi[0] = phi[1] = phi[2] = 0.0;
      continue;
    }
    // the semi-implicit drag exchange: the acceleration the fluid takes, also the next
    // predictor's (coupling/drag_exchange.hpp)
    if (take_drag_exchange(dt, f.drag_rate[a], volume, f.ax[a], f.ay[a], f.az[a], phi))
      exchange = true;
    f.vx[a] = u0x_[a] + dt * f.ax[a];
    f.vy[a] = u0y_[a] + dt * f.ay[a];
    f.vz[a] = u0z_[a] + dt * f.az[a];
    f.x[a] += 0.5 * dt * f.vx[a];
    f.y[a] += 0.5 * dt * f.vy[a];
    f.z[a] += 0.5 * dt * f.vz[a];
  }
  if (exchange && !hold_spheres) {  // what the fluid did not take goes to the spheres
    DemParticles& s = dem_.spheres();
    drag_exchange_impulses(s, dem_.drag_gains().data(), sphere_pairs_, dem_.halo(),
                           drag_phi_.data(), f.n_owned, dt, sphere_scratch_, drag_impulse_);
    dem_.add_impulses(drag_impulse_.data());
  }
  if (flow_.on()) control_flow(time_ + (hold_spheres ? 0.0 : dt), dt, hold_spheres);
  lap(PassTimers::kIntegrate);
  if (!hold_spheres) dem_.half_step(dt, /*first_half=*/false);
  lap(PassTimers::kDem);
  if (!hold_spheres) {
    time_ += dt;
    ++steps_;
  }
  next_dt();
  lap(PassTimers::kOther);
}

void Simulation::next_dt() {
  const FluidParticles& f = fluid_;
  const FluidStepParams& p = params_.fluid;
  double dt = p.max_dt;
  const double nu = p.kinematic_viscosity, alpha = p.momentum.alpha_artificial;
  for (std::size_t a = 0; a < f.n_owned; ++a) {
    if (f.kind[a] != kFluid) continue;
    dt = std::min(dt, f.dt_limit[a]);  // CFL (3.5)
    // viscous diffusion: mu over the superficial density eps rho_f (2.55), plus the
    // Monaghan term's own kinematic viscosity alpha h c / 10 (2.57, in 3D)
    const double nu_a = nu / f.eps[a] + 0.1 * alpha * f.h[a] * f.cs[a];
    dt = std::min(dt, 0.125 * f.h[a] * f.h[a] / nu_a);
    const double acc = std::sqrt(f.ax[a] * f.ax[a] + f.ay[a] * f.ay[a] + f.az[a] * f.az[a]);
    if (acc > 0) dt = std::min(dt, 0.25 * std::sqrt(f.h[a] / acc));  // force
  }
  dt_sph_ = comm_.min(dt);
}

}  // namespace sphdem
