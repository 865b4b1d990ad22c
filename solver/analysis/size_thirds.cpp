#include "analysis/size_thirds.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <numeric>
#include <stdexcept>

namespace sphdem {

double number_percentile(const std::vector<double>& sorted, double p) {
  if (sorted.empty()) return std::nan("");
  const double pos = p * static_cast<double>(sorted.size() - 1);
  const std::size_t k = static_cast<std::size_t>(std::floor(pos));
  if (k + 1 >= sorted.size()) return sorted.back();
  return sorted[k] + (pos - static_cast<double>(k)) * (sorted[k + 1] - sorted[k]);
}

SizeThirds size_thirds(const std::vector<double>& z, const std::vector<std::int64_t>& id,
                       const std::vector<double>& diameter, double d_lo, double d_hi, int n_bins) {
  if (n_bins < 1 || !(d_hi > d_lo))
    throw std::invalid_argument("size_thirds: need n_bins >= 1 and d_hi > d_lo");
  SizeThirds out;
  for (int b = 0; b <= n_bins; ++b) out.bin_edges.push_back(d_lo + (d_hi - d_lo) * b / n_bins);
  const std::size_t n = z.size();
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return z[a] != z[b] ? z[a] < z[b] : id[a] < id[b];
  });
  double sum = 0, sum2 = 0;
  for (std::size_t i = 0; i < n; ++i) {
    sum += diameter[i];
    sum2 += diameter[i] * diameter[i];
  }
  out.std_d = n > 1 ? std::sqrt(std::max(0.0, (sum2 - sum * sum / n) / (n - 1))) : 0.0;
  std::size_t begin = 0;
  for (int t = 0; t < 3; ++t) {
    const std::size_t size = n / 3 + (static_cast<std::size_t>(t) < n % 3 ? 1 : 0);
    SizeThird& th = out.third[t];
    th.count = size;
    th.bin_count.assign(n_bins, 0);
    std::vector<double> d;
    for (std::size_t k = begin; k < begin + size; ++k) {
      const std::size_t i = order[k];
      const double di = diameter[i];
      d.push_back(di);
      const double u = (di - d_lo) / (d_hi - d_lo) * n_bins;
      if (di >= d_lo && di <= d_hi) ++th.bin_count[std::min(static_cast<int>(u), n_bins - 1)];
    }
    if (size > 0) {
      th.z_min = z[order[begin]];
      th.z_max = z[order[begin + size - 1]];
      std::sort(d.begin(), d.end());
      th.mean_d = std::accumulate(d.begin(), d.end(), 0.0) / size;
      th.d10 = number_percentile(d, 0.1);
      th.d50 = number_percentile(d, 0.5);
      th.d90 = number_percentile(d, 0.9);
    }
    begin += size;
  }
  return out;
}

SizeThirds size_thirds(const DemParticles& s, double d_lo, double d_hi, int n_bins) {
  std::vector<double> d(s.n_owned);
  for (std::size_t i = 0; i < s.n_owned; ++i) d[i] = 2.0 * s.radius[i];
  return size_thirds({s.z.begin(), s.z.begin() + s.n_owned},
                     {s.id.begin(), s.id.begin() + s.n_owned}, d, d_lo, d_hi, n_bins);
}

void write_size_thirds_csv(const SizeThirds& t, const std::string& path) {
  std::ofstream out(path);
  if (!out) throw std::runtime_error("cannot write " + path);
  out << "third,count,z_min,z_max,mean_d,d10,d50,d90";
  for (std::size_t b = 0; b + 1 < t.bin_edges.size(); ++b)
    out << fmt::format(",n_[{:.6g};{:.6g})", t.bin_edges[b], t.bin_edges[b + 1]);
  out << '\n';
  const char* names[3] = {"bottom", "middle", "top"};
  for (int k = 0; k < 3; ++k) {
    const SizeThird& th = t.third[k];
    out << fmt::format("{},{},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g}", names[k], th.count,
                       th.z_min, th.z_max, th.mean_d, th.d10, th.d50, th.d90);
    for (std::size_t c : th.bin_count) out << ',' << c;
    out << '\n';
  }
}

}  // namespace sphdem
