#include "propagator/multirate_half_step.hpp"

#include <algorithm>
#include <cmath>
#include <variant>

#include "dem/contact_rows.hpp"
#include "domain/row_partition.hpp"

namespace sphdem {

bool MultirateHalfStep::take(const DemStepParams& p, DemParticles& s, SphereLists& lists,
                             SphereDrag& drag, double dt, double h, int count) {
  long n = static_cast<long>(s.n_owned);
  const RankComm& comm = lists.halo().comm();  // every decision below the same on each rank
  const double T = 0.5 * dt;
  const double rate = comm.max(drag.rate_max);
  const double free_bound =
      std::min(p.free_dt_max, rate > 0.0 ? p.drag_time_fraction / rate : p.dt_max);
  const int free_count = std::max(1, static_cast<int>(std::ceil(T / free_bound)));
  if (2 * free_count > count) return false;  // little to gain
  double v2 = 0.0, a2 = 0.0;
#pragma omp parallel for schedule(static) reduction(max : v2, a2) if (n > kMinParallelSpheres)
  for (long j = 0; j < n; ++j) {
    v2 = std::max(v2, s.vx[j] * s.vx[j] + s.vy[j] * s.vy[j] + s.vz[j] * s.vz[j]);
    a2 = std::max(a2, s.ax[j] * s.ax[j] + s.ay[j] * s.ay[j] + s.az[j] * s.az[j]);
  }
  if (comm.parallel()) {
    std::vector<double> m{v2, a2};
    comm.max(m);
    v2 = m[0];
    a2 = m[1];
  }
  const double margin = p.multirate_margin * (std::sqrt(v2) * T + 0.5 * std::sqrt(a2) * T * T);
  if (!lists.holds_for(s, 0.5 * margin)) return false;  // the list must last
  n = static_cast<long>(s.n_owned);  // (on ranks a rebuild there migrates spheres)
  // the spheres within the margin of a contact (each pair is in both rows)
  const ContactNeighbourList& contacts = lists.contacts();
  const HaloImages images = lists.halo().images();
  near_.clear();
  for (long i = 0; i < n; ++i) {
    bool near = s.z[i] - s.radius[i] - p.walls.bottom < margin ||  // the bottom wall
                p.walls.top - s.z[i] - s.radius[i] < margin;       // the top plane
    for (std::uint32_t k = contacts.offset[i]; !near && k < contacts.offset[i + 1]; ++k) {
      double dx, dy, dz;
      const std::size_t j = owned_image(images, contacts.neighbour[k], s.x[i], s.y[i], s.z[i], s.x,
                                        s.y, s.z, dx, dy, dz);
      const double reach = s.radius[i] + s.radius[j] + margin;
      near = dx * dx + dy * dy + dz * dz < reach * reach;
    }
    if (near) near_.push_back(static_cast<std::uint32_t>(i));
  }
  if (2 * comm.sum(near_.size()) > comm.sum(s.n_owned)) return false;  // mostly in contact
  saved_.save(s, s.n_owned);
  if (p.rotation) keep_near_history(lists);
  double free_reach = 0.0, near_reach = 0.0, rate_free = 0.0, rate_near = 0.0;
  for (int k = 0; k < free_count; ++k) {
    const double hf = T / free_count;
    free_reach += std::sqrt(comm.max(free_step(p, s, drag, hf, 0.5 * hf / dt, k == 0)));
    rate_free = drag.rate_max;
  }
  saved_.restore(s, near_);  // the near spheres back to the start, then sub-stepped
  std::visit(
      [&](const auto& contact) {
        near_reach = near_substeps(contact, p, s, lists, drag, h, count, 0.5 * h / dt);
      },
      p.law);
  rate_near = drag.rate_max;
  const double reach = std::max(free_reach, near_reach);
  if (2.0 * reach >= margin) {  // a sphere may have met another: back to the start
    saved_.restore(s);
    if (p.rotation) restore_near_history(lists);
    ++tally_.sent_back;
    return false;
  }
  ++tally_.multirate;
  tally_.near_spheres += static_cast<double>(near_.size());
  tally_.owned_spheres += static_cast<double>(n);
  lists.moved_by(reach);
  drag.rate_max = std::max(rate_free, rate_near);
  return true;
}

void MultirateHalfStep::keep_near_history(const SphereLists& lists) {
  const ContactNeighbourList& contacts = lists.contacts();
  const ContactHistory& history = lists.history();
  history_saved_.clear();
  for (const std::uint32_t i : near_) {
    const std::uint32_t a = contacts.offset[i], b = contacts.offset[i + 1];
    history_saved_.insert(history_saved_.end(), history.pair.begin() + a, history.pair.begin() + b);
    history_saved_.push_back(history.wall[i]);
  }
}

void MultirateHalfStep::restore_near_history(SphereLists& lists) const {
  const ContactNeighbourList& contacts = lists.contacts();
  ContactHistory& history = lists.history();
  std::size_t q = 0;
  for (const std::uint32_t i : near_) {
    const std::uint32_t a = contacts.offset[i], b = contacts.offset[i + 1];
    std::copy_n(history_saved_.begin() + q, b - a, history.pair.begin() + a);
    history.wall[i] = history_saved_[q + (b - a)];
    q += b - a + 1;
  }
}

// `fresh` (the first of a half step): the step starts from the force in the fluid fields
// of this evaluation, not the last sub-step's in the previous ones (a sub-step would feel
// those for h, this step for h_free: its x would lag by h_free^2 / 2 times the change).
// The near spheres are put back after it.
double MultirateHalfStep::free_step(const DemStepParams& p, DemParticles& s, SphereDrag& drag,
                                    double h, double weight, bool fresh) {
  const long n = static_cast<long>(s.n_owned);
  const FluidForceWindow window{true, weight, p.variational};
  const auto& g = p.gravity;
  const auto& G = p.mean_pressure_gradient;
  double* const drag_c = s.drag_c.data();
  const PairIsa isa = drag.isa;
  double max_step2 = 0.0, rate_max = 0.0;
#pragma omp parallel if (n > kMinParallelSpheres) reduction(max : max_step2, rate_max)
  {
    const auto [begin, end] = thread_rows({}, n, 1.0);
    double aox[kSphereBlock], aoy[kSphereBlock], aoz[kSphereBlock];
    for (std::size_t block = begin; block < end; block += kSphereBlock) {
      const std::size_t block_end = std::min(end, block + kSphereBlock);
      if (fresh) {
        fluid_forces(p.drag, s, p.fluid, block, block_end, FluidForceWindow{}, drag_c, isa);
        for (std::size_t j = block; j < block_end; ++j) {
          const double inv_m = 1.0 / s.mass[j];
          const double vm = mean_gradient_share(s.radius[j], inv_m);
          s.ax[j] = s.fx[j] * inv_m + g[0] + G[0] * vm;
          s.ay[j] = s.fy[j] * inv_m + g[1] + G[1] * vm;
          s.az[j] = s.fz[j] * inv_m + g[2] + G[2] * vm;
        }
      }
      for (std::size_t j = block; j < block_end; ++j) {
        aox[j - block] = s.ax[j];
        aoy[j - block] = s.ay[j];
        aoz[j - block] = s.az[j];
        max_step2 = std::max(max_step2, predict(s, j, h));
        s.overlap_max[j] = 0.0;
      }
      rate_max = std::max(rate_max,
                          fluid_forces(p.drag, s, p.fluid, block, block_end, window, drag_c, isa));
      for (std::size_t j = block; j < block_end; ++j) {
        const double inv_m = 1.0 / s.mass[j];
        const double vm = mean_gradient_share(s.radius[j], inv_m);
        s.ax[j] = s.fx[j] * inv_m + g[0] + G[0] * vm;
        s.ay[j] = s.fy[j] * inv_m + g[1] + G[1] * vm;
        s.az[j] = s.fz[j] * inv_m + g[2] + G[2] * vm;
        correct(s, j, 0.5 * h, aox[j - block], aoy[j - block], aoz[j - block]);
      }
    }
  }
  drag.rate_max = rate_max;
  return max_step2;
}

// As the plain sub-steps, over the near spheres' rows; their neighbours out of reach stand
// where their own step left them.
template <class Contact>
double MultirateHalfStep::near_substeps(const Contact& contact, const DemStepParams& p,
                                        DemParticles& s, SphereLists& lists, SphereDrag& drag,
                                        double h, int count, double weight) {
  const long m = static_cast<long>(near_.size());
  const std::uint32_t* const near = near_.data();
  a_old_.resize(m);
  constexpr bool kSpin = Contact::kHistory;
  OldTorque& t_old = torque_old_;
  const ContactNeighbourList& contacts = lists.contacts();
  ContactHistory& history = lists.history();
  if constexpr (kSpin) {
    history.require_aligned(contacts, s.n_owned);
    t_old.x.resize(m);
    t_old.y.resize(m);
    t_old.z.resize(m);
  }
  const double bf = contact.normal.beta_factor();
  const HaloImages images = lists.halo().images();
  const FluidForceWindow window{true, weight, p.variational};
  const auto& g = p.gravity;
  const auto& G = p.mean_pressure_gradient;
  double* const drag_c = s.drag_c.data();
  double* const aox = a_old_.x.data();
  double* const aoy = a_old_.y.data();
  double* const aoz = a_old_.z.data();
  double reach = 0.0, rate_max = 0.0;
  const RankComm& comm = lists.halo().comm();
  for (int k = 0; k < count; ++k) {
    const double finish = k > 0 ? 0.5 * h : 0.0;  // the previous sub-step's corrector
    double max_step2 = 0.0;
#pragma omp parallel for schedule(static) reduction(max : max_step2) if (m > kMinParallelSpheres)
    for (long q = 0; q < m; ++q) {
      const std::size_t j = near[q];
      max_step2 = std::max(max_step2, correct_and_predict(s, j, finish, h, aox[q], aoy[q], aoz[q]));
      if constexpr (kSpin) {  // as predict_spin and correct_spin
        if (k > 0) correct_spin_of(s, j, h, t_old.x[q], t_old.y[q], t_old.z[q]);
        predict_spin_of(s, j, h, t_old.x[q], t_old.y[q], t_old.z[q]);
      }
    }
    reach += std::sqrt(comm.max(max_step2));
    lists.refresh_for_contacts(s);  // ranks: the copies as their owners now stand
    rate_max = 0.0;
#pragma omp parallel for schedule(static) reduction(max : rate_max) if (m > kMinParallelSpheres)
    for (long q = 0; q < m; ++q) {
      const std::size_t j = near[q];
      rate_max = std::max(
          rate_max, fluid_forces(p.drag, s, p.fluid, j, j + 1, window, drag_c, PairIsa::kBaseline));
      const ContactRow c = contact_row(s, contacts, contact, bf, history, images, p.walls, h, j);
      store_torque_and_overlap<Contact>(s, j, c);
      const double inv_m = 1.0 / s.mass[j];
      const double vm = mean_gradient_share(s.radius[j], inv_m);
      s.ax[j] = (c.fx + s.fx[j]) * inv_m + g[0] + G[0] * vm;
      s.ay[j] = (c.fy + s.fy[j]) * inv_m + g[1] + G[1] * vm;
      s.az[j] = (c.fz + s.fz[j]) * inv_m + g[2] + G[2] * vm;
    }
  }
#pragma omp parallel for schedule(static) if (m > kMinParallelSpheres)
  for (long q = 0; q < m; ++q) {
    const std::size_t j = near[q];
    correct(s, j, 0.5 * h, aox[q], aoy[q], aoz[q]);
    if constexpr (kSpin) correct_spin_of(s, j, h, t_old.x[q], t_old.y[q], t_old.z[q]);
  }
  drag.rate_max = rate_max;
  return reach;
}

}  // namespace sphdem
