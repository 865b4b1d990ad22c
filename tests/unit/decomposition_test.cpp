// The decomposition over ranks (domain/sfc_grid.hpp, domain/sfc_partition.hpp), with the
// ranks emulated in one process: the curve, the weighted cuts, and the halo each rank
// sends against a brute-force search of every pair within reach.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <set>
#include <tuple>

#include "domain/sfc_grid.hpp"
#include "domain/sfc_partition.hpp"

namespace sphdem {
namespace {

// A Hilbert curve (not a Morton order): every key on a 2^b cube once, and consecutive keys
// face neighbours.
TEST(SfcGrid, HilbertKeysVisitEveryCellOnceByFaceSteps) {
  for (int bits = 1; bits <= 4; ++bits) {
    const std::uint32_t n = 1u << bits;
    std::vector<std::array<std::uint32_t, 3>> at(std::size_t(n) * n * n, {n, n, n});
    for (std::uint32_t z = 0; z < n; ++z)
      for (std::uint32_t y = 0; y < n; ++y)
        for (std::uint32_t x = 0; x < n; ++x) {
          const std::uint64_t k = hilbert_key(x, y, z, bits);
          ASSERT_LT(k, at.size());
          ASSERT_EQ(at[k][0], n) << "key " << k << " twice";
          at[k] = {x, y, z};
        }
    for (std::size_t k = 1; k < at.size(); ++k) {
      int step = 0;
      for (int d = 0; d < 3; ++d)
        step += std::abs(static_cast<int>(at[k][d]) - static_cast<int>(at[k - 1][d]));
      ASSERT_EQ(step, 1) << "bits " << bits << " key " << k;
    }
  }
}

TEST(SfcGrid, CellsCoverTheBoxAndTheCurveEveryCell) {
  Box box{{0, 0, 0}, {0.05, 0.05, 1.0}, {true, true, false}};
  const SfcGrid grid(box, 0.0125);
  EXPECT_EQ(grid.cells(), (std::array<int, 3>{4, 4, 64}));  // powers of two
  EXPECT_EQ(grid.curve().size(), 4u * 4 * 64);
  std::vector<int> seen(grid.cell_count(), 0);
  for (const std::uint32_t i : grid.curve()) ++seen[i];
  EXPECT_EQ(std::count(seen.begin(), seen.end(), 1), static_cast<long>(grid.cell_count()));
  EXPECT_EQ(grid.cell_of(-0.001, 0.051, 1.2), (std::array<int, 3>{3, 0, 63}));  // wrapped, clamped
  EXPECT_EQ(grid.cell(grid.index({2, 3, 41})), (std::array<int, 3>{2, 3, 41}));
}

// A settling bed: ten times the work per cell in the bottom fifth, none in the top half.
std::vector<std::uint64_t> bed_weights(const SfcGrid& grid, std::mt19937_64& rng) {
  std::uniform_int_distribution<int> noise(0, 20);
  std::vector<std::uint64_t> w(grid.cell_count());
  for (std::size_t i = 0; i < w.size(); ++i) {
    const double z = (grid.cell(i)[2] + 0.5) / grid.cells()[2];
    w[i] = z < 0.2 ? 1000 + noise(rng) : z < 0.5 ? 100 + noise(rng) : 0;
  }
  return w;
}

TEST(SfcPartition, WeightedCutsAreContiguousAndWithinOneCellOfTheMean) {
  Box box{{0, 0, 0}, {0.05, 0.05, 1.0}, {true, true, false}};
  const SfcGrid grid(box, 0.00625);  // 8 x 8 x 128
  std::mt19937_64 rng(7);
  const std::vector<std::uint64_t> w = bed_weights(grid, rng);
  const std::uint64_t w_max = *std::max_element(w.begin(), w.end());
  for (int R : {1, 2, 3, 4, 7, 16}) {
    const SfcPartition part = partition_curve(grid, w, R);
    ASSERT_EQ(part.ranks(), R);
    EXPECT_EQ(part.first.front(), 0u);
    EXPECT_EQ(part.first.back(), grid.cell_count());
    for (int r = 0; r < R; ++r) EXPECT_LT(part.first[r], part.first[r + 1]) << "R " << R;
    const std::vector<std::uint64_t> rw = rank_weights(grid, part, w);
    std::uint64_t total = 0;
    for (auto x : rw) total += x;
    for (int r = 0; r < R; ++r)
      EXPECT_LE(std::abs(static_cast<double>(rw[r]) - double(total) / R), double(w_max))
          << "R " << R << " rank " << r;
    EXPECT_LT(load_imbalance(rw), 1.01) << "R " << R;
    EXPECT_EQ(partition_curve(grid, w, R).first, part.first);  // the same cuts every time
  }
}

// The control: cut by cell count (no weights), the bed's ranks carry the load.
TEST(SfcPartition, EqualCellCountsDoNotBalanceABed) {
  Box box{{0, 0, 0}, {0.05, 0.05, 1.0}, {true, true, false}};
  const SfcGrid grid(box, 0.00625);
  std::mt19937_64 rng(7);
  const std::vector<std::uint64_t> w = bed_weights(grid, rng);
  const std::vector<std::uint64_t> none(grid.cell_count(), 0);
  const SfcPartition by_count = partition_curve(grid, none, 4);
  for (int r = 0; r < 4; ++r) EXPECT_EQ(by_count.first[r + 1] - by_count.first[r], 2048u);
  EXPECT_GT(load_imbalance(rank_weights(grid, by_count, w)), 2.0);
  EXPECT_LT(load_imbalance(rank_weights(grid, partition_curve(grid, w, 4), w)), 1.01);
}

TEST(SfcPartition, MoreRanksThanCellsIsRefused) {
  Box box{{0, 0, 0}, {1, 1, 1}, {true, true, false}};
  const SfcGrid grid(box, 0.5);  // 8 cells
  const std::vector<std::uint64_t> w(8, 1);
  EXPECT_NO_THROW(partition_curve(grid, w, 8));
  EXPECT_THROW(partition_curve(grid, w, 9), std::invalid_argument);
  EXPECT_THROW(partition_curve(grid, w, 0), std::invalid_argument);
}

// The halo keeps a copy where it lies within the reach of a cell the receiver owns, so the
// distance to a cell must bound the distance to every point the cell holds: past the walls
// too, where cell_of clamps wall particles into the outer cells (a wall particle 0.5 mm
// below the box and another 0.1 mm below it in the next cell are nearer than the first is
// to that cell's box).
TEST(SfcGrid, DistanceToACellBoundsEveryPointItHolds) {
  const Box box{{0, 0, 0}, {0.2, 0.2, 1.0}, {true, true, false}};
  const SfcGrid grid(box, 0.05);
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  auto point = [&] {  // in x and y inside the box (wrapped), in z up to 0.1 past the walls
    return std::array<double, 3>{0.2 * u(rng), 0.2 * u(rng), -0.1 + 1.2 * u(rng)};
  };
  int past_walls = 0;
  for (int k = 0; k < 200000; ++k) {
    const std::array<double, 3> p = point(), q = point();
    const double r2 = (p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) +
                      (p[2] - q[2]) * (p[2] - q[2]);
    const std::size_t c = grid.index(grid.cell_of(q[0], q[1], q[2]));
    ASSERT_LE(grid.distance2_to_cell(c, p.data()), r2 * (1 + 1e-12))
        << "p (" << p[0] << ", " << p[1] << ", " << p[2] << "), q (" << q[0] << ", " << q[1] << ", "
        << q[2] << ")";
    past_walls += (q[2] < 0 || q[2] > 1.0) && (p[2] < 0 || p[2] > 1.0);
  }
  EXPECT_GT(past_walls, 1000);
}

TEST(SfcGrid, DecompositionCellHalvesTheReachWhereTheBoxHoldsFewCellsARank) {
  const Box column{{0, 0, 0}, {0.2, 0.2, 1.0}, {true, true, false}};
  // 4 x 4 x 16 = 256 cells of the reach: enough for 4 ranks, too few for 5
  EXPECT_EQ(decomposition_cell(column, 0.05, 4), 0.05);
  EXPECT_EQ(decomposition_cell(column, 0.05, 5), 0.025);
  EXPECT_EQ(SfcGrid(column, decomposition_cell(column, 0.05, 5)).cell_count(), 8u * 8u * 32u);
  // 1 x 1 x 4 cells of 0.2, then 2 x 2 x 8 of 0.1: halved twice, no more
  EXPECT_EQ(decomposition_cell(column, 0.2, 4), 0.05);
  EXPECT_EQ(decomposition_cell(column, 0.2, 1), 0.05);
}

// Every pair of particles within the reach whose owners differ, or that meet through a
// periodic face, is in the halo: the rank of one receives the other's cell at the image
// the pair needs. Brute force over every pair and every periodic image.
void expect_halo_complete(const Box& box, double reach, double min_cell, int R, unsigned seed) {
  const SfcGrid grid(box, min_cell);
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const int n = 400;
  std::vector<std::array<double, 3>> x(n);
  std::vector<std::uint64_t> w(grid.cell_count(), 0);
  for (auto& p : x) {
    for (int d = 0; d < 3; ++d) p[d] = box.lo[d] + box.length(d) * u(rng) * (d == 2 ? u(rng) : 1.0);
    w[grid.index(grid.cell_of(p[0], p[1], p[2]))] += 1 + (p[2] < 0.3 * box.length(2) ? 9 : 0);
  }
  const SfcPartition part = partition_curve(grid, w, R);
  std::array<int, 3> k{};
  for (int d = 0; d < 3; ++d) k[d] = static_cast<int>(std::ceil(reach / grid.cell_size(d)));
  std::vector<std::vector<HaloSend>> sends(R);
  for (int r = 0; r < R; ++r) sends[r] = halo_sends(grid, part, r, k);
  long needed = 0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const auto ci = grid.cell_of(x[i][0], x[i][1], x[i][2]);
      const auto cj = grid.cell_of(x[j][0], x[j][1], x[j][2]);
      const int ri = part.owner(grid, ci), rj = part.owner(grid, cj);
      std::array<int, 3> s{};
      const int span[3] = {box.periodic[0] ? 2 : 0, box.periodic[1] ? 2 : 0,
                           box.periodic[2] ? 2 : 0};
      for (s[2] = -span[2]; s[2] <= span[2]; ++s[2])
        for (s[1] = -span[1]; s[1] <= span[1]; ++s[1])
          for (s[0] = -span[0]; s[0] <= span[0]; ++s[0]) {
            if (i == j && s == std::array<int, 3>{0, 0, 0}) continue;
            double r2 = 0;
            for (int d = 0; d < 3; ++d) {
              const double dx = x[i][d] - (x[j][d] + s[d] * box.length(d));
              r2 += dx * dx;
            }
            if (r2 > reach * reach) continue;
            if (ri == rj && s == std::array<int, 3>{0, 0, 0}) continue;  // both owned by one rank
            ++needed;
            const HaloSend want{static_cast<std::uint32_t>(grid.index(cj)), ri, s, {}};
            ASSERT_TRUE(std::binary_search(sends[rj].begin(), sends[rj].end(), want))
                << "R " << R << ": rank " << rj << " does not send cell " << want.cell
                << " to rank " << ri << " at image (" << s[0] << "," << s[1] << "," << s[2] << ")";
          }
    }
  EXPECT_GT(needed, 0) << "R " << R;
}

TEST(SfcPartition, HaloHoldsEveryPairWithinReach) {
  // a column periodic in x and y (the shipped scenes' box), a narrow one where the reach
  // exceeds half the width (images of the same cell on both sides), and cells finer
  // than the reach
  const Box column{{0, 0, 0}, {0.2, 0.2, 1.0}, {true, true, false}};
  const Box narrow{{0, 0, 0}, {0.05, 0.05, 0.5}, {true, true, false}};
  const Box cube{{0, 0, 0}, {0.3, 0.3, 0.3}, {true, true, true}};
  for (int R : {1, 2, 3, 4}) {
    expect_halo_complete(column, 0.06, 0.06, R, 1 + R);
    expect_halo_complete(column, 0.06, 0.02, R, 11 + R);
    expect_halo_complete(narrow, 0.03, 0.01, R, 21 + R);
    expect_halo_complete(cube, 0.05, 0.05, R, 31 + R);
  }
}

}  // namespace
}  // namespace sphdem
