#pragma once
// Compressed rows (offset + entries) built on all threads. Rows differ in length (a bed
// below a dilute suspension), so they are cut into blocks of kRowsPerBlock that the
// threads take in turn as they finish; the blocks are then concatenated in order, so the
// result is the same as one thread's, whatever thread built which block.
#include <omp.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace sphdem {

class CompressedRowBuilder {
 public:
  static constexpr std::size_t kRowsPerBlock = 256;

  // row(i, out) appends the entries of row i to out (a std::vector<std::uint32_t>).
  template <class Row>
  void build(std::size_t n, std::vector<std::uint32_t>& offset, std::vector<std::uint32_t>& entries,
             Row&& row) {
    const long nb = static_cast<long>((n + kRowsPerBlock - 1) / kRowsPerBlock);
    if (static_cast<long>(block_.size()) < nb) block_.resize(nb);
    start_.assign(nb + 1, 0);
    offset.assign(n + 1, 0);
#pragma omp parallel if (nb > 1)
    {
#pragma omp for schedule(dynamic, 1)
      for (long b = 0; b < nb; ++b) {
        auto& buf = block_[b];
        buf.clear();
        const std::size_t lo = b * kRowsPerBlock, hi = std::min(n, lo + kRowsPerBlock);
        for (std::size_t i = lo; i < hi; ++i) {
          row(i, buf);
          offset[i + 1] = static_cast<std::uint32_t>(buf.size());  // within the block for now
        }
        start_[b + 1] = buf.size();
      }
#pragma omp single
      {
        for (long b = 0; b < nb; ++b) start_[b + 1] += start_[b];
        entries.resize(start_[nb]);
      }
#pragma omp for schedule(static)
      for (long b = 0; b < nb; ++b) {
        const std::size_t lo = b * kRowsPerBlock, hi = std::min(n, lo + kRowsPerBlock);
        const auto shift = static_cast<std::uint32_t>(start_[b]);
        for (std::size_t i = lo; i < hi; ++i) offset[i + 1] += shift;
        std::copy(block_[b].begin(), block_[b].end(), entries.begin() + start_[b]);
      }
    }
  }

 private:
  std::vector<std::vector<std::uint32_t>> block_;  // kept between builds (no page faults)
  std::vector<std::size_t> start_;
};

}  // namespace sphdem
