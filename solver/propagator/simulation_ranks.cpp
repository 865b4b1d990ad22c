// Simulation on several ranks: its share of the placed or read particles, the cuts, and
// the balance and migration at a fluid rebuild (ARCHITECTURE.md, Ranks). One rank never
// enters these.
#include <fmt/format.h>

#include <algorithm>
#include <cstdint>
#include <vector>

#include "domain/rank_halo.hpp"
#include "propagator/simulation.hpp"

namespace sphdem {

namespace {

// A rebuild on several ranks recuts the curve where the largest rank's counted work passes
// the mean by more than this (issue 36).
constexpr double kRebalanceThreshold = 1.10;

// The particle arrays with the state a step keeps from its start (u^n, rho^n), so that a
// rebuild inside the step migrates them with their particles.
struct FluidWithStepStart {
  FluidParticles& f;
  std::vector<double>&u0x, &u0y, &u0z, &rho0;
  std::size_t& n_owned;
  bool in_step;  // the same on every rank: the exchanges below are collective
  template <class F>
  void for_each_field(F&& fn) {
    f.for_each_field(fn);
    if (!in_step) return;
    fn(FieldInfo{"u0x", kScratch}, u0x);
    fn(FieldInfo{"u0y", kScratch}, u0y);
    fn(FieldInfo{"u0z", kScratch}, u0z);
    fn(FieldInfo{"rho0", kScratch}, rho0);
  }
};

// Of the particles every rank read, the slice [first, first + count) in file order.
template <class Particles>
void keep_slice(Particles& p, std::size_t first, std::size_t count) {
  p.for_each_field([&](const FieldInfo&, auto& v) {
    std::copy(v.begin() + first, v.begin() + first + count, v.begin());
    v.resize(count);
  });
  p.n_owned = count;
}

std::size_t slice_start(const std::vector<std::int64_t>& counts, int rank) {
  std::size_t first = 0;
  for (int q = 0; q < rank; ++q) first += static_cast<std::size_t>(counts[q]);
  return first;
}

}  // namespace

// Several ranks, continuing a run: written on as many ranks, each takes back its own slice
// with the cuts and the counted work (the run goes on bit for bit); on another count, each
// keeps the particles in its cells of a fresh cut by the work the run had counted.
void Simulation::resume_share(const CheckpointReader& r) {
  const double cell = r.has("ranks/grid_cell") ? r.scalar<double>("ranks/grid_cell") : cell_size_;
  const auto fluid_count = r.array<std::int64_t>("ranks/fluid_count");
  const auto sphere_count = r.array<std::int64_t>("ranks/sphere_count");
  std::vector<std::uint64_t> work;
  if (r.has("ranks/work") && comm_.rank() == 0)  // summed once, at the next balance
    for (const std::int64_t w : r.array<std::int64_t>("ranks/work")) work.push_back(w);
  const int R = comm_.size(), me = comm_.rank();
  if (static_cast<int>(fluid_count.size()) == R && r.has("ranks/cuts")) {
    decompose(cell, /*keep_cells=*/false);
    keep_slice(fluid_, slice_start(fluid_count, me), fluid_count[me]);
    keep_slice(dem_.spheres(), slice_start(sphere_count, me), sphere_count[me]);
    std::vector<std::uint32_t> cuts;
    for (const std::int64_t c : r.array<std::int64_t>("ranks/cuts")) cuts.push_back(c);
    work.resize(decomposition_->grid().cell_count(), 0);
    decomposition_->restore(std::move(cuts), std::move(work));
    return;
  }
  decompose(cell, /*keep_cells=*/true);
  work.resize(decomposition_->grid().cell_count(), 0);
  decomposition_->restore({}, std::move(work));
}

// Several ranks: the box's Hilbert-ordered cells of at least `cell` (the fluid lists' cell)
// cut by cell count, and (keep_cells) of the global set every rank holds, the share in its
// cells kept.
void Simulation::decompose(double cell, bool keep_cells) {
  const SfcGrid grid(params_.box, cell);
  if (grid.cell_count() < static_cast<std::size_t>(comm_.size()))
    throw SceneError(fmt::format(  // (every rank throws it: rank 0 prints it)
        "{}: {} ranks, but the box cuts into only {} cells of {:.3g} m (the reach of a pair, "
        "halved at most twice): run on at "
        "most {} ranks, or enlarge the domain",
        scene_.name, comm_.size(), grid.cell_count(), cell, grid.cell_count()));
  decomposition_.emplace(comm_, params_.box, cell);
  grid_cell_ = cell;
  balanced_at_ = steps_;
  dem_.set_decomposition(&*decomposition_);
  if (!keep_cells) return;
  FluidParticles& f = fluid_;
  f.resize(f.n_owned);
  std::vector<int> dest(f.n_owned);
  for (std::size_t a = 0; a < f.n_owned; ++a)
    dest[a] = decomposition_->owner(f.x[a], f.y[a], f.z[a]);
  keep_share(comm_, f, dest);
  DemParticles& s = dem_.spheres();
  const Box& box = params_.box;
  s.resize(s.n_owned);
  dest.resize(s.n_owned);
  for (std::size_t i = 0; i < s.n_owned; ++i)
    dest[i] = decomposition_->owner(box.wrap(0, s.x[i]), box.wrap(1, s.y[i]), box.wrap(2, s.z[i]));
  keep_share(comm_, s, dest);
}

// Several ranks, at a rebuild: the work counted since the last one summed, the curve recut
// where it is out of balance (or when forced), and each particle sent to the rank that owns
// its cell, with the state the step keeps from its start.
void Simulation::distribute_fluid() {
  Decomposition& d = *decomposition_;
  d.balance(kRebalanceThreshold, force_rebalance_, steps_ - balanced_at_);
  balanced_at_ = steps_;
  force_rebalance_ = false;
  FluidParticles& f = fluid_;
  std::vector<int> dest(f.n_owned);
  for (std::size_t a = 0; a < f.n_owned; ++a) dest[a] = d.owner(f.x[a], f.y[a], f.z[a]);
  FluidWithStepStart moving{f, u0x_, u0y_, u0z_, rho0_, f.n_owned, in_step_};
  migrate(comm_, moving, dest);
}

}  // namespace sphdem
