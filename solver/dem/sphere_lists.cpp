#include "dem/sphere_lists.hpp"

#include <algorithm>
#include <cmath>

#include "dem/history_migration.hpp"
#include "domain/reorder.hpp"

namespace sphdem {

// With tangential or rolling parts, the contact history goes to its id-keyed store
// before the list changes and comes back aligned with the new list.
void SphereLists::rebuild(DemParticles& s) {
  if (history_on_) history_.save(s, contacts_);  // no-op if already saved (a sort)
  for (std::size_t i = 0; i < s.n_owned; ++i) {
    s.x[i] = box_.wrap(0, s.x[i]);
    s.y[i] = box_.wrap(1, s.y[i]);
    s.z[i] = box_.wrap(2, s.z[i]);
  }
  s.resize(s.n_owned);
  if (decomposition_) distribute(s);
  for (std::size_t i = 0; i < s.n_owned; ++i) {
    s.x0[i] = s.x[i];
    s.y0[i] = s.y[i];
    s.z0[i] = s.z[i];
  }
  double rmax = 0;
  for (std::size_t i = 0; i < s.n_owned; ++i) rmax = std::max(rmax, s.radius[i]);
  rmax = halo_.comm().max(rmax);
  const double skin = skin_fraction_ * 2.0 * rmax;
  const double contact_cut = 2.0 * rmax + skin;
  // (a kernel centred on the spheres reaches further by the skin they may move before
  // the next rebuild)
  const double needed = std::max({reach_.needed, 2.0 * rmax, reach_.sphere_kernel});
  const double wanted = std::max(
      {reach_.wanted, contact_cut, reach_.sphere_kernel > 0 ? reach_.sphere_kernel + skin : 0.0});
  if (decomposition_)
    halo_.build(*decomposition_, std::max(needed, wanted), s.x.data(), s.y.data(), s.z.data(),
                s.n_owned);
  else
    halo_.build(box_, box_.halo_width(needed, wanted), s.x.data(), s.y.data(), s.z.data(),
                s.n_owned);
  s.resize(s.n_owned + halo_.n_ghost());
  halo_.fill_positions(s.x.data(), s.y.data(), s.z.data());
  s.for_each_field([&](const FieldInfo& field, auto& v) {
    if (field.filled_on_build()) halo_.fill(v);
  });
  if (rmax > 0.0) {  // (on ranks: spheres on any rank)
    cells_.build(s.x.data(), s.y.data(), s.z.data(), s.size(), contact_cut);
    contacts_.build(s, cells_, skin);
  }
  if (halo_.ranks()) {  // the copies the contact rows read, refreshed alone each sub-step
    std::vector<std::uint8_t> wanted(halo_.n_ghost(), 0);
    if (rmax > 0.0)
      for (const std::uint32_t j : contacts_.neighbour)
        if (j >= s.n_owned) wanted[j - s.n_owned] = 1;
    halo_.select(wanted);
  }
  if (history_on_) history_.load(s, contacts_);
  drift_ = 0.0;
  ++builds_;
}

// Several ranks: each owned sphere to the rank that owns its cell, its contact records
// (in the keyed store since rebuild's save) with it.
void SphereLists::distribute(DemParticles& s) {
  const RankComm& comm = halo_.comm();
  std::vector<int> dest(s.n_owned);
  std::vector<std::int64_t> leaving_id;
  std::vector<int> leaving_dest;
  for (std::size_t i = 0; i < s.n_owned; ++i) {
    dest[i] = decomposition_->owner(s.x[i], s.y[i], s.z[i]);
    if (dest[i] == comm.rank()) continue;
    leaving_id.push_back(s.id[i]);
    leaving_dest.push_back(dest[i]);
  }
  if (history_on_) migrate_history(comm, history_, leaving_id, leaving_dest);
  migrate(comm, s, dest);
}

void SphereLists::sort_by_cell(DemParticles& s, double cell_size) {
  if (history_on_) history_.save(s, contacts_);  // while the list matches the arrays
  s.resize(s.n_owned);
  if (s.n_owned > 0) sort_owned_by_cell(s, cell_size);
  rebuild(s);
}

void SphereLists::moved(DemParticles& s, double max_step2) {
  drift_ += std::sqrt(halo_.comm().max(max_step2));  // every rank the same decision
  if (drift_ > 0.5 * skin()) drift_ = displacement_since_build(s);
  if (drift_ > 0.5 * skin()) rebuild(s);
}

bool SphereLists::holds_for(DemParticles& s, double reach) {
  if (drift_ + reach > 0.5 * skin()) drift_ = displacement_since_build(s);
  if (drift_ + reach > 0.5 * skin()) rebuild(s);
  return !(reach > 0.5 * skin());
}

double SphereLists::displacement_since_build(const DemParticles& s) const {
  const long n = static_cast<long>(s.n_owned);
  double max_disp2 = 0.0;
#pragma omp parallel for schedule(static) reduction(max : max_disp2) if (n > kMinParallelSpheres)
  for (long j = 0; j < n; ++j) {
    const double dx = s.x[j] - s.x0[j], dy = s.y[j] - s.y0[j], dz = s.z[j] - s.z0[j];
    max_disp2 = std::max(max_disp2, dx * dx + dy * dy + dz * dz);
  }
  return std::sqrt(halo_.comm().max(max_disp2));
}

void SphereLists::refresh_halo(DemParticles& s) const {
  refresh_copies(halo_, s);
}

void SphereLists::write(CheckpointWriter& w, const DemParticles& s) const {
  const std::vector<ContactHistory::Record> records = this->records(s);
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
  w.distributed("contacts/id", id, id.size());  // each rank its spheres' records
  w.distributed("contacts/partner", partner, partner.size());
  w.distributed("contacts/xi", xi, xi.size());
  w.distributed("contacts/mr", mr, mr.size());
  w.scalar("dem/reach_needed", reach_.needed);
  w.scalar("dem/reach_wanted", reach_.wanted);
  w.scalar("dem/reach_sphere_kernel", reach_.sphere_kernel);
}

void SphereLists::read(const CheckpointReader& r) {
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
  reach_ = {r.scalar<double>("dem/reach_needed"), r.scalar<double>("dem/reach_wanted"),
            r.scalar<double>("dem/reach_sphere_kernel")};
}

}  // namespace sphdem
