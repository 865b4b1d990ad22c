#pragma once
// Per-thread accumulation arrays for passes over a half neighbour list: a pair (a, b)
// of owned particles is visited once and adds to both; each thread adds into its own
// copy, and the copies are summed afterwards (no atomics, deterministic for a fixed
// thread count). A pass that splits a row into a vectorised evaluation and a scalar
// scatter keeps the row's mirror contributions in the thread's entry buffer.
#include <omp.h>

#include <algorithm>
#include <cstddef>
#include <vector>

namespace sphdem {

class PairAccumulator {
 public:
  // `fields` values per particle for n particles, zeroed, one copy per thread.
  void reset(std::size_t n, int fields) {
    n_ = n;
    fields_ = fields;
    threads_ = omp_get_max_threads();
    // each thread zeroes its own copy: one thread zeroing them all took longer than the
    // pass itself at 8-16 threads (bench/RESULTS.md, session 28)
    const std::size_t copy = n * static_cast<std::size_t>(fields);
    data_.resize(static_cast<std::size_t>(threads_) * copy);
    double* data = data_.data();
#pragma omp parallel for schedule(static) num_threads(threads_)
    for (int t = 0; t < threads_; ++t) std::fill_n(data + t * copy, copy, 0.0);
    entries_.resize(threads_);
  }
  // The calling thread's buffer of at least `count` doubles (grows only on a longer row).
  double* entries(int thread, std::size_t count) {
    std::vector<double>& e = entries_[thread];
    if (e.size() < count) e.resize(count);
    return e.data();
  }
  // A buffer of at least `count` doubles shared by the threads, for the values per
  // particle that a pass stages before its pair loop (grows only when needed).
  double* staged(std::size_t count) {
    if (staged_.size() < count) staged_.resize(count);
    return staged_.data();
  }
  // The calling thread's row for particle i.
  double* row(int thread, std::size_t i) {
    return data_.data() + (thread * n_ + i) * fields_;
  }
  // Sums the threads' copies into the first and returns it (n rows of `fields` values);
  // called outside a parallel region.
  double* fold() {
    const long n = static_cast<long>(n_ * fields_);
    if (threads_ > 1) {
#pragma omp parallel for schedule(static)
      for (long i = 0; i < n; ++i)
        for (int t = 1; t < threads_; ++t) data_[i] += data_[t * n + i];
    }
    return data_.data();
  }
  // Sum over threads of field k of particle i.
  double sum(std::size_t i, int k) const {
    double s = 0.0;
    for (int t = 0; t < threads_; ++t) s += data_[(t * n_ + i) * fields_ + k];
    return s;
  }
  double max(std::size_t i, int k) const {
    double m = data_[i * fields_ + k];
    for (int t = 1; t < threads_; ++t) m = std::max(m, data_[(t * n_ + i) * fields_ + k]);
    return m;
  }

 private:
  std::size_t n_ = 0;
  int fields_ = 0, threads_ = 1;
  std::vector<double> data_;
  std::vector<std::vector<double>> entries_;  // per thread, kept between passes
  std::vector<double> staged_;
};

}  // namespace sphdem
