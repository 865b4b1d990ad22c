#include "domain/neighbour_list.hpp"

#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>
#endif

#include <algorithm>
#include <cmath>

#include "sph/pair_isa.hpp"

namespace sphdem {

namespace {

// Appends the binned points within rc of p to out, in slot order: a row of a full list
// (no self, no half), whose candidates are the cells' contiguous runs.
void append_within(const CellList& cells, double px, double py, double pz, double rc2,
                   std::vector<std::uint32_t>& out) {
  cells.for_each_neighbour(
      px, py, pz, rc2, [&](std::uint32_t j, double, double, double, double) { out.push_back(j); });
}

#if defined(__x86_64__) && defined(__GNUC__)
// The same, eight slots at a time: the distances in lanes, the indices within the cut-off
// packed and stored under a mask (AVX-512 compress), in the same order.
SPHDEM_TARGET_AVX512 void append_within_avx512(const CellList& cells, double px, double py,
                                               double pz, double rc2,
                                               std::vector<std::uint32_t>& out) {
  const double* xs = cells.xs();
  const double* ys = cells.ys();
  const double* zs = cells.zs();
  const std::uint32_t* index = cells.index();
  const __m512d vx = _mm512_set1_pd(px), vy = _mm512_set1_pd(py), vz = _mm512_set1_pd(pz),
                vrc2 = _mm512_set1_pd(rc2);
  std::uint32_t run[CellList::kMaxRuns][2];
  const int runs = cells.runs(px, py, pz, run);
  for (int r = 0; r < runs; ++r) {
    const std::uint32_t b = run[r][0], e = run[r][1];
    std::size_t n = out.size();
    out.resize(n + (e - b));  // room for every candidate; cut back below
    std::uint32_t* dst = out.data();
    for (std::uint32_t k = b; k < e; k += 8) {
      const __mmask8 live = e - k >= 8 ? 0xff : static_cast<__mmask8>((1u << (e - k)) - 1u);
      const __m512d dx = _mm512_sub_pd(vx, _mm512_maskz_loadu_pd(live, xs + k));
      const __m512d dy = _mm512_sub_pd(vy, _mm512_maskz_loadu_pd(live, ys + k));
      const __m512d dz = _mm512_sub_pd(vz, _mm512_maskz_loadu_pd(live, zs + k));
      const __m512d r2 = _mm512_add_pd(_mm512_add_pd(_mm512_mul_pd(dx, dx), _mm512_mul_pd(dy, dy)),
                                       _mm512_mul_pd(dz, dz));
      const __mmask8 inside = _mm512_mask_cmp_pd_mask(live, r2, vrc2, _CMP_LT_OQ);
      _mm256_mask_compressstoreu_epi32(dst + n, inside, _mm256_maskz_loadu_epi32(live, index + k));
      n += __builtin_popcount(inside);
    }
    out.resize(n);
  }
}
#endif

}  // namespace

void NeighbourList::build(const CellList& cells, const double* x, const double* y, const double* z,
                          std::size_t n_query, double rc, bool exclude_self, bool half) {
  const double rc2 = rc * rc;
  if (!exclude_self && !half) {  // every point within rc: the cells' runs in lanes
#if defined(__x86_64__) && defined(__GNUC__)
    if (best_pair_isa() == PairIsa::kAvx512) {
      rows_.build(n_query, offset, neighbour, [&](std::size_t i, std::vector<std::uint32_t>& out) {
        append_within_avx512(cells, x[i], y[i], z[i], rc2, out);
      });
      return;
    }
#endif
    rows_.build(n_query, offset, neighbour, [&](std::size_t i, std::vector<std::uint32_t>& out) {
      append_within(cells, x[i], y[i], z[i], rc2, out);
    });
    return;
  }
  rows_.build(n_query, offset, neighbour, [&](std::size_t i, std::vector<std::uint32_t>& out) {
    cells.for_each_neighbour(x[i], y[i], z[i], rc2,
                             [&](std::uint32_t j, double, double, double, double) {
                               if (half ? (j > i || j >= n_query) : !(exclude_self && j == i))
                                 out.push_back(j);
                             });
  });
}

void NeighbourList::build_within(const CellList& cells, const double* x, const double* y,
                                 const double* z, std::size_t n_query, const double* rc) {
#if defined(__x86_64__) && defined(__GNUC__)
  if (best_pair_isa() == PairIsa::kAvx512) {
    rows_.build(n_query, offset, neighbour, [&](std::size_t i, std::vector<std::uint32_t>& out) {
      append_within_avx512(cells, x[i], y[i], z[i], rc[i] * rc[i], out);
    });
    return;
  }
#endif
  rows_.build(n_query, offset, neighbour, [&](std::size_t i, std::vector<std::uint32_t>& out) {
    append_within(cells, x[i], y[i], z[i], rc[i] * rc[i], out);
  });
}

void NeighbourList::build_half_within(const CellList& cells, const double* x, const double* y,
                                      const double* z, std::size_t n_query, const double* reach) {
  rows_.build(n_query, offset, neighbour, [&](std::size_t i, std::vector<std::uint32_t>& out) {
    const double ri = reach[i];
    cells.for_each_neighbour(x[i], y[i], z[i], HUGE_VAL,  // the pair's cut-off below
                             [&](std::uint32_t j, double, double, double, double r2) {
                               const double rc = std::max(ri, reach[j]);
                               if ((j > i || j >= n_query) && r2 < rc * rc) out.push_back(j);
                             });
  });
}

}  // namespace sphdem
