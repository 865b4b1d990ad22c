#include "scene/size_distribution.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace sphdem {

namespace {

constexpr double kSqrt2 = 1.41421356237309504880;
constexpr double kSqrt2Pi = 2.50662827463100050242;

double normal_pdf(double x) {
  return std::exp(-0.5 * x * x) / kSqrt2Pi;
}

// P(a <= Z <= b) for a standard normal Z, from the tail on the side of [a, b] so that
// an interval far in a tail keeps its digits.
double normal_between(double a, double b) {
  if (a >= 0) return 0.5 * (std::erfc(a / kSqrt2) - std::erfc(b / kSqrt2));
  if (b <= 0) return 0.5 * (std::erfc(-b / kSqrt2) - std::erfc(-a / kSqrt2));
  return 1.0 - 0.5 * std::erfc(b / kSqrt2) - 0.5 * std::erfc(-a / kSqrt2);
}

// Quantile u of a standard normal truncated to [a, b]. An interval above the mean is
// mirrored below it, where Phi keeps its relative precision.
double truncated_normal_quantile(double a, double b, double u) {
  if (a > 0) return -truncated_normal_quantile(-b, -a, 1.0 - u);
  const double x = normal_quantile(normal_cdf(a) + u * normal_between(a, b));
  return std::clamp(x, a, b);
}

// Standardised bounds of the truncated normal (of d) or lognormal (of ln d).
struct Standardised {
  double a, b, mu, sigma;
};
Standardised standardised(const SizeDistribution& L) {
  if (L.law == SizeLaw::kNormal)
    return {(L.min - L.mean) / L.std, (L.max - L.mean) / L.std, L.mean, L.std};
  const double mu = std::log(L.median);
  return {(std::log(L.min) - mu) / L.sigma_ln, (std::log(L.max) - mu) / L.sigma_ln, mu, L.sigma_ln};
}

std::vector<std::size_t> by_diameter(const SizeDistribution& L) {
  std::vector<std::size_t> order(L.diameters.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t i, std::size_t j) { return L.diameters[i] < L.diameters[j]; });
  return order;
}

}  // namespace

const char* size_law_name(SizeLaw law) {
  switch (law) {
    case SizeLaw::kSingle:
      return "single";
    case SizeLaw::kList:
      return "list";
    case SizeLaw::kUniform:
      return "uniform";
    case SizeLaw::kNormal:
      return "normal";
    case SizeLaw::kLognormal:
      return "lognormal";
  }
  return "?";
}

double normal_cdf(double x) {
  return 0.5 * std::erfc(-x / kSqrt2);
}

double normal_quantile(double p) {
  if (p <= 0) return -std::numeric_limits<double>::infinity();
  if (p >= 1) return std::numeric_limits<double>::infinity();
  // P. J. Acklam's rational approximation (relative error 1.15e-9) ...
  static const double a[] = {-3.969683028665376e+01, 2.209460984245205e+02,  -2.759285104469687e+02,
                             1.383577518672690e+02,  -3.066479806614716e+01, 2.506628277459239e+00};
  static const double b[] = {-5.447609879822406e+01, 1.615858368580409e+02, -1.556989798598866e+02,
                             6.680131188771972e+01, -1.328068155288572e+01};
  static const double c[] = {-7.784894002430293e-03, -3.223964580411365e-01, -2.400758277161838e+00,
                             -2.549732539343734e+00, 4.374664141464968e+00,  2.938163982698783e+00};
  static const double d[] = {7.784695709041462e-03, 3.224671290700398e-01, 2.445134137142996e+00,
                             3.754408661907416e+00};
  constexpr double p_low = 0.02425;
  double x;
  if (p < p_low) {
    const double q = std::sqrt(-2.0 * std::log(p));
    x = (((((c[0] * q + c[1]) * q + c[2]) * q + c[3]) * q + c[4]) * q + c[5]) /
        ((((d[0] * q + d[1]) * q + d[2]) * q + d[3]) * q + 1.0);
  } else if (p <= 1.0 - p_low) {
    const double q = p - 0.5, r = q * q;
    x = (((((a[0] * r + a[1]) * r + a[2]) * r + a[3]) * r + a[4]) * r + a[5]) * q /
        (((((b[0] * r + b[1]) * r + b[2]) * r + b[3]) * r + b[4]) * r + 1.0);
  } else {
    const double q = std::sqrt(-2.0 * std::log1p(-p));
    x = -(((((c[0] * q + c[1]) * q + c[2]) * q + c[3]) * q + c[4]) * q + c[5]) /
        ((((d[0] * q + d[1]) * q + d[2]) * q + d[3]) * q + 1.0);
  }
  // ... and one Halley step on Phi(x) - p to full double precision.
  const double e = normal_cdf(x) - p;
  const double u = e * kSqrt2Pi * std::exp(0.5 * x * x);
  return x - u / (1.0 + 0.5 * x * u);
}

std::vector<double> number_fractions(const SizeDistribution& L) {
  std::vector<double> n = L.fractions;
  if (L.by_volume)
    for (std::size_t i = 0; i < n.size(); ++i)
      n[i] /= L.diameters[i] * L.diameters[i] * L.diameters[i];
  const double sum = std::accumulate(n.begin(), n.end(), 0.0);
  for (double& v : n) v /= sum;
  return n;
}

