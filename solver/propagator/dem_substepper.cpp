#include "propagator/dem_substepper.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>
#include <variant>

#include "coupling/fluid_force.hpp"
#include "domain/measured_shares.hpp"
#include "domain/reorder.hpp"
#include "domain/row_partition.hpp"
#include "io/particle_state.hpp"

namespace sphdem {

DemSubstepper::DemSubstepper(const Box& box, const DemStepParams& params, DemParticles spheres)
    : box_(box), p_(params), s_(std::move(spheres)) {
  for (std::size_t i = 0; i < s_.size(); ++i)
    n_groups_ = std::max(n_groups_, s_.rigid_group[i] + 1);
  group_fx_.assign(n_groups_, 0);
  group_fy_.assign(n_groups_, 0);
  group_fz_.assign(n_groups_, 0);
  group_m_.assign(n_groups_, 0);
}

// With tangential or rolling parts, the contact history goes to its id-keyed store
// before the list changes and comes back aligned with the new list.
void DemSubstepper::rebuild_lists() {
  DemParticles& s = s_;
  if (p_.rotation) history_.save(s, contacts_);  // no-op if already saved (a sort)
  for (std::size_t i = 0; i < s.n_owned; ++i) {
    s.x[i] = box_.wrap(0, s.x[i]);
    s.y[i] = box_.wrap(1, s.y[i]);
    s.x0[i] = s.x[i];
    s.y0[i] = s.y[i];
    s.z0[i] = s.z[i];
  }
  double rmax = 0;
  for (std::size_t i = 0; i < s.n_owned; ++i) rmax = std::max(rmax, s.radius[i]);
  const double skin = p_.skin * 2.0 * rmax;
  const double contact_cut = 2.0 * rmax + skin;
  s.resize(s.n_owned);
  // (a kernel centred on the spheres reaches further by the skin they may move before
  // the next rebuild)
  const double needed = std::max({reach_.needed, 2.0 * rmax, reach_.sphere_kernel});
  const double wanted = std::max(
      {reach_.wanted, contact_cut, reach_.sphere_kernel > 0 ? reach_.sphere_kernel + skin : 0.0});
  halo_.build(box_, box_.halo_width(needed, wanted), s.x.data(), s.y.data(), s.z.data(), s.n_owned);
  s.resize(s.n_owned + halo_.n_ghost());
  halo_.fill_positions(s.x.data(), s.y.data(), s.z.data());
  s.for_each_field([&](const FieldInfo& field, auto& v) {
    if (field.filled_on_build()) halo_.fill(v);
  });
  if (s.n_owned > 0) {
    cells_.build(s.x.data(), s.y.data(), s.z.data(), s.size(), contact_cut);
    contacts_.build(s, cells_, skin);
  }
  if (p_.rotation) history_.load(s, contacts_);
  drift_ = 0.0;
  ++list_builds_;
}

void DemSubstepper::sort_by_cell(double cell_size) {
  if (p_.rotation) history_.save(s_, contacts_);  // while the list matches the arrays
  s_.resize(s_.n_owned);
  if (s_.n_owned > 0) sort_owned_by_cell(s_, cell_size);
  rebuild_lists();
}

void DemSubstepper::clear_mean_force() {
  std::fill(s_.fmx.begin(), s_.fmx.end(), 0.0);
  std::fill(s_.fmy.begin(), s_.fmy.end(), 0.0);
  std::fill(s_.fmz.begin(), s_.fmz.end(), 0.0);
}

// Sums force(j) over the spheres of each rigid group into group_f*_, and their masses
// into group_m_.
template <class Force>
void DemSubstepper::sum_over_rigid_groups(Force force) {
  const DemParticles& s = s_;
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

void DemSubstepper::keep_pressure_gradient() {
  const DemParticles& s = s_;
  const long n = static_cast<long>(s.n_owned);
  g_old_x_.assign(s.gx.begin(), s.gx.begin() + n);
  g_old_y_.assign(s.gy.begin(), s.gy.begin() + n);
  g_old_z_.assign(s.gz.begin(), s.gz.begin() + n);
}

// Between two evaluations a sphere must feel one constant pressure force, so that what
// it receives over the window of the step mean is what the fluid got: the force and
// acceleration of the last sub-step (the 'old' ones of the next trapezoid) switch to
// the new g.
void DemSubstepper::switch_pressure_force() {
  DemParticles& s = s_;
  const long n = static_cast<long>(s.n_owned);
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
  add_group_shares(s.ax, s.ay, s.az);
}

// One pass over the owned spheres, in blocks that stay in the cache: the block's fluid
// forces (2.68, in lanes), then each sphere's contact row (2.36) and its acceleration
// (2.35), so that a sub-step streams the sphere arrays once.
template <bool kFluid, class Contact>
double DemSubstepper::force_rows(const Contact& contact, bool accumulate_mean, double weight,
                                 double dt_springs, const Advance& advance) {
  DemParticles& s = s_;
  const long n = static_cast<long>(s.n_owned);
  if constexpr (Contact::kHistory) history_.require_aligned(contacts_, s.n_owned);
  const double bf = contact.normal.beta_factor();
  const HaloImages images = halo_.images();
  const FluidForceWindow window{accumulate_mean, weight, p_.variational};
  const auto& g = p_.gravity;
  const drag::Fluid& fluid = p_.fluid;
  double* const drag_c = drag_c_.data();
  const PairIsa isa = isa_;
  const double h = advance.h;
  double* const xn = x_next_.data();
  double* const yn = y_next_.data();
  double* const zn = z_next_.data();
  double* const vxn = vx_next_.data();
  double* const vyn = vy_next_.data();
  double* const vzn = vz_next_.data();
  double* const wxn = wx_next_.data();
  double* const wyn = wy_next_.data();
  double* const wzn = wz_next_.data();
  double rate_max = 0.0, max_step2 = 0.0;
  // Dry: the shares follow the measured times (every row the same bits on any thread).
  // With fluid the drag's lanes start at each share's first sphere: fixed shares keep the
  // bits of two threads from run to run.
  MeasuredShares& shares = measured_shares_;
  if constexpr (!kFluid)
    shares.prepare(contacts_.offset, n, row_cost(),
                   n > kMinParallelSpheres ? omp_get_max_threads() : 1);
#pragma omp parallel if (n > kMinParallelSpheres) reduction(max : rate_max, max_step2)
  {
    const double start = kFluid ? 0.0 : omp_get_wtime();
    const auto [begin, end] = kFluid ? thread_rows(contacts_.offset, n, row_cost())
                                     : shares.rows(contacts_.offset, row_cost());
    for (std::size_t block = begin; block < end; block += kForceBlock) {
      const std::size_t block_end = std::min(end, block + kForceBlock);
      if constexpr (kFluid)
        rate_max = std::max(rate_max,
                            fluid_forces(p_.drag, s, fluid, block, block_end, window, drag_c, isa));
      for (std::size_t j = block; j < block_end; ++j) {
        const ContactRow c =
            contact_row(s, contacts_, contact, bf, history_, images, 0.0, dt_springs, j);
        if constexpr (Contact::kHistory) {
          if (advance.correct) {  // the spin as the velocity (rotation.hpp), tau_old = t
            const double I = s.inertia(j), cc = 0.5 * h / I;
            double wx = s.wx[j] + cc * (c.qx - s.tx[j]);
            double wy = s.wy[j] + cc * (c.qy - s.ty[j]);
            double wz = s.wz[j] + cc * (c.qz - s.tz[j]);
            if (advance.predict) {
              const double cp = h / I;
              wx += cp * c.qx;
              wy += cp * c.qy;
              wz += cp * c.qz;
            }
            wxn[j] = wx;
            wyn[j] = wy;
            wzn[j] = wz;
          }
        }
        store_torque_and_overlap<Contact>(s, j, c);
        const double fx = kFluid ? s.fx[j] : 0.0, fy = kFluid ? s.fy[j] : 0.0,
                     fz = kFluid ? s.fz[j] : 0.0;
        const double inv_m = 1.0 / s.mass[j];
        const double ax = (c.fx + fx) * inv_m + g[0];
        const double ay = (c.fy + fy) * inv_m + g[1];
        const double az = (c.fz + fz) * inv_m + g[2];
        if (advance.correct) {  // v_n + h (a_old + a_new)/2
          const double vx = s.vx[j] + 0.5 * h * (ax - s.ax[j]);
          const double vy = s.vy[j] + 0.5 * h * (ay - s.ay[j]);
          const double vz = s.vz[j] + 0.5 * h * (az - s.az[j]);
          if (advance.predict) {  // as substeps_apart's predictor
            const double dx = h * (vx + 0.5 * h * ax);
            const double dy = h * (vy + 0.5 * h * ay);
            const double dz = h * (vz + 0.5 * h * az);
            xn[j] = s.x[j] + dx;
            yn[j] = s.y[j] + dy;
            zn[j] = s.z[j] + dz;
            max_step2 = std::max(max_step2, dx * dx + dy * dy + dz * dz);
            vxn[j] = vx + h * ax;
            vyn[j] = vy + h * ay;
            vzn[j] = vz + h * az;
          } else {
            vxn[j] = vx;
            vyn[j] = vy;
            vzn[j] = vz;
          }
        }
        s.ax[j] = ax;
        s.ay[j] = ay;
        s.az[j] = az;
      }
    }
    if constexpr (!kFluid) shares.record(omp_get_wtime() - start);
  }
  if constexpr (!kFluid) shares.rebalance();
  drag_rate_max_ = rate_max;
  return max_step2;
}

double DemSubstepper::fluid_drag_time() const {
  const DemParticles& s = s_;
  double t_min = std::numeric_limits<double>::infinity();
  if (!p_.fluid_force || drag_c_.size() < s.n_owned) return t_min;
  const long n = static_cast<long>(s.n_owned);
  const double rho_f = p_.fluid.rho;
#pragma omp parallel for schedule(static) reduction(min : t_min) if (n > kMinParallelSpheres)
  for (long j = 0; j < n; ++j) {
    const double rate = drag_c_[j] * s.eps[j] / s.mass[j];  // 1 / tau_s at its voidage and Re
    if (!(rate > 0.0)) continue;
    const double r = (1.0 - s.eps[j]) * s.mass[j] / (s.volume(j) * s.eps[j] * rho_f);
    t_min = std::min(t_min, std::log1p(1.0 / r) / rate);
  }
  return t_min;
}

const std::vector<double>& DemSubstepper::update_drag_gains() {
  const DemParticles& s = s_;
  drag_gain_.assign(s.size(), 0.0);
  if (!p_.fluid_force || drag_c_.size() < s.n_owned) return drag_gain_;
  for (std::size_t j = 0; j < s.n_owned; ++j) drag_gain_[j] = drag_c_[j] * s.eps[j];
  halo_.fill(drag_gain_);
  return drag_gain_;
}

void DemSubstepper::add_impulses(const double* impulse) {
  DemParticles& s = s_;
  const long n = static_cast<long>(s.n_owned);
  for (long j = 0; j < n; ++j) {
    if (s.rigid_group[j] >= 0) continue;  // below: the group's share
    const double inv_m = 1.0 / s.mass[j];
    s.vx[j] += impulse[3 * j] * inv_m;
    s.vy[j] += impulse[3 * j + 1] * inv_m;
    s.vz[j] += impulse[3 * j + 2] * inv_m;
  }
  if (n_groups_ == 0) return;
  sum_over_rigid_groups([&](long j, double& jx, double& jy, double& jz) {
    jx = impulse[3 * j];
    jy = impulse[3 * j + 1];
    jz = impulse[3 * j + 2];
  });
  add_group_shares(s.vx, s.vy, s.vz);
}

void DemSubstepper::add_group_shares(std::vector<double>& x, std::vector<double>& y,
                                     std::vector<double>& z) const {
  const DemParticles& s = s_;
  for (std::size_t j = 0; j < s.n_owned; ++j) {
    const int gr = s.rigid_group[j];
    if (gr < 0) continue;
    x[j] += group_fx_[gr] / group_m_[gr];
    y[j] += group_fy_[gr] / group_m_[gr];
    z[j] += group_fz_[gr] / group_m_[gr];
  }
}

// Rigid groups share their total force equally (thesis §4.5).
void DemSubstepper::forces(bool accumulate_mean, double weight, double dt_springs) {
  forces_advancing(accumulate_mean, weight, dt_springs, Advance{});
}

double DemSubstepper::forces_advancing(bool accumulate_mean, double weight, double dt_springs,
                                       const Advance& advance) {
  DemParticles& s = s_;
  if (s.n_owned == 0) return 0.0;
  const long n = static_cast<long>(s.n_owned);
  if (p_.fluid_force) drag_c_.resize(s.n_owned);
  if (advance.correct) {
    for (auto* v : {&vx_next_, &vy_next_, &vz_next_}) v->resize(s.size());
    if (p_.rotation)
      for (auto* w : {&wx_next_, &wy_next_, &wz_next_}) w->resize(s.size());
    if (advance.predict)
      for (auto* x : {&x_next_, &y_next_, &z_next_}) x->resize(s.size());
  }
  double max_step2 = 0.0;
  std::visit(
      [&](const auto& contact) {
        max_step2 = p_.fluid_force
                        ? force_rows<true>(contact, accumulate_mean, weight, dt_springs, advance)
                        : force_rows<false>(contact, accumulate_mean, weight, dt_springs, advance);
      },
      p_.law);
  if (advance.correct) {  // the next sub-step's arrays become the current ones
    std::swap(s.vx, vx_next_);
    std::swap(s.vy, vy_next_);
    std::swap(s.vz, vz_next_);
    if (p_.rotation) {
      std::swap(s.wx, wx_next_);
      std::swap(s.wy, wy_next_);
      std::swap(s.wz, wz_next_);
    }
    if (advance.predict) {
      std::swap(s.x, x_next_);
      std::swap(s.y, y_next_);
      std::swap(s.z, z_next_);
    }
  }
  if (n_groups_ == 0) return max_step2;
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
  return max_step2;
}

// Velocity-Verlet sub-steps with the fluid fields at the spheres held fixed (physics.md
// §4). The fluid impulse of the second half of one step and the first half of the next
// make the mean force fm that the fluid gets back at the next evaluation, so every
// impulse is returned exactly once.
void DemSubstepper::half_step(double dt, bool first_half) {
  DemParticles& s = s_;
  if (s.n_owned == 0) return;
  // dt_max (contacts, Stokes time) and the drag relaxation at the last force pass
  const double drag_bound =
      drag_rate_max_ > 0.0 ? p_.drag_time_fraction / drag_rate_max_ : p_.dt_max;
  const double h_max = std::min(p_.dt_max, drag_bound);
  const int per_half = std::max(1, static_cast<int>(std::ceil(0.5 * dt / h_max)));
  const double h = 0.5 * dt / per_half;
  dt_ = h;
  substeps_ = 2 * per_half;
  if (!first_half) clear_mean_force();  // start the window of the next mean force
  ++tally_.half_steps;
  if (n_groups_ == 0) {
    if (!(p_.multirate && substeps_multirate(dt, h, per_half)))
      substeps_fused(h, per_half, 0.5 * h / dt);
  } else
    substeps_apart(h, per_half, 0.5 * h / dt);
  // the halo copies as the fluid passes read them
  halo_.fill_positions(s.x.data(), s.y.data(), s.z.data());
  s.for_each_field([&](const FieldInfo& field, auto& v) {
    if (field.refreshed()) halo_.fill(v);
  });
}

void DemSubstepper::drifted(double max_step2) {
  drift_ += std::sqrt(max_step2);
  if (drift_ > 0.5 * contacts_.skin) drift_ = displacement_since_build();
  if (drift_ > 0.5 * contacts_.skin) rebuild_lists();
}

double DemSubstepper::displacement_since_build() const {
  const DemParticles& s = s_;
  const long n = static_cast<long>(s.n_owned);
  double max_disp2 = 0.0;
#pragma omp parallel for schedule(static) reduction(max : max_disp2) if (n > kMinParallelSpheres)
  for (long j = 0; j < n; ++j) {
    const double dx = s.x[j] - s.x0[j], dy = s.y[j] - s.y0[j], dz = s.z[j] - s.z0[j];
    max_disp2 = std::max(max_disp2, dx * dx + dy * dy + dz * dz);
  }
  return std::sqrt(max_disp2);
}

// x += h (v + h a/2); v -> v + h a_old, the predicted end-of-step velocity at which the
// velocity-dependent forces (dashpot, drag) are evaluated: second order, where the
// half-step velocity would make the dashpot first order (e_n off by ~eta h/2). Returns
// the step's length squared.
static inline double predict(DemParticles& s, std::size_t j, double h) {
  const double dx = h * (s.vx[j] + 0.5 * h * s.ax[j]);
  const double dy = h * (s.vy[j] + 0.5 * h * s.ay[j]);
  const double dz = h * (s.vz[j] + 0.5 * h * s.az[j]);
  s.x[j] += dx;
  s.y[j] += dy;
  s.z[j] += dz;
  s.vx[j] += h * s.ax[j];
  s.vy[j] += h * s.ay[j];
  s.vz[j] += h * s.az[j];
  return dx * dx + dy * dy + dz * dz;
}

// The sub-step before's corrector v_n + h (a_old + a_new)/2 (finish = h/2; 0 before the
// first), then this one's predictor; a_old takes the acceleration the step starts from.
static inline double correct_and_predict(DemParticles& s, std::size_t j, double finish, double h,
                                         double& aox, double& aoy, double& aoz) {
  s.vx[j] += finish * (s.ax[j] - aox);
  s.vy[j] += finish * (s.ay[j] - aoy);
  s.vz[j] += finish * (s.az[j] - aoz);
  const double step2 = predict(s, j, h);
  aox = s.ax[j];
  aoy = s.ay[j];
  aoz = s.az[j];
  return step2;
}

void DemSubstepper::substeps_fused(double h, int count, double weight) {
  DemParticles& s = s_;
  const long n = static_cast<long>(s.n_owned);
  double max_step2 = 0.0;
  const bool spin = p_.rotation;
#pragma omp parallel reduction(max : max_step2) if (n > kMinParallelSpheres)
  for (auto [j, end] = thread_rows(contacts_.offset, n, row_cost()); j < end; ++j) {
    max_step2 = std::max(max_step2, predict(s, j, h));
    if (spin) kick_spin_of(s, j, h);
  }
  drifted(max_step2);
  for (int k = 0; k < count; ++k) {
    const bool last = k + 1 == count;  // its corrector ends the half step
    const double step2 = forces_advancing(true, weight, h, Advance{true, !last, h});
    if (!last) drifted(step2);
  }
}

// Multi-rate sub-steps (the r-RESPA idea, Tuckerman, Berne & Martyna 1992). A sphere whose
// neighbours and wall are all farther than a margin m at the start of the half step feels
// no contact in it as long as no sphere moves m/2 or more: it takes the step of its fluid
// force and gravity (free_dt_max and the drag's relaxation bound), the spheres near a
// contact take the contact sub-steps. m is time.multirate_margin times the largest distance
// a sphere would cover at the start's speeds and accelerations; if any sphere moved m/2 or
// more (a bound: the sums of the largest steps), the half step starts again from the saved
// state with every sphere sub-stepped. Both kinds add their trapezoids to fm over the same
// window. With friction a free sphere keeps its spin (no contact, no torque) and the near
// ones sub-step theirs; only their rows advance the contact history, so only theirs is kept
// for a restart.
bool DemSubstepper::substeps_multirate(double dt, double h, int count) {
  DemParticles& s = s_;
  const long n = static_cast<long>(s.n_owned);
  const double T = 0.5 * dt;
  const double free_bound = std::min(
      p_.free_dt_max, drag_rate_max_ > 0.0 ? p_.drag_time_fraction / drag_rate_max_ : p_.dt_max);
  const int free_count = std::max(1, static_cast<int>(std::ceil(T / free_bound)));
  if (2 * free_count > count) return false;  // little to gain
  double v2 = 0.0, a2 = 0.0;
#pragma omp parallel for schedule(static) reduction(max : v2, a2) if (n > kMinParallelSpheres)
  for (long j = 0; j < n; ++j) {
    v2 = std::max(v2, s.vx[j] * s.vx[j] + s.vy[j] * s.vy[j] + s.vz[j] * s.vz[j]);
    a2 = std::max(a2, s.ax[j] * s.ax[j] + s.ay[j] * s.ay[j] + s.az[j] * s.az[j]);
  }
  const double margin = p_.multirate_margin * (std::sqrt(v2) * T + 0.5 * std::sqrt(a2) * T * T);
  if (drift_ + 0.5 * margin > 0.5 * contacts_.skin) drift_ = displacement_since_build();
  if (drift_ + 0.5 * margin > 0.5 * contacts_.skin) rebuild_lists();  // the list must last
  if (0.5 * margin > 0.5 * contacts_.skin) return false;
  // the spheres within the margin of a contact (each pair is in both rows)
  const HaloImages images = halo_.images();
  near_.clear();
  for (long i = 0; i < n; ++i) {
    bool near = s.z[i] - s.radius[i] < margin;  // the wall at z = 0
    for (std::uint32_t k = contacts_.offset[i]; !near && k < contacts_.offset[i + 1]; ++k) {
      double dx, dy, dz;
      const std::size_t j = owned_image(images, contacts_.neighbour[k], s.x[i], s.y[i], s.z[i], s.x,
                                        s.y, s.z, dx, dy, dz);
      const double reach = s.radius[i] + s.radius[j] + margin;
      near = dx * dx + dy * dy + dz * dz < reach * reach;
    }
    if (near) near_.push_back(static_cast<std::uint32_t>(i));
  }
  if (2 * near_.size() > s.n_owned) return false;  // mostly in contact
  std::vector<double>* const state[] = {&s.x,   &s.y,  &s.z,  &s.vx, &s.vy, &s.vz,  &s.ax,
                                        &s.ay,  &s.az, &s.fx, &s.fy, &s.fz, &s.fmx, &s.fmy,
                                        &s.fmz, &s.wx, &s.wy, &s.wz, &s.tx, &s.ty,  &s.tz};
  const int n_state = p_.rotation ? 21 : 15;  // the last six: spin and torque
  saved_.resize(n_state * n);
  for (int f = 0; f < n_state; ++f)
    std::copy(state[f]->begin(), state[f]->begin() + n, saved_.begin() + f * n);
  // the near spheres' contact history (only their rows advance it)
  const auto near_history = [&](bool save) {
    std::size_t q = 0;
    if (save) history_saved_.clear();
    for (const std::uint32_t i : near_) {
      const std::uint32_t a = contacts_.offset[i], b = contacts_.offset[i + 1];
      if (save) {
        history_saved_.insert(history_saved_.end(), history_.pair.begin() + a,
                              history_.pair.begin() + b);
        history_saved_.push_back(history_.wall[i]);
      } else {
        std::copy_n(history_saved_.begin() + q, b - a, history_.pair.begin() + a);
        history_.wall[i] = history_saved_[q + (b - a)];
      }
      q += b - a + 1;
    }
  };
  if (p_.rotation) near_history(true);
  const double drift_at_start = drift_;
  double free_reach = 0.0, near_reach = 0.0, rate_free = 0.0, rate_near = 0.0;
  for (int k = 0; k < free_count; ++k) {
    const double hf = T / free_count;
    free_reach += std::sqrt(free_step(hf, 0.5 * hf / dt, k == 0));
    rate_free = drag_rate_max_;
  }
  // the near spheres back to the start, then sub-stepped
  for (int f = 0; f < n_state; ++f)
    for (const std::uint32_t j : near_) (*state[f])[j] = saved_[f * n + j];
  std::visit(
      [&](const auto& contact) { near_reach = near_substeps(contact, h, count, 0.5 * h / dt); },
      p_.law);
  rate_near = drag_rate_max_;
  const double reach = std::max(free_reach, near_reach);
  if (2.0 * reach >= margin) {  // a sphere may have met another: back to the start
    for (int f = 0; f < n_state; ++f)
      std::copy(saved_.begin() + f * n, saved_.begin() + (f + 1) * n, state[f]->begin());
    if (p_.rotation) near_history(false);
    drift_ = drift_at_start;
    ++tally_.sent_back;
    return false;
  }
  ++tally_.multirate;
  tally_.near_spheres += static_cast<double>(near_.size());
  tally_.owned_spheres += static_cast<double>(n);
  drift_ += reach;
  drag_rate_max_ = std::max(rate_free, rate_near);
  return true;
}

// One velocity-Verlet step of length h of every sphere under its fluid force and gravity
// alone (the near ones are put back after it); returns the largest step squared. `fresh`
// (the first of a half step): the step starts from the force in the fluid fields of this
// evaluation, not the last sub-step's in the previous ones (a sub-step would feel those
// for h, this step for h_free: its x would lag by h_free^2 / 2 times the change).
double DemSubstepper::free_step(double h, double weight, bool fresh) {
  DemParticles& s = s_;
  const long n = static_cast<long>(s.n_owned);
  drag_c_.resize(s.n_owned);
  const FluidForceWindow window{true, weight, p_.variational};
  const auto& g = p_.gravity;
  double* const drag_c = drag_c_.data();
  double max_step2 = 0.0, rate_max = 0.0;
#pragma omp parallel if (n > kMinParallelSpheres) reduction(max : max_step2, rate_max)
  {
    const auto [begin, end] = thread_rows({}, n, 1.0);
    double aox[kForceBlock], aoy[kForceBlock], aoz[kForceBlock];
    for (std::size_t block = begin; block < end; block += kForceBlock) {
      const std::size_t block_end = std::min(end, block + kForceBlock);
      if (fresh) {
        fluid_forces(p_.drag, s, p_.fluid, block, block_end, FluidForceWindow{}, drag_c, isa_);
        for (std::size_t j = block; j < block_end; ++j) {
          const double inv_m = 1.0 / s.mass[j];
          s.ax[j] = s.fx[j] * inv_m + g[0];
          s.ay[j] = s.fy[j] * inv_m + g[1];
          s.az[j] = s.fz[j] * inv_m + g[2];
        }
      }
      for (std::size_t j = block; j < block_end; ++j) {
        aox[j - block] = s.ax[j];
        aoy[j - block] = s.ay[j];
        aoz[j - block] = s.az[j];
        max_step2 = std::max(max_step2, predict(s, j, h));
        s.overlap_max[j] = 0.0;
      }
      rate_max = std::max(
          rate_max, fluid_forces(p_.drag, s, p_.fluid, block, block_end, window, drag_c, isa_));
      for (std::size_t j = block; j < block_end; ++j) {
        const double inv_m = 1.0 / s.mass[j];
        s.ax[j] = s.fx[j] * inv_m + g[0];
        s.ay[j] = s.fy[j] * inv_m + g[1];
        s.az[j] = s.fz[j] * inv_m + g[2];
        s.vx[j] += 0.5 * h * (s.ax[j] - aox[j - block]);  // v_n + h (a_old + a_new)/2
        s.vy[j] += 0.5 * h * (s.ay[j] - aoy[j - block]);
        s.vz[j] += 0.5 * h * (s.az[j] - aoz[j - block]);
      }
    }
  }
  drag_rate_max_ = rate_max;
  return max_step2;
}

// The contact sub-steps of the near spheres (as substeps_apart's, over their list); their
// neighbours out of reach stand where their own step left them. Returns the sum over the
// sub-steps of the largest step.
template <class Contact>
double DemSubstepper::near_substeps(const Contact& contact, double h, int count, double weight) {
  DemParticles& s = s_;
  const long m = static_cast<long>(near_.size());
  const std::uint32_t* const near = near_.data();
  a_old_x_.resize(m);
  a_old_y_.resize(m);
  a_old_z_.resize(m);
  constexpr bool kSpin = Contact::kHistory;
  OldTorque& t_old = torque_old_;
  if constexpr (kSpin) {
    history_.require_aligned(contacts_, s.n_owned);
    t_old.x.resize(m);
    t_old.y.resize(m);
    t_old.z.resize(m);
  }
  const double bf = contact.normal.beta_factor();
  const HaloImages images = halo_.images();
  const FluidForceWindow window{true, weight, p_.variational};
  const auto& g = p_.gravity;
  double* const drag_c = drag_c_.data();
  double reach = 0.0, rate_max = 0.0;
  for (int k = 0; k < count; ++k) {
    const double finish = k > 0 ? 0.5 * h : 0.0;  // the previous sub-step's corrector
    double max_step2 = 0.0;
#pragma omp parallel for schedule(static) reduction(max : max_step2) if (m > kMinParallelSpheres)
    for (long q = 0; q < m; ++q) {
      const std::size_t j = near[q];
      max_step2 = std::max(
          max_step2, correct_and_predict(s, j, finish, h, a_old_x_[q], a_old_y_[q], a_old_z_[q]));
      if constexpr (kSpin) {  // as predict_spin and correct_spin
        if (k > 0) correct_spin_of(s, j, h, t_old.x[q], t_old.y[q], t_old.z[q]);
        predict_spin_of(s, j, h, t_old.x[q], t_old.y[q], t_old.z[q]);
      }
    }
    reach += std::sqrt(max_step2);
    rate_max = 0.0;
#pragma omp parallel for schedule(static) reduction(max : rate_max) if (m > kMinParallelSpheres)
    for (long q = 0; q < m; ++q) {
      const std::size_t j = near[q];
      rate_max = std::max(rate_max, fluid_forces(p_.drag, s, p_.fluid, j, j + 1, window, drag_c,
                                                 PairIsa::kBaseline));
      const ContactRow c = contact_row(s, contacts_, contact, bf, history_, images, 0.0, h, j);
      store_torque_and_overlap<Contact>(s, j, c);
      const double inv_m = 1.0 / s.mass[j];
      s.ax[j] = (c.fx + s.fx[j]) * inv_m + g[0];
      s.ay[j] = (c.fy + s.fy[j]) * inv_m + g[1];
      s.az[j] = (c.fz + s.fz[j]) * inv_m + g[2];
    }
  }
#pragma omp parallel for schedule(static) if (m > kMinParallelSpheres)
  for (long q = 0; q < m; ++q) {
    const std::size_t j = near[q];
    s.vx[j] += 0.5 * h * (s.ax[j] - a_old_x_[q]);
    s.vy[j] += 0.5 * h * (s.ay[j] - a_old_y_[q]);
    s.vz[j] += 0.5 * h * (s.az[j] - a_old_z_[q]);
    if constexpr (kSpin) correct_spin_of(s, j, h, t_old.x[q], t_old.y[q], t_old.z[q]);
  }
  drag_rate_max_ = rate_max;
  return reach;
}

void DemSubstepper::substeps_apart(double h, int count, double weight) {
  DemParticles& s = s_;
  const long n = static_cast<long>(s.n_owned);
  a_old_x_.resize(n);
  a_old_y_.resize(n);
  a_old_z_.resize(n);
  for (int k = 0; k < count; ++k) {
    double max_step2 = 0.0;
    const double finish = k > 0 ? 0.5 * h : 0.0;  // the previous sub-step's corrector, fused
#pragma omp parallel reduction(max : max_step2) if (n > kMinParallelSpheres)
    for (auto [j, end] = thread_rows(contacts_.offset, n, row_cost()); j < end; ++j) {
      // (the last sub-step's corrector below)
      max_step2 = std::max(
          max_step2, correct_and_predict(s, j, finish, h, a_old_x_[j], a_old_y_[j], a_old_z_[j]));
    }
    if (p_.rotation) {
      if (k > 0) correct_spin(s, h, torque_old_);
      predict_spin(s, h, torque_old_);
    }
    // (the contact passes read halo neighbours through their owned source: no fill here)
    drifted(max_step2);
    forces(true, weight, h);
  }
#pragma omp parallel if (n > kMinParallelSpheres)
  for (auto [j, end] = thread_rows(contacts_.offset, n, row_cost()); j < end; ++j) {
    // the last sub-step's v_n + h (a_old + a_new)/2
    s.vx[j] += 0.5 * h * (s.ax[j] - a_old_x_[j]);
    s.vy[j] += 0.5 * h * (s.ay[j] - a_old_y_[j]);
    s.vz[j] += 0.5 * h * (s.az[j] - a_old_z_[j]);
  }
  if (p_.rotation) correct_spin(s, h, torque_old_);
}

void DemSubstepper::write_state(CheckpointWriter& w) const {
  write_particle_state(w, "spheres/", s_);
  const std::vector<ContactHistory::Record> records = contact_records();
  std::vector<std::int64_t> id(records.size()), partner(records.size());
  std::vector<double> xi(3 * records.size()), mr(3 * records.size());
  for (std::size_t k = 0; k < records.size(); ++k) {
    id[k] = records[k].id;
    partner[k] = records[k].partner;
    for (int d = 0; d < 3; ++d) {
      xi[3 * k + d] = records[k].state.xi[d];
      mr[3 * k + d] = records[k].state.mr[d];
    }
  }
  w.array("contacts/id", id);
  w.array("contacts/partner", partner);
  w.array("contacts/xi", xi);
  w.array("contacts/mr", mr);
  w.scalar("dem/drag_rate_max", drag_rate_max_);
  w.scalar("dem/reach_needed", reach_.needed);
  w.scalar("dem/reach_wanted", reach_.wanted);
  w.scalar("dem/reach_sphere_kernel", reach_.sphere_kernel);
}

DemParticles DemSubstepper::read_spheres(const CheckpointReader& r) {
  return read_particle_state<DemParticles>(r, "spheres/");
}

void DemSubstepper::read_state(const CheckpointReader& r) {
  const auto id = r.array<std::int64_t>("contacts/id");
  const auto partner = r.array<std::int64_t>("contacts/partner");
  const auto xi = r.array<double>("contacts/xi");
  const auto mr = r.array<double>("contacts/mr");
  if (partner.size() != id.size() || xi.size() != 3 * id.size() || mr.size() != 3 * id.size())
    throw CheckpointError(r.path() + ": the contact history's arrays differ in length");
  std::vector<ContactHistory::Record> records(id.size());
  for (std::size_t k = 0; k < id.size(); ++k) {
    records[k].id = id[k];
    records[k].partner = partner[k];
    for (int d = 0; d < 3; ++d) {
      records[k].state.xi[d] = xi[3 * k + d];
      records[k].state.mr[d] = mr[3 * k + d];
    }
  }
  history_.set_keyed(std::move(records));
  drag_rate_max_ = r.scalar<double>("dem/drag_rate_max");
  reach_ = {r.scalar<double>("dem/reach_needed"), r.scalar<double>("dem/reach_wanted"),
            r.scalar<double>("dem/reach_sphere_kernel")};
}

}  // namespace sphdem
