// The decomposition on real ranks (Cornerstone's test, sphexa-org/sphexa domain_nranks):
// every rank builds the same seeded global set of fluid-like particles with global ids
// and keeps an arbitrary slice; the weights are summed over the ranks, the curve cut,
// the particles migrated to their owners and the halo built. Then, summed by global id,
// each particle's neighbours within the reach (owned and copies) equal a brute-force
// count over the whole set and every periodic image, exactly; a field filled into the
// copies equals its owner's; and the reverse scatter brings each copy's integer share back.
//
//   mpirun -np R halo_mpi_test R     (the test fails unless it got R ranks)
#include <gtest/gtest.h>
#include <mpi.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <set>
#include <vector>

#include "dem/history_migration.hpp"
#include "domain/decomposition.hpp"
#include "domain/rank_comm.hpp"
#include "domain/rank_halo.hpp"
#include "domain/sfc_grid.hpp"
#include "domain/sfc_partition.hpp"
#include "mpi_gtest_main.hpp"

namespace sphdem {
namespace {

int g_expected_ranks = 0;

// Positions, a global id and one more field: the least a registry needs.
struct Points {
  std::vector<double> x, y, z;
  std::vector<std::int64_t> id;
  std::vector<double> load;
  std::size_t n_owned = 0;
  std::size_t size() const { return x.size(); }
  template <class F>
  void for_each_field(F&& f) {
    f(FieldInfo{"x", kState | kPosition}, x);
    f(FieldInfo{"y", kState | kPosition}, y);
    f(FieldInfo{"z", kState | kPosition}, z);
    f(FieldInfo{"id", kState | kConstant}, id);
    f(FieldInfo{"load", kState}, load);
  }
  void resize(std::size_t n) {
    for_each_field([n](const FieldInfo&, auto& v) { v.resize(n); });
  }
};

struct Scenario {
  Box box;
  double reach, min_cell;
  int n;
};

// The global set: denser at the bottom (a settling bed), seeded, the same on every rank.
std::vector<std::array<double, 3>> global_set(const Scenario& s, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<std::array<double, 3>> p(s.n);
  for (auto& q : p)
    for (int d = 0; d < 3; ++d)
      q[d] = s.box.lo[d] + s.box.length(d) * (d == 2 ? u(rng) * u(rng) : u(rng));
  return p;
}

// This rank's slice of the global set (an arbitrary one: not by position), with ids and
// a field of known values.
Points slice_of(const std::vector<std::array<double, 3>>& all, int R, int me) {
  Points p;
  const std::size_t n = all.size(), lo = n * me / R, hi = n * (me + 1) / R;
  p.resize(hi - lo);
  p.n_owned = hi - lo;
  for (std::size_t i = lo; i < hi; ++i) {
    p.x[i - lo] = all[i][0];
    p.y[i - lo] = all[i][1];
    p.z[i - lo] = all[i][2];
    p.id[i - lo] = static_cast<std::int64_t>(i);
    p.load[i - lo] = 1.0 + static_cast<double>(i % 7);
  }
  return p;
}

void run_case(const Scenario& s, unsigned seed) {
  const RankComm comm;
  ASSERT_EQ(comm.size(), g_expected_ranks) << "the launcher started other rank counts";
  const int R = comm.size(), me = comm.rank();
  const auto all = global_set(s, seed);
  Points p = slice_of(all, R, me);
  const SfcGrid grid(s.box, s.min_cell);
  std::vector<std::uint64_t> w(grid.cell_count(), 0);  // work: one per particle here
  for (std::size_t i = 0; i < p.n_owned; ++i) ++w[grid.index(grid.cell_of(p.x[i], p.y[i], p.z[i]))];
  comm.sum(w);
  const SfcPartition part = partition_curve(grid, w, R);
  std::vector<int> dest(p.n_owned);
  for (std::size_t i = 0; i < p.n_owned; ++i)
    dest[i] = part.owner(grid, grid.cell_of(p.x[i], p.y[i], p.z[i]));
  migrate(comm, p, dest);
  // each particle once, on the rank that owns its cell
  EXPECT_EQ(comm.sum(p.n_owned), std::uint64_t(s.n));
  for (std::size_t i = 0; i < p.n_owned; ++i)
    ASSERT_EQ(part.owner(grid, grid.cell_of(p.x[i], p.y[i], p.z[i])), me);
  std::vector<std::uint64_t> seen(s.n, 0);
  for (std::size_t i = 0; i < p.n_owned; ++i) ++seen[p.id[i]];
  comm.sum(seen);
  for (int i = 0; i < s.n; ++i) ASSERT_EQ(seen[i], 1u) << "id " << i;
  // the halo
  RankHalo halo;
  halo.build(comm, grid, part, s.reach, p.x.data(), p.y.data(), p.z.data(), p.n_owned);
  p.resize(p.n_owned + halo.n_ghost());
  halo.fill_positions(comm, p.x.data(), p.y.data(), p.z.data());
  halo.fill(comm, p.id);
  halo.fill(comm, p.load);
  // neighbours of each owned particle among owned and copies, by global id
  std::vector<std::uint64_t> count(s.n, 0);
  for (std::size_t i = 0; i < p.n_owned; ++i)
    for (std::size_t j = 0; j < p.size(); ++j) {
      if (j == i) continue;
      const double dx = p.x[i] - p.x[j], dy = p.y[i] - p.y[j], dz = p.z[i] - p.z[j];
      count[p.id[i]] += dx * dx + dy * dy + dz * dz <= s.reach * s.reach;
    }
  comm.sum(count);
  // brute force over the whole set and every image (on every rank: cheap at this size)
  for (int i = 0; i < s.n; ++i) {
    std::uint64_t want = 0;
    for (int j = 0; j < s.n; ++j)
      for (int sx = -1; sx <= 1; ++sx)
        for (int sy = -1; sy <= 1; ++sy)
          for (int sz = -1; sz <= 1; ++sz) {
            const int sh[3] = {sx, sy, sz};
            bool ok = !(i == j && sx == 0 && sy == 0 && sz == 0);
            double r2 = 0;
            for (int d = 0; d < 3; ++d) {
              ok = ok && (s.box.periodic[d] || sh[d] == 0);
              const double dd = all[i][d] - (all[j][d] + sh[d] * s.box.length(d));
              r2 += dd * dd;
            }
            want += ok && r2 <= s.reach * s.reach;
          }
    ASSERT_EQ(count[i], want) << "particle " << i << " on " << R << " ranks";
  }
  // copies hold their owner's fields; the reverse scatter returns one share per copy
  for (std::size_t g = p.n_owned; g < p.size(); ++g)
    ASSERT_EQ(p.load[g], 1.0 + static_cast<double>(p.id[g] % 7));
  std::vector<double> share(p.size(), 0.0);
  for (std::size_t g = p.n_owned; g < p.size(); ++g) share[g] = 1.0;
  halo.add_to_sources(comm, share.data(), 1);
  std::vector<std::uint64_t> copies(s.n, 0), returned(s.n, 0);
  for (std::size_t g = p.n_owned; g < p.size(); ++g) ++copies[p.id[g]];
  for (std::size_t i = 0; i < p.n_owned; ++i) returned[p.id[i]] = std::uint64_t(share[i]);
  comm.sum(copies);
  comm.sum(returned);
  EXPECT_EQ(returned, copies);
  EXPECT_GT(comm.sum(halo.n_ghost()), 0u);
  // a refresh of the selected copies (those of even id): the owners move by 1 m and load
  // +100; the selected copies follow (with their image's shift: to round-off), the others
  // keep their values
  std::vector<std::uint8_t> wanted(halo.n_ghost());
  for (std::size_t g = 0; g < wanted.size(); ++g) wanted[g] = p.id[p.n_owned + g] % 2 == 0;
  halo.select(comm, wanted);
  const Points before = p;
  for (std::size_t i = 0; i < p.n_owned; ++i) {
    p.x[i] += 1.0;
    p.load[i] += 100.0;
  }
  halo.fill_selected(comm, p.x.data(), p.y.data(), p.z.data(), {p.load.data()});
  std::size_t refreshed = 0;
  for (std::size_t g = 0; g < wanted.size(); ++g) {
    const std::size_t j = p.n_owned + g;
    EXPECT_DOUBLE_EQ(p.x[j], wanted[g] ? before.x[j] + 1.0 : before.x[j]) << "copy " << g;
    EXPECT_EQ(p.y[j], before.y[j]);
    EXPECT_EQ(p.load[j], wanted[g] ? before.load[j] + 100.0 : before.load[j]) << "copy " << g;
    refreshed += wanted[g];
  }
  EXPECT_EQ(halo.n_selected(), refreshed);
  if (R > 1) {
    EXPECT_GT(comm.sum(refreshed), 0u);
    EXPECT_LT(comm.sum(refreshed), comm.sum(halo.n_ghost()));
  }
}

TEST(RanksHalo, ColumnPeriodicInXY) {
  run_case({{{0, 0, 0}, {0.2, 0.2, 1.0}, {true, true, false}}, 0.07, 0.035, 600}, 5);
}

TEST(RanksHalo, NarrowColumnReachOverHalfItsWidth) {
  run_case({{{0, 0, 0}, {0.05, 0.05, 0.4}, {true, true, false}}, 0.03, 0.015, 500}, 6);
}

TEST(RanksHalo, PeriodicCube) {
  run_case({{{0, 0, 0}, {0.3, 0.3, 0.3}, {true, true, true}}, 0.06, 0.06, 500}, 7);
}

// The contact history follows its spheres: each sphere i carries records (i, i + 1) and
// (i, wall) whose state encodes i; after the spheres and their records migrate, every
// record is on the rank that owns its sphere, none is lost or doubled.
TEST(RanksHalo, ContactHistoryFollowsItsSphere) {
  const RankComm comm;
  ASSERT_EQ(comm.size(), g_expected_ranks);
  const Scenario s{{{0, 0, 0}, {0.2, 0.2, 1.0}, {true, true, false}}, 0.07, 0.035, 600};
  const int R = comm.size(), me = comm.rank();
  const auto all = global_set(s, 9);
  Points p = slice_of(all, R, me);
  std::vector<ContactHistory::Record> records;
  for (std::size_t k = 0; k < p.n_owned; ++k) {
    const std::int64_t i = p.id[k];
    for (const std::int64_t partner : {i + 1, ContactHistory::kBottomWall}) {
      ContactHistory::Record r{i, partner, {}};
      r.state.xi[0] = static_cast<double>(i);
      r.state.mr[2] = static_cast<double>(partner);
      records.push_back(r);
    }
  }
  ContactHistory history;
  history.set_keyed(records);
  const SfcGrid grid(s.box, s.min_cell);
  std::vector<std::uint64_t> w(grid.cell_count(), 0);
  for (std::size_t i = 0; i < p.n_owned; ++i) ++w[grid.index(grid.cell_of(p.x[i], p.y[i], p.z[i]))];
  comm.sum(w);
  const SfcPartition part = partition_curve(grid, w, R);
  std::vector<int> dest(p.n_owned);
  std::vector<std::int64_t> leaving_id;
  std::vector<int> leaving_dest;
  for (std::size_t i = 0; i < p.n_owned; ++i) {
    dest[i] = part.owner(grid, grid.cell_of(p.x[i], p.y[i], p.z[i]));
    if (dest[i] != me) {
      leaving_id.push_back(p.id[i]);
      leaving_dest.push_back(dest[i]);
    }
  }
  migrate(comm, p, dest);
  migrate_history(comm, history, leaving_id, leaving_dest);
  std::set<std::int64_t> owned(p.id.begin(), p.id.begin() + p.n_owned);
  for (const auto& r : history.keyed()) {
    ASSERT_TRUE(owned.count(r.id)) << "record of sphere " << r.id << " on rank " << me;
    EXPECT_EQ(r.state.xi[0], static_cast<double>(r.id));
    EXPECT_EQ(r.state.mr[2], static_cast<double>(r.partner));
  }
  EXPECT_EQ(history.keyed().size(), 2 * p.n_owned);
  EXPECT_EQ(comm.sum(history.keyed().size()), 2u * s.n);
}

// Load balance as a suspension settles: the work per particle grows in the bed at the
// bottom (8), stays in the suspension (3) and falls in the clear liquid above it (1) while
// the bed rises and the suspension's top falls. Each epoch the ranks count their owned
// particles' work, balance() recuts where max/mean passes 1.10 and the particles migrate:
// after it every epoch's load is within 1.10; the cuts of the start, kept as a control,
// drift past it.
TEST(RanksHalo, BalanceFollowsASettlingLoad) {
  const RankComm comm;
  ASSERT_EQ(comm.size(), g_expected_ranks);
  const Scenario s{{{0, 0, 0}, {0.2, 0.2, 1.0}, {true, true, false}}, 0.05, 0.05, 3000};
  const int R = comm.size(), me = comm.rank();
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<std::array<double, 3>> all(s.n);
  for (auto& q : all) q = {0.2 * u(rng), 0.2 * u(rng), u(rng)};
  Points p = slice_of(all, R, me);
  Decomposition dec(comm, s.box, s.min_cell);
  const auto work = [](double z, int epoch) -> std::uint64_t {
    const double bed = 0.03 * epoch, top = 1.0 - 0.08 * epoch;
    return z < bed ? 8 : z < top ? 3 : 1;
  };
  const auto move_to_owners = [&] {
    std::vector<int> dest(p.n_owned);
    for (std::size_t i = 0; i < p.n_owned; ++i) dest[i] = dec.owner(p.x[i], p.y[i], p.z[i]);
    migrate(comm, p, dest);
  };
  SfcPartition start;
  double static_worst = 1.0;
  for (int epoch = 0; epoch < 10; ++epoch) {
    for (std::size_t i = 0; i < p.n_owned; ++i)
      dec.count(p.x[i], p.y[i], p.z[i], work(p.z[i], epoch));
    dec.balance(1.10, /*force=*/epoch == 0);
    move_to_owners();
    EXPECT_LE(dec.imbalance_after(), 1.10) << "epoch " << epoch;
    std::vector<std::uint64_t> w(dec.grid().cell_count(), 0);  // the same load, from the global set
    for (const auto& q : all)
      w[dec.grid().index(dec.grid().cell_of(q[0], q[1], q[2]))] += work(q[2], epoch);
    EXPECT_EQ(load_imbalance(rank_weights(dec.grid(), dec.partition(), w)), dec.imbalance_after());
    if (epoch == 0) start = dec.partition();
    const double fixed = load_imbalance(rank_weights(dec.grid(), start, w));
    static_worst = std::max(static_worst, fixed);
    if (me == 0)
      std::printf("epoch %d: max/mean %.3f before, %.3f after balance; start's cuts %.3f\n", epoch,
                  dec.imbalance_before(), dec.imbalance_after(), fixed);
    for (std::size_t i = 0; i < p.n_owned; ++i) ASSERT_EQ(dec.owner(p.x[i], p.y[i], p.z[i]), me);
  }
  EXPECT_EQ(comm.sum(p.n_owned), std::uint64_t(s.n));
  if (R > 1) {
    EXPECT_GT(static_worst, 1.10);  // the control drifts
  }
}

// The exchange point to point: each rank sends me + 1 values to the next rank and 2 to
// itself, nothing to the others; every value lands in its place, and the tally counts
// one exchange, the bytes that left the rank (not its own copies) and the count exchange.
TEST(RanksComm, ExchangeDeliversInPlaceAndTalliesWhatLeft) {
  const RankComm comm;
  ASSERT_EQ(comm.size(), g_expected_ranks);
  const int R = comm.size(), me = comm.rank(), next = (me + 1) % R;
  std::vector<std::uint64_t> send_count(R, 0);
  send_count[me] += 2;
  send_count[next] += static_cast<std::uint64_t>(me + 1);
  std::vector<std::int64_t> send;  // grouped by destination rank
  for (int q = 0; q < R; ++q)
    for (std::uint64_t k = 0; k < send_count[q]; ++k) send.push_back(1000 * me + 10 * q + k);
  const RankComm::Traffic before = comm.traffic();
  const std::vector<std::uint64_t> recv_count = comm.counts(send_count);
  std::uint64_t n = 0;
  for (const std::uint64_t c : recv_count) n += c;
  std::vector<std::int64_t> recv(n, -1);
  comm.exchange(send.data(), send_count, recv.data(), recv_count, sizeof(std::int64_t));
  std::size_t at = 0;
  for (int q = 0; q < R; ++q)
    for (std::uint64_t k = 0; k < recv_count[q]; ++k, ++at)
      EXPECT_EQ(recv[at], static_cast<std::int64_t>(1000 * q + 10 * me + k)) << "from " << q;
  const RankComm::Traffic& after = comm.traffic();
  const std::uint64_t left = R > 1 ? (me + 1) * sizeof(std::int64_t) : 0;
  EXPECT_EQ(after.exchanges - before.exchanges, R > 1 ? 1u : 0u);
  EXPECT_EQ(after.bytes_sent - before.bytes_sent, left);
  EXPECT_EQ(after.collectives - before.collectives, R > 1 ? 1u : 0u);  // counts()
}

}  // namespace
}  // namespace sphdem

int main(int argc, char** argv) {
  return sphdem::run_mpi_gtests(argc, argv, sphdem::g_expected_ranks);
}