double truncation_mass(const SizeDistribution& L) {
  if (L.law != SizeLaw::kNormal && L.law != SizeLaw::kLognormal) return 1.0;
  const Standardised s = standardised(L);
  return normal_between(s.a, s.b);
}

double size_cdf(const SizeDistribution& L, double d) {
  if (d < L.min) return 0.0;
  if (d >= L.max) return 1.0;
  switch (L.law) {
    case SizeLaw::kSingle:
      return 1.0;
    case SizeLaw::kUniform:
      return (d - L.min) / (L.max - L.min);
    case SizeLaw::kList: {
      const std::vector<double> n = number_fractions(L);
      double F = 0.0;
      for (std::size_t i = 0; i < n.size(); ++i)
        if (L.diameters[i] <= d) F += n[i];
      return std::min(F, 1.0);
    }
    case SizeLaw::kNormal:
    case SizeLaw::kLognormal: {
      const Standardised s = standardised(L);
      const double z = ((L.law == SizeLaw::kNormal ? d : std::log(d)) - s.mu) / s.sigma;
      return normal_between(s.a, std::clamp(z, s.a, s.b)) / normal_between(s.a, s.b);
    }
  }
  return 0.0;
}

double size_quantile(const SizeDistribution& L, double u) {
  switch (L.law) {
    case SizeLaw::kSingle:
      return L.min;
    case SizeLaw::kUniform:
      return std::clamp(L.min + u * (L.max - L.min), L.min, L.max);
    case SizeLaw::kList: {
      const std::vector<double> n = number_fractions(L);
      double F = 0.0;
      const auto order = by_diameter(L);
      for (std::size_t i : order) {
        F += n[i];
        if (u < F) return L.diameters[i];
      }
      return L.diameters[order.back()];
    }
    case SizeLaw::kNormal:
    case SizeLaw::kLognormal: {
      const Standardised s = standardised(L);
      const double x = s.mu + s.sigma * truncated_normal_quantile(s.a, s.b, u);
      return std::clamp(L.law == SizeLaw::kNormal ? x : std::exp(x), L.min, L.max);
    }
  }
  return L.min;
}

double size_moment(const SizeDistribution& L, int k) {
  switch (L.law) {
    case SizeLaw::kSingle:
      return std::pow(L.min, k);
    case SizeLaw::kUniform:
      return (std::pow(L.max, k + 1) - std::pow(L.min, k + 1)) / ((k + 1) * (L.max - L.min));
    case SizeLaw::kList: {
      const std::vector<double> n = number_fractions(L);
      double m = 0.0;
      for (std::size_t i = 0; i < n.size(); ++i) m += n[i] * std::pow(L.diameters[i], k);
      return m;
    }
    case SizeLaw::kNormal: {
      // Moments of the standard normal truncated to [a, b]:
      // M_0 = 1, M_j = (j-1) M_{j-2} + (a^{j-1} phi(a) - b^{j-1} phi(b)) / Z, with M_{-1} = 0;
      // then E[d^k] = sum_j C(k, j) mean^{k-j} std^j M_j.
      const Standardised s = standardised(L);
      const double Z = normal_between(s.a, s.b);
      std::vector<double> M(k + 1, 0.0);
      M[0] = 1.0;
      for (int j = 1; j <= k; ++j)
        M[j] =
            (j >= 2 ? (j - 1) * M[j - 2] : 0.0) +
            (std::pow(s.a, j - 1) * normal_pdf(s.a) - std::pow(s.b, j - 1) * normal_pdf(s.b)) / Z;
      double m = 0.0, binom = 1.0;
      for (int j = 0; j <= k; ++j) {
        m += binom * std::pow(L.mean, k - j) * std::pow(L.std, j) * M[j];
        binom = binom * (k - j) / (j + 1);
      }
      return m;
    }
    case SizeLaw::kLognormal: {
      // E[d^k] = median^k exp(k^2 sigma^2 / 2) P(a - k sigma <= Z <= b - k sigma) / P(a <= Z <= b).
      const Standardised s = standardised(L);
      const double ks = k * s.sigma;
      return std::pow(L.median, k) * std::exp(0.5 * ks * ks) * normal_between(s.a - ks, s.b - ks) /
             normal_between(s.a, s.b);
    }
  }
  return 0.0;
}

QuotaDealer::QuotaDealer(std::vector<double> shares)
    : shares_(std::move(shares)), count_(shares_.size(), 0) {}

std::size_t QuotaDealer::next() {
  std::size_t best = 0;
  double behind = -std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < shares_.size(); ++i) {
    const double deficit =
        shares_[i] * static_cast<double>(dealt_ + 1) - static_cast<double>(count_[i]);
    if (deficit > behind) {
      behind = deficit;
      best = i;
    }
  }
  ++count_[best];
  ++dealt_;
  return best;
}

SizeSampler::SizeSampler(const SizeDistribution& law)
    : law_(law),
      classes_(law.law == SizeLaw::kList ? number_fractions(law) : std::vector<double>{1.0}) {}

double SizeSampler::next(std::mt19937_64& rng) {
  switch (law_.law) {
    case SizeLaw::kSingle:
      return law_.min;
    case SizeLaw::kList:
      return law_.diameters[classes_.next()];
    default:
      return size_quantile(law_, uniform01(rng));
  }
}

}  // namespace sphdem
