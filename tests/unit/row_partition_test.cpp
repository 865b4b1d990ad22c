// Contiguous cost-balanced shares of a compressed-row list, one per thread
// (solver/domain/row_partition.hpp), and what they promise the DEM sub-steps: the same
// bits on two threads as on one.
#include "domain/row_partition.hpp"

#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

#include "domain/measured_shares.hpp"
#include "propagator/simulation.hpp"
#include "scene/scene.hpp"

namespace {

using namespace sphdem;

// Offsets of a list whose row i has entries[i] entries.
std::vector<std::uint32_t> offsets(const std::vector<std::uint32_t>& entries) {
  std::vector<std::uint32_t> offset(entries.size() + 1, 0);
  for (std::size_t i = 0; i < entries.size(); ++i) offset[i + 1] = offset[i] + entries[i];
  return offset;
}

// The share of each thread of a team of `threads`.
std::vector<std::pair<std::size_t, std::size_t>> shares(const std::vector<std::uint32_t>& offset,
                                                        std::size_t n, double row_cost,
                                                        int threads) {
  std::vector<std::pair<std::size_t, std::size_t>> out(threads);
#pragma omp parallel num_threads(threads)
  {
    EXPECT_EQ(omp_get_num_threads(), threads);  // (nested or capped teams would void the test)
    out[omp_get_thread_num()] = thread_rows(offset, n, row_cost);
  }
  return out;
}

double cost(const std::vector<std::uint32_t>& offset, double row_cost, std::size_t b,
            std::size_t e) {
  return row_cost * static_cast<double>(e - b) + (offset[e] - offset[b]);
}

// A bed under a dilute suspension: the first fifth of the rows has 20 times the entries.
std::vector<std::uint32_t> bed_under_suspension(std::size_t n) {
  std::vector<std::uint32_t> entries(n, 2);
  for (std::size_t i = 0; i < n / 5; ++i) entries[i] = 40;
  return entries;
}

TEST(RowPartition, SharesAreContiguousCoverEveryRowAndBalanceTheCost) {
  const std::size_t n = 10007;
  const auto offset = offsets(bed_under_suspension(n));
  const double row_cost = 4.0, largest_row = row_cost + 40;
  for (int threads : {2, 3, 4, 7}) {
    const auto s = shares(offset, n, row_cost, threads);
    EXPECT_EQ(s.front().first, 0u);
    EXPECT_EQ(s.back().second, n);
    const double ideal = cost(offset, row_cost, 0, n) / threads;
    for (int t = 0; t < threads; ++t) {
      if (t > 0) {
        EXPECT_EQ(s[t].first, s[t - 1].second) << threads << " threads, share " << t;
      }
      EXPECT_LE(s[t].first, s[t].second);
      EXPECT_NEAR(cost(offset, row_cost, s[t].first, s[t].second), ideal, largest_row)
          << threads << " threads, share " << t;
    }
  }
  // The rows of the bed are the costly ones: the first of two shares ends well before n/2
  // (equal counts would give it 0.7 of the cost).
  const auto two = shares(offset, n, row_cost, 2);
  EXPECT_LT(two[0].second, n / 2 - n / 10);
}

TEST(RowPartition, OneThreadTakesEveryRowAndNoListMeansEqualCounts) {
  const std::size_t n = 1000;
  const auto offset = offsets(bed_under_suspension(n));
  EXPECT_EQ(thread_rows(offset, n, 4.0),
            (std::pair<std::size_t, std::size_t>{0, n}));  // outside a region
  const auto s = shares({}, n, 4.0, 4);                    // no list (e.g. before the first build)
  for (int t = 0; t < 4; ++t) EXPECT_EQ(s[t].second - s[t].first, n / 4) << t;
  const auto empty = shares(offsets({}), 0, 4.0, 2);
  for (const auto& r : empty) EXPECT_EQ(r.first, r.second);
}

// Rows whose cost the list does not show (the first fifth ten times the rest, with equal
// entries): from the estimate's equal halves the measured shares reach equal times within
// a few passes and stay contiguous and complete; a new row count starts again.
TEST(MeasuredShares, MoveToEqualMeasuredTimes) {
  const std::size_t n = 1000;
  const auto offset = offsets(std::vector<std::uint32_t>(n, 2));
  const auto row_time = [&](std::size_t i) { return i < n / 5 ? 10.0 : 1.0; };
  MeasuredShares shares;
  shares.prepare(offset, n, 4.0, 2);
  EXPECT_EQ(shares.split(), (std::vector<std::size_t>{0, n / 2, n}));
  std::vector<double> time(2);
  for (int pass = 0; pass < 12; ++pass) {
#pragma omp parallel num_threads(2)
    {
      EXPECT_EQ(omp_get_num_threads(), 2);
      const auto [b, e] = shares.rows(offset, 4.0);
      double seconds = 0.0;
      for (std::size_t i = b; i < e; ++i) seconds += row_time(i);
      shares.record(seconds);
      time[omp_get_thread_num()] = seconds;
    }
    shares.rebalance();
    shares.prepare(offset, n, 4.0, 2);  // the same n and team: kept
  }
  EXPECT_EQ(shares.split().front(), 0u);
  EXPECT_EQ(shares.split().back(), n);
  EXPECT_NEAR(time[0] / time[1], 1.0, 0.02);  // from 1400 / 500 at the estimate
  shares.prepare(offset, n + 8, 4.0, 2);
  EXPECT_EQ(shares.split(), (std::vector<std::size_t>{0, (n + 8) / 2, n + 8}));
}

// Every DEM pass splits the spheres by these shares and no sum crosses two shares, so a
// dry DEM run gives the bits of one thread on two: a missed or repeated row, or a share
// that moves during a sub-step, would not.
TEST(RowPartition, DryDemOnTwoThreadsGivesTheBitsOfOne) {
  const Scene sc = load_scene_text(R"(
name: settle_threads
domain: {size: [0.0016, 0.0016, 0.003]}
fluid: {enabled: false}
species: [{name: glass, diameter: 1.0e-4, density: 2500}]
particles:
  - {type: lattice, species: glass, voidage: 0.7, min: [0, 0, 0], max: [0.0016, 0.0016, 0.003],
     velocity_jitter: 0.05, velocity_seed: 7}
contact: {stiffness: 10, restitution: 0.9, skin: 0.3}
time: {end: 0.01, max_dt_sph: 5.0e-5}
startup: {relax_steps: 0}
insitu: {enabled: false}
)",
                                   "settle_threads");
  auto run = [&](int threads) {
    omp_set_num_threads(threads);
    Simulation sim(sc);
    sim.relax();
    for (int k = 0; k < 200; ++k) sim.step();  // 10 ms: the lowest layers have landed
    return sim.spheres();
  };
  const int before = omp_get_max_threads();
  const DemParticles one = run(1), two = run(2);
  omp_set_num_threads(before);
  ASSERT_GT(one.n_owned, 2000u);  // above the threshold of a parallel pass, twice over
  std::size_t in_contact = 0;
  for (std::size_t i = 0; i < one.n_owned; ++i) {
    ASSERT_EQ(one.id[i], two.id[i]) << i;
    EXPECT_EQ(one.x[i], two.x[i]) << i;
    EXPECT_EQ(one.z[i], two.z[i]) << i;
    EXPECT_EQ(one.vz[i], two.vz[i]) << i;
    in_contact += one.overlap_max[i] > 0.0;
  }
  EXPECT_GT(in_contact, one.n_owned / 10);  // a bed under falling spheres: rows of unequal cost
}

}  // namespace
