#include "propagator/dem_substepper.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <type_traits>
#include <variant>

#include "coupling/fluid_force.hpp"
#include "dem/contact_rows.hpp"
#include "domain/measured_shares.hpp"
#include "domain/row_partition.hpp"
#include "io/particle_state.hpp"

namespace sphdem {

DemSubstepper::DemSubstepper(const Box& box, const DemStepParams& params, DemParticles spheres,
                             const RankComm& comm)
    : p_(params),
      s_(std::move(spheres)),
      lists_(box, params.skin, params.rotation, comm),
      groups_(s_, comm),
      any_spheres_(comm.sum(s_.n_owned) > 0) {
  groups_.set_fixed(p_.fixed_groups);
}

void DemSubstepper::set_decomposition(const Decomposition* d) {
  lists_.set_decomposition(d);
}

void DemSubstepper::clear_mean_force() {
  std::fill(s_.fmx.begin(), s_.fmx.end(), 0.0);
  std::fill(s_.fmy.begin(), s_.fmy.end(), 0.0);
  std::fill(s_.fmz.begin(), s_.fmz.end(), 0.0);
}

void DemSubstepper::keep_pressure_gradient() {
  const DemParticles& s = s_;
  const long n = static_cast<long>(s.n_owned);
  g_old_.x.assign(s.gx.begin(), s.gx.begin() + n);
  g_old_.y.assign(s.gy.begin(), s.gy.begin() + n);
  g_old_.z.assign(s.gz.begin(), s.gz.begin() + n);
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
    const double dfx = V * (s.gx[j] - g_old_.x[j]), dfy = V * (s.gy[j] - g_old_.y[j]),
                 dfz = V * (s.gz[j] - g_old_.z[j]);
    s.fx[j] += dfx;
    s.fy[j] += dfy;
    s.fz[j] += dfz;
    if (s.rigid_group[j] >= 0) continue;  // below: the group's share
    s.ax[j] += dfx * inv_m;
    s.ay[j] += dfy * inv_m;
    s.az[j] += dfz * inv_m;
  }
  if (groups_.count() == 0) return;
  groups_.sum(s, [&](long j, double& fx, double& fy, double& fz) {
    const double V = s.volume(j);
    fx = V * (s.gx[j] - g_old_.x[j]);
    fy = V * (s.gy[j] - g_old_.y[j]);
    fz = V * (s.gz[j] - g_old_.z[j]);
  });
  groups_.share(s, s.ax, s.ay, s.az, /*add=*/true);
}

