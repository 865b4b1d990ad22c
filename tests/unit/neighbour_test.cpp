// Neighbour search across periodic faces (solver/domain/: box.hpp, periodic_halo.hpp,
// cell_list.hpp, neighbour_list.hpp). Reference: brute force over all owned points and
// all 9 periodic images in x, y (z is bounded), so no minimum-image assumption is made.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iomanip>
#include <random>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

#include "domain/box.hpp"
#include "domain/cell_list.hpp"
#include "domain/neighbour_list.hpp"
#include "domain/periodic_halo.hpp"

namespace {

using namespace sphdem;

// A neighbour: owned source index and the image shift in whole box lengths along x, y.
using Neighbour = std::tuple<std::uint32_t, int, int>;
using NeighbourSets = std::vector<std::vector<Neighbour>>;

struct Points {
  std::vector<double> x, y, z;
  std::size_t size() const { return x.size(); }
  void push(double a, double b, double c) {
    x.push_back(a);
    y.push_back(b);
    z.push_back(c);
  }
};

Box make_box() {
  Box b;
  b.lo = {-0.3, 0.1, 0.0};
  b.hi = {0.7, 0.9, 0.6};  // Lx = 1.0, Ly = 0.8, Lz = 0.6
  b.periodic = {true, true, false};
  return b;
}

// n random points in the box plus points on and near its faces, edges and corners.
Points make_points(const Box& box, std::size_t n, unsigned seed) {
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Points p;
  auto at = [&](double fx, double fy, double fz) {
    p.push(box.lo[0] + fx * box.length(0), box.lo[1] + fy * box.length(1),
           box.lo[2] + fz * box.length(2));
  };
  for (std::size_t i = 0; i < n; ++i) at(u(gen), u(gen), u(gen));
  const double e = 1e-9;
  for (double fx : {0.0, e, 1.0 - e})
    for (double fy : {0.0, e, 1.0 - e})
      for (double fz : {0.0, 0.5, 1.0}) at(fx, fy, fz);
  at(0.5, 0.0, 0.2);  // on a face
  at(0.0, 0.5, 0.2);
  return p;
}

// Brute force: every owned j and every image shift (sx, sy) in {-1,0,1}^2 with
// |p_i - (p_j + s)| < rc (self included), with the same arithmetic as the halo and cell list.
NeighbourSets brute_force(const Box& box, const Points& p, double rc) {
  const double Lx = box.length(0), Ly = box.length(1), rc2 = rc * rc;
  NeighbourSets out(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) {
    for (std::size_t j = 0; j < p.size(); ++j)
      for (int sx = -1; sx <= 1; ++sx)
        for (int sy = -1; sy <= 1; ++sy) {
          const double dx = p.x[i] - (p.x[j] + sx * Lx), dy = p.y[i] - (p.y[j] + sy * Ly),
                       dz = p.z[i] - p.z[j];
          if (dx * dx + dy * dy + dz * dz < rc2)
            out[i].emplace_back(static_cast<std::uint32_t>(j), sx, sy);
        }
    std::sort(out[i].begin(), out[i].end());
  }
  return out;
}

// The solver's pipeline: halo of width rc, cell list over owned + ghosts, neighbour list
// for the owned points; each neighbour mapped back to (owned source, image shift).
NeighbourSets via_solver(const Box& box, const Points& owned, double rc, int reach,
                         bool exclude_self) {
  const std::size_t n = owned.size();
  PeriodicHalo halo;
  halo.build(box, rc, owned.x.data(), owned.y.data(), owned.z.data(), n);
  const std::size_t total = n + halo.n_ghost();
  std::vector<double> x(owned.x), y(owned.y), z(owned.z);
  x.resize(total);
  y.resize(total);
  z.resize(total);
  halo.fill_positions(x.data(), y.data(), z.data());

  CellList cells;
  cells.build(x.data(), y.data(), z.data(), total, rc, reach);
  NeighbourList list;
  list.build(cells, x.data(), y.data(), z.data(), n, rc, exclude_self);
  EXPECT_EQ(list.size(), n);

  const double Lx = box.length(0), Ly = box.length(1);
  NeighbourSets out(n);
  for (std::size_t i = 0; i < n; ++i) {
    for (std::uint32_t k = list.begin(i); k < list.end(i); ++k) {
      const std::uint32_t j = list.neighbour[k];
      const std::uint32_t src = j < n ? j : halo.source()[j - n];
      EXPECT_LT(src, n);
      // ghost z is never shifted (z not periodic); x, y shifts are whole box lengths
      EXPECT_EQ(z[j], z[src]);
      const int sx = static_cast<int>(std::lround((x[j] - x[src]) / Lx));
      const int sy = static_cast<int>(std::lround((y[j] - y[src]) / Ly));
      EXPECT_NEAR(x[j] - x[src], sx * Lx, 1e-12);
      EXPECT_NEAR(y[j] - y[src], sy * Ly, 1e-12);
      out[i].emplace_back(src, sx, sy);
    }
    std::sort(out[i].begin(), out[i].end());
  }
  return out;
}

void expect_same(const NeighbourSets& got, const NeighbourSets& want, const Points& p,
                 bool nearest_only) {
  ASSERT_EQ(got.size(), want.size());
  std::size_t pairs = 0, across = 0, mismatched = 0;
  for (std::size_t i = 0; i < want.size(); ++i) {
    pairs += want[i].size();
    for (const auto& nb : want[i]) across += (std::get<1>(nb) != 0 || std::get<2>(nb) != 0);
    if (got[i] != want[i] && ++mismatched <= 5)
      ADD_FAILURE() << "point " << i << " at (" << p.x[i] << ", " << p.y[i] << ", " << p.z[i]
                    << "): " << got[i].size() << " neighbours from the list, " << want[i].size()
                    << " by brute force";
  }
  EXPECT_EQ(mismatched, 0u);
  // rc < L/2: at most one image of each source, i.e. the minimum image; above L/2
  // some sources must appear through two images (the brute force has them too)
  std::size_t repeated = 0;
  for (std::size_t i = 0; i < got.size(); ++i)
    for (std::size_t k = 1; k < got[i].size(); ++k)
      repeated += std::get<0>(got[i][k]) == std::get<0>(got[i][k - 1]);
  if (nearest_only)
    EXPECT_EQ(repeated, 0u);
  else
    EXPECT_GT(repeated, want.size());
  // the test is only meaningful if there are many pairs, some of them through periodic faces
  EXPECT_GT(pairs, 5 * want.size());
  EXPECT_GT(across, want.size() / 2);
}

struct Case {
  double rc;
  int reach;
};

class NeighbourListVsBruteForce : public ::testing::TestWithParam<Case> {};

TEST_P(NeighbourListVsBruteForce, SameSetsIncludingImages) {
  const Box box = make_box();
  const Points p = make_points(box, 1000, 12345u);
  const auto [rc, reach] = GetParam();
  const NeighbourSets with_self = brute_force(box, p, rc);
  for (bool exclude_self : {true, false}) {
    SCOPED_TRACE(testing::Message()
                 << "rc = " << rc << " reach = " << reach << " exclude_self = " << exclude_self);
    NeighbourSets want = with_self;
    if (exclude_self)
      for (std::size_t i = 0; i < p.size(); ++i)
        want[i].erase(std::remove(want[i].begin(), want[i].end(),
                                  Neighbour{static_cast<std::uint32_t>(i), 0, 0}),
                      want[i].end());
    const NeighbourSets got = via_solver(box, p, rc, reach, exclude_self);
    expect_same(got, want, p, 2.0 * rc < std::min(box.length(0), box.length(1)));
    // self appears exactly once (shift 0) without exclude_self, never with it
    for (std::size_t i = 0; i < p.size(); ++i) {
      const auto self =
          std::count(got[i].begin(), got[i].end(), Neighbour{static_cast<std::uint32_t>(i), 0, 0});
      EXPECT_EQ(self, exclude_self ? 0 : 1) << "point " << i;
    }
  }
}

// Ly = 0.8, so rc = 0.399 is just under half the narrowest periodic width; 0.6 is above
// half of both (every point within 0.6 of a pair of faces sees two images of some sources).
INSTANTIATE_TEST_SUITE_P(CutOffs, NeighbourListVsBruteForce,
                         ::testing::Values(Case{0.12, 1}, Case{0.12, 2}, Case{0.25, 1},
                                           Case{0.25, 2}, Case{0.25, 3}, Case{0.399, 1},
                                           Case{0.399, 2}, Case{0.6, 1}, Case{0.6, 2}),
                         [](const ::testing::TestParamInfo<Case>& info) {
                           // e.g. rc0p399_reach2 for rc = 0.399 box units
                           return "rc0p" + std::to_string(std::lround(info.param.rc * 1000)) +
                                  "_reach" + std::to_string(info.param.reach);
                         });

TEST(PeriodicHalo, RefusesWidthAboveTheBox) {
  const Box box = make_box();  // periodic Ly = 0.8 is the narrowest; z (0.6) is not periodic
  const Points p = make_points(box, 20, 7u);
  PeriodicHalo halo;
  EXPECT_NO_THROW(halo.build(box, 0.8, p.x.data(), p.y.data(), p.z.data(), p.size()));  // = Ly
  EXPECT_THROW(halo.build(box, 0.8001, p.x.data(), p.y.data(), p.z.data(), p.size()),
               std::runtime_error);
  EXPECT_THROW(halo.build(box, 1.2, p.x.data(), p.y.data(), p.z.data(), p.size()),
               std::runtime_error);
}

TEST(PeriodicHalo, GhostsCoverEveryImageWithinTheWidth) {
  // every image p + (sx Lx, sy Ly), (sx, sy) != 0, that lies within `width` of the box
  // (in x and y) must be a ghost, exactly once; no other ghosts.
  const Box box = make_box();
  const Points p = make_points(box, 200, 99u);
  const double width = 0.2;
  PeriodicHalo halo;
  halo.build(box, width, p.x.data(), p.y.data(), p.z.data(), p.size());
  std::vector<double> x(p.x), y(p.y), z(p.z);
  const std::size_t n = p.size(), total = n + halo.n_ghost();
  x.resize(total), y.resize(total), z.resize(total);
  halo.fill_positions(x.data(), y.data(), z.data());
  std::vector<Neighbour> got, want;
  for (std::size_t g = n; g < total; ++g) {
    const std::uint32_t s = halo.source()[g - n];
    got.emplace_back(s, static_cast<int>(std::lround((x[g] - x[s]) / box.length(0))),
                     static_cast<int>(std::lround((y[g] - y[s]) / box.length(1))));
  }
  auto inside = [&](int d, double v) { return v >= box.lo[d] - width && v < box.hi[d] + width; };
  for (std::uint32_t i = 0; i < n; ++i)
    for (int sx = -1; sx <= 1; ++sx)
      for (int sy = -1; sy <= 1; ++sy)
        if ((sx || sy) && inside(0, p.x[i] + sx * box.length(0)) &&
            inside(1, p.y[i] + sy * box.length(1)))
          want.emplace_back(i, sx, sy);
  std::sort(got.begin(), got.end());
  std::sort(want.begin(), want.end());
  EXPECT_EQ(got, want);
  // field copy: a ghost carries its source's value
  std::vector<double> f(total, -1.0);
  for (std::size_t i = 0; i < n; ++i) f[i] = 10.0 * i;
  halo.fill(f);
  for (std::size_t g = n; g < total; ++g) EXPECT_EQ(f[g], 10.0 * halo.source()[g - n]);
}

// Box::wrap must map into [lo, hi) (box.hpp). Checked against lo + (v - lo) mod L.
void expect_wraps_into_box(const Box& box, int d, double v) {
  const double L = box.length(d);
  const double w = box.wrap(d, v);
  EXPECT_GE(w, box.lo[d]) << std::setprecision(17) << "v = " << v << " -> " << w;
  EXPECT_LT(w, box.hi[d]) << std::setprecision(17) << "v = " << v << " -> " << w;
  double expected = box.lo[d] + std::fmod(std::fmod(v - box.lo[d], L) + L, L);
  if (expected >= box.hi[d]) expected -= L;
  // |v - lo| <= 8 L: a few roundings of numbers of size <= 8 L, so 1e-14 L; a value within
  // that of hi may legitimately land at lo instead
  if (std::abs(w - expected) > 1e-14 * L) {
    EXPECT_NEAR(std::abs(w - expected), L, 1e-14 * L) << v;
  }
}

// Points just beside a face, and whole multiples of L from it.
std::vector<double> wrap_probes(const Box& box, int d) {
  const double L = box.length(d);
  std::vector<double> v;
  for (double k : {-3.0, -1.0, 0.0, 1.0, 2.0}) {
    const double face = box.lo[d] + k * L;
    v.insert(v.end(), {face, std::nextafter(face, -1e9), std::nextafter(face, 1e9)});
  }
  for (double f : {0.01, 0.5, 0.99, 1.2, 2.95, -0.01, -1.75, -7.3}) v.push_back(box.lo[d] + f * L);
  return v;
}

TEST(Box, WrapOriginAtZero) {
  Box box;  // the solver's scenes: lo = 0, thesis column 4 x 4 x 6 mm
  box.hi = {4e-3, 4e-3, 6e-3};
  for (int d : {0, 1})
    for (double v : wrap_probes(box, d)) expect_wraps_into_box(box, d, v);
  EXPECT_EQ(box.wrap(0, 4e-3), 0.0);   // the upper face maps to the lower one
  EXPECT_EQ(box.wrap(2, -5.0), -5.0);  // non-periodic axis untouched
  EXPECT_EQ(box.wrap(2, 0.61), 0.61);
}

TEST(Box, WrapOffsetOrigin) {
  const Box box = make_box();  // x in [-0.3, 0.7), y in [0.1, 0.9)
  for (int d : {0, 1})
    for (double v : wrap_probes(box, d)) expect_wraps_into_box(box, d, v);
  EXPECT_NEAR(box.wrap(1, 0.95), 0.15, 1e-15);
  EXPECT_NEAR(box.wrap(1, 0.05), 0.85, 1e-15);
  EXPECT_EQ(box.wrap(2, -5.0), -5.0);
}

TEST(CellList, RejectsBadParameters) {
  const double x[1] = {0}, y[1] = {0}, z[1] = {0};
  CellList cells;
  EXPECT_THROW(cells.build(x, y, z, 1, 0.0, 1), std::invalid_argument);
  EXPECT_THROW(cells.build(x, y, z, 1, 0.1, 0), std::invalid_argument);
}

}  // namespace