// One pass over the owned spheres, in blocks that stay in the cache: the block's fluid
// forces (2.68, in lanes), then each sphere's contact row (2.36) and its acceleration
// (2.35), so that a sub-step streams the sphere arrays once.
template <bool kFluid, class Contact>
double DemSubstepper::force_rows(const Contact& contact, bool accumulate_mean, double weight,
                                 double dt_springs, const Advance& advance) {
  DemParticles& s = s_;
  const long n = static_cast<long>(s.n_owned);
  const ContactNeighbourList& contacts = lists_.contacts();
  ContactHistory& history = lists_.history();
  if constexpr (Contact::kHistory) history.require_aligned(contacts, s.n_owned);
  const double bf = contact.normal.beta_factor();
  const HaloImages images = lists_.halo().images();
  const FluidForceWindow window{accumulate_mean, weight, p_.variational};
  const auto& g = p_.gravity;
  const auto& G = p_.mean_pressure_gradient;
  const drag::Fluid& fluid = p_.fluid;
  double* const drag_c = s.drag_c.data();
  const PairIsa isa = drag_.isa;
  const double h = advance.h;
  double* const xn = next_.x.data();
  double* const yn = next_.y.data();
  double* const zn = next_.z.data();
  double* const vxn = next_.vx.data();
  double* const vyn = next_.vy.data();
  double* const vzn = next_.vz.data();
  double* const wxn = next_.wx.data();
  double* const wyn = next_.wy.data();
  double* const wzn = next_.wz.data();
  double rate_max = 0.0, max_step2 = 0.0;
  // Dry: the shares follow the measured times (every row the same bits on any thread).
  // With fluid the drag's lanes start at each share's first sphere: fixed shares keep the
  // bits of two threads from run to run.
  MeasuredShares& shares = measured_shares_;
  if constexpr (!kFluid)
    shares.prepare(contacts.offset, n, row_cost(),
                   n > kMinParallelSpheres ? omp_get_max_threads() : 1);
#pragma omp parallel if (n > kMinParallelSpheres) reduction(max : rate_max, max_step2)
  {
    const double start = kFluid ? 0.0 : omp_get_wtime();
    const auto [begin, end] = kFluid ? thread_rows(contacts.offset, n, row_cost())
                                     : shares.rows(contacts.offset, row_cost());
    for (std::size_t block = begin; block < end; block += kSphereBlock) {
      const std::size_t block_end = std::min(end, block + kSphereBlock);
      if constexpr (kFluid)
        rate_max = std::max(rate_max,
                            fluid_forces(p_.drag, s, fluid, block, block_end, window, drag_c, isa));
      for (std::size_t j = block; j < block_end; ++j) {
        const ContactRow c =
            contact_row(s, contacts, contact, bf, history, images, p_.walls, dt_springs, j);
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
        const double vm = mean_gradient_share(s.radius[j], inv_m);
        const double ax = (c.fx + fx) * inv_m + g[0] + G[0] * vm;
        const double ay = (c.fy + fy) * inv_m + g[1] + G[1] * vm;
        const double az = (c.fz + fz) * inv_m + g[2] + G[2] * vm;
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
  drag_.rate_max = rate_max;
  return max_step2;
}

double DemSubstepper::fluid_drag_time() const {
  const DemParticles& s = s_;
  double t_min = std::numeric_limits<double>::infinity();
  if (!p_.fluid_force) return t_min;
  const long n = static_cast<long>(s.n_owned);
  const double rho_f = p_.fluid.rho;
  std::vector<double> gains(s.n_owned);
  sphdem::drag_gains(p_.drag, s, p_.fluid, 0, s.n_owned, gains.data());
  const double* gain = gains.data();
#pragma omp parallel for schedule(static) reduction(min : t_min) if (n > kMinParallelSpheres)
  for (long j = 0; j < n; ++j) {
    const double rate = gain[j] / s.mass[j];  // 1 / tau_s at its voidage and Re, linearised
    if (!(rate > 0.0)) continue;
    const double r = (1.0 - s.eps[j]) * s.mass[j] / (s.volume(j) * s.eps[j] * rho_f);
    t_min = std::min(t_min, std::log1p(1.0 / r) / rate);
  }
  return t_min;
}

const std::vector<double>& DemSubstepper::update_drag_gains() {
  const DemParticles& s = s_;
  drag_gain_.assign(s.size(), 0.0);
  if (!p_.fluid_force) return drag_gain_;
  sphdem::drag_gains(p_.drag, s, p_.fluid, 0, s.n_owned, drag_gain_.data());
  lists_.halo().fill(drag_gain_);
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
  if (groups_.count() == 0) return;
  groups_.sum(s, [&](long j, double& jx, double& jy, double& jz) {
    jx = impulse[3 * j];
    jy = impulse[3 * j + 1];
    jz = impulse[3 * j + 2];
  });
  groups_.share(s, s.vx, s.vy, s.vz, /*add=*/true);
}

// Rigid groups share their total force equally (thesis §4.5).
void DemSubstepper::forces(bool accumulate_mean, double weight, double dt_springs) {
  forces_advancing(accumulate_mean, weight, dt_springs, Advance{});
}

double DemSubstepper::forces_advancing(bool accumulate_mean, double weight, double dt_springs,
                                       const Advance& advance) {
  DemParticles& s = s_;
  if (s.n_owned == 0) {  // (on ranks the groups' sums still count this rank, with nothing)
    if (groups_.count() > 0) groups_.sum(s, [](long, double&, double&, double&) {});
    return 0.0;
  }
  NextSubstep& next = next_;
  if (advance.correct) {
    for (auto* v : {&next.vx, &next.vy, &next.vz}) v->resize(s.size());
    if (p_.rotation)
      for (auto* w : {&next.wx, &next.wy, &next.wz}) w->resize(s.size());
    if (advance.predict)
      for (auto* x : {&next.x, &next.y, &next.z}) x->resize(s.size());
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
    std::swap(s.vx, next.vx);
    std::swap(s.vy, next.vy);
    std::swap(s.vz, next.vz);
    if (p_.rotation) {
      std::swap(s.wx, next.wx);
      std::swap(s.wy, next.wy);
      std::swap(s.wz, next.wz);
    }
    if (advance.predict) {
      std::swap(s.x, next.x);
      std::swap(s.y, next.y);
      std::swap(s.z, next.z);
    }
  }
  if (groups_.count() == 0) return max_step2;
  groups_.sum(s, [&](long j, double& fx, double& fy, double& fz) {
    fx = s.ax[j] * s.mass[j];
    fy = s.ay[j] * s.mass[j];
    fz = s.az[j] * s.mass[j];
  });
  groups_.share(s, s.ax, s.ay, s.az, /*add=*/false);
  return max_step2;
}

// Velocity-Verlet sub-steps with the fluid fields at the spheres held fixed (physics.md
// §4). The fluid impulse of the second half of one step and the first half of the next
// make the mean force fm that the fluid gets back at the next evaluation, so every
// impulse is returned exactly once.
void DemSubstepper::half_step(double dt, bool first_half) {
  DemParticles& s = s_;
  if (!any_spheres_) return;
  // dt_max (contacts, Stokes time) and the drag relaxation at the last force pass, the
  // same on every rank
  const double rate_max = lists_.halo().comm().max(drag_.rate_max);
  const double drag_bound = rate_max > 0.0 ? p_.drag_time_fraction / rate_max : p_.dt_max;
  const double h_max = std::min(p_.dt_max, drag_bound);
  const int per_half = std::max(1, static_cast<int>(std::ceil(0.5 * dt / h_max)));
  const double h = 0.5 * dt / per_half;
  dt_ = h;
  substeps_ = 2 * per_half;
  if (!first_half) clear_mean_force();  // start the window of the next mean force
  ++multirate_.tally().half_steps;
  if (groups_.count() == 0) {
    if (!(p_.multirate && multirate_.take(p_, s, lists_, drag_, dt, h, per_half)))
      substeps_fused(h, per_half, 0.5 * h / dt);
  } else
    substeps_apart(h, per_half, 0.5 * h / dt);
  // the halo copies as the fluid passes read them. On ranks, after the second half nothing
  // in the step reads them before the next step's sub-steps refresh those their contacts
  // read, so the exchange waits for an analysis that does (refresh_halo()); one rank's
  // images cost no exchange and stay current (the contact network reads them)
  if (first_half || !lists_.halo().ranks()) lists_.refresh_halo(s);
}

void DemSubstepper::substeps_fused(double h, int count, double weight) {
  DemParticles& s = s_;
  const long n = static_cast<long>(s.n_owned);
  double max_step2 = 0.0;
  const bool spin = p_.rotation;
#pragma omp parallel reduction(max : max_step2) if (n > kMinParallelSpheres)
  for (auto [j, end] = thread_rows(lists_.contacts().offset, n, row_cost()); j < end; ++j) {
    max_step2 = std::max(max_step2, predict(s, j, h));
    if (spin) kick_spin_of(s, j, h);
  }
  lists_.moved(s, max_step2);
  lists_.refresh_for_contacts(s);
  for (int k = 0; k < count; ++k) {
    const bool last = k + 1 == count;  // its corrector ends the half step
    const double step2 = forces_advancing(true, weight, h, Advance{true, !last, h});
    if (last) break;
    lists_.moved(s, step2);
    lists_.refresh_for_contacts(s);
  }
}

void DemSubstepper::substeps_apart(double h, int count, double weight) {
  DemParticles& s = s_;
  const long n = static_cast<long>(s.n_owned);
  a_old_.resize(n);
  double* const aox = a_old_.x.data();
  double* const aoy = a_old_.y.data();
  double* const aoz = a_old_.z.data();
  const std::vector<std::uint32_t>& rows = lists_.contacts().offset;
  for (int k = 0; k < count; ++k) {
    double max_step2 = 0.0;
    const double finish = k > 0 ? 0.5 * h : 0.0;  // the previous sub-step's corrector, fused
#pragma omp parallel reduction(max : max_step2) if (n > kMinParallelSpheres)
    for (auto [j, end] = thread_rows(rows, n, row_cost()); j < end; ++j)  // (the last's below)
      max_step2 = std::max(max_step2, correct_and_predict(s, j, finish, h, aox[j], aoy[j], aoz[j]));
    if (p_.rotation) {
      if (k > 0) correct_spin(s, h, torque_old_);
      predict_spin(s, h, torque_old_);
    }
    // (the contact passes read halo neighbours through their owned source: no fill here)
    lists_.moved(s, max_step2);
    forces(true, weight, h);
  }
#pragma omp parallel if (n > kMinParallelSpheres)
  for (auto [j, end] = thread_rows(rows, n, row_cost()); j < end; ++j)
    correct(s, j, 0.5 * h, aox[j], aoy[j], aoz[j]);  // the last sub-step's
  if (p_.rotation) correct_spin(s, h, torque_old_);
}

void DemSubstepper::write_state(CheckpointWriter& w) const {
  write_particle_state(w, "spheres/", s_);
  lists_.write(w, s_);
  w.scalar("dem/drag_rate_max", lists_.halo().comm().max(drag_.rate_max));  // (over ranks)
}

DemParticles DemSubstepper::read_spheres(const CheckpointReader& r) {
  return read_particle_state<DemParticles>(r, "spheres/");
}

void DemSubstepper::read_state(const CheckpointReader& r) {
  lists_.read(r);
  drag_.rate_max = r.scalar<double>("dem/drag_rate_max");
}

}  // namespace sphdem