// Lists at each point's own reach (the solver's, where h varies: a bed under clear liquid):
// full rows within rc_i, and half rows within max(R_i, R_j), against brute force.
TEST(NeighbourList, OwnReachesMatchBruteForce) {
  std::mt19937 gen(99u);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const std::size_t n = 800;
  Points p;
  std::vector<double> reach(n);
  const double rc_max = 0.12;
  for (std::size_t i = 0; i < n; ++i) {
    p.push(u(gen), u(gen), 0.6 * u(gen));
    reach[i] = rc_max * (0.5 + 0.5 * u(gen));
  }
  CellList cells;
  cells.build(p.x.data(), p.y.data(), p.z.data(), n, rc_max, 2);
  NeighbourList full, half;
  full.build_within(cells, p.x.data(), p.y.data(), p.z.data(), n, reach.data());
  half.build_half_within(cells, p.x.data(), p.y.data(), p.z.data(), n, reach.data());
  std::size_t pairs = 0, from_other = 0;
  for (std::size_t i = 0; i < n; ++i) {
    std::vector<std::uint32_t> want_full, want_half, got_full, got_half;
    for (std::uint32_t j = 0; j < n; ++j) {
      const double dx = p.x[i] - p.x[j], dy = p.y[i] - p.y[j], dz = p.z[i] - p.z[j];
      const double r2 = dx * dx + dy * dy + dz * dz;
      if (r2 < reach[i] * reach[i]) want_full.push_back(j);
      const double rc = std::max(reach[i], reach[j]);
      if (j > i && r2 < rc * rc) {
        want_half.push_back(j);
        from_other += r2 >= reach[i] * reach[i];  // listed only for j's wider reach
      }
    }
    got_full.assign(full.neighbour.begin() + full.begin(i), full.neighbour.begin() + full.end(i));
    got_half.assign(half.neighbour.begin() + half.begin(i), half.neighbour.begin() + half.end(i));
    std::sort(got_full.begin(), got_full.end());
    std::sort(got_half.begin(), got_half.end());
    EXPECT_EQ(got_full, want_full) << "point " << i;
    EXPECT_EQ(got_half, want_half) << "point " << i;
    pairs += want_half.size();
  }
  EXPECT_GT(pairs, 2 * n);        // a meaningful test: many pairs,
  EXPECT_GT(from_other, n / 10);  // some of them through the other point's reach only
}
