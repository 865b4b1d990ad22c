// Size laws of species.N.size_distribution (size_distribution.hpp), read through the
// scene loader: the draws of every law against the law itself, and the closed-form
// moments and CDF against references computed here independently (Simpson on the
// density written out below, std::erf for the CDF).
//
// Sampling bounds (N = 200000 draws, fixed seed, so the test is deterministic; the
// bounds say how unlikely a failure would be for a correct sampler):
// - mean:     |mean_N - mu| <= 5 sigma / sqrt(N)                   (5 standard errors)
// - variance: |s_N^2 - sigma^2| <= 5 sqrt((mu_4 - sigma^4) / N)    (5 standard errors)
// - quantiles / whole CDF: sup_d |F_N(d) - F(d)| <= sqrt(ln(2/a) / (2N)) with a = 1e-6,
//   the Dvoretzky-Kiefer-Wolfowitz bound (Massart's constant): P(exceeded) <= 1e-6.
#include "scene/size_distribution.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include "scene/scene.hpp"

using namespace sphdem;

namespace {

constexpr std::size_t kDraws = 200000;

SpeciesSpec species_with(const std::string& law_yaml) {
  const Scene sc = load_scene_text(
      "species:\n  - {name: s, density: 2500, size_distribution: " + law_yaml + "}\n", "psd.yaml");
  return sc.species.at(0);
}

std::vector<double> draw(const SizeDistribution& L, std::size_t n, std::uint64_t seed = 7) {
  std::mt19937_64 rng(seed);
  SizeSampler s(L);
  std::vector<double> d(n);
  for (auto& x : d) x = s.next(rng);
  return d;
}

// Reference law written out here: density (unnormalised) and CDF on [lo, hi].
struct Reference {
  std::function<double(double)> pdf;
  std::function<double(double)> cdf;
  double lo, hi;
};

double phi_cdf(double x) {
  return 0.5 * (1.0 + std::erf(x / std::sqrt(2.0)));
}

Reference normal_ref(double mu, double s, double lo, double hi) {
  const double Z = phi_cdf((hi - mu) / s) - phi_cdf((lo - mu) / s);
  return {[=](double d) { return std::exp(-0.5 * std::pow((d - mu) / s, 2)); },
          [=](double d) { return (phi_cdf((d - mu) / s) - phi_cdf((lo - mu) / s)) / Z; }, lo, hi};
}
Reference lognormal_ref(double median, double s, double lo, double hi) {
  const double m = std::log(median);
  const double Z = phi_cdf((std::log(hi) - m) / s) - phi_cdf((std::log(lo) - m) / s);
  return {[=](double d) { return std::exp(-0.5 * std::pow((std::log(d) - m) / s, 2)) / d; },
          [=](double d) {
            return (phi_cdf((std::log(d) - m) / s) - phi_cdf((std::log(lo) - m) / s)) / Z;
          },
          lo, hi};
}
Reference uniform_ref(double lo, double hi) {
  return {[](double) { return 1.0; }, [=](double d) { return (d - lo) / (hi - lo); }, lo, hi};
}

// E[D^k] of the reference by composite Simpson (20000 intervals).
double ref_moment(const Reference& R, int k) {
  const int n = 20000;
  const double h = (R.hi - R.lo) / n;
  double num = 0, den = 0;
  for (int i = 0; i <= n; ++i) {
    const double d = R.lo + i * h, w = (i == 0 || i == n) ? 1 : (i % 2 ? 4 : 2);
    num += w * R.pdf(d) * std::pow(d, k);
    den += w * R.pdf(d);
  }
  return num / den;
}

// Checks draws against the reference with the bounds of the header comment.
void expect_sample_matches(const SizeDistribution& L, const Reference& R) {
  const std::vector<double> d = draw(L, kDraws);
  const double N = static_cast<double>(d.size());
  const double mu = ref_moment(R, 1), m2 = ref_moment(R, 2), m3 = ref_moment(R, 3),
               m4 = ref_moment(R, 4);
  const double var = m2 - mu * mu;
  const double mu4 = m4 - 4 * mu * m3 + 6 * mu * mu * m2 - 3 * mu * mu * mu * mu;  // central
  double mean = 0;
  for (double x : d) mean += x;
  mean /= N;
  double s2 = 0;
  for (double x : d) s2 += (x - mean) * (x - mean);
  s2 /= N - 1;
  EXPECT_NEAR(mean, mu, 5 * std::sqrt(var / N)) << "sample mean";
  EXPECT_NEAR(s2, var, 5 * std::sqrt((mu4 - var * var) / N)) << "sample variance";
  // All draws in the support.
  EXPECT_GE(*std::min_element(d.begin(), d.end()), L.min);
  EXPECT_LE(*std::max_element(d.begin(), d.end()), L.max);
  // Kolmogorov-Smirnov distance against the reference CDF, DKW bound.
  std::vector<double> s = d;
  std::sort(s.begin(), s.end());
  double D = 0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const double F = R.cdf(s[i]);
    D = std::max({D, std::abs(F - i / N), std::abs((i + 1) / N - F)});
  }
  const double dkw = std::sqrt(std::log(2.0 / 1e-6) / (2.0 * N));
  EXPECT_LT(D, dkw) << "KS distance";
  // Named quantiles: F(empirical quantile) within the same bound of p.
  for (double p : {0.05, 0.25, 0.5, 0.75, 0.95}) {
    const double q = s[static_cast<std::size_t>(p * N)];
    EXPECT_NEAR(R.cdf(q), p, dkw) << "quantile " << p;
  }
  // The library's closed forms agree with the independent reference.
  for (int k = 1; k <= 4; ++k)
    EXPECT_NEAR(size_moment(L, k), ref_moment(R, k), 1e-9 * ref_moment(R, k)) << "moment " << k;
  for (double u : {0.01, 0.3, 0.5, 0.7, 0.99}) {
    const double x = R.lo + u * (R.hi - R.lo);
    EXPECT_NEAR(size_cdf(L, x), R.cdf(x), 1e-12) << "cdf at " << x;
    EXPECT_NEAR(size_quantile(L, R.cdf(x)), x, 1e-9 * x) << "quantile of cdf at " << x;
  }
}

}  // namespace

TEST(SizeDistribution, NormalQuantileInvertsTheCdf) {
  for (double p :
       {1e-300, 1e-12, 1e-6, 0.01, 0.02425, 0.2, 0.5, 0.8, 0.97575, 0.99, 1 - 1e-6, 1 - 1e-12}) {
    const double x = normal_quantile(p);
    EXPECT_NEAR(normal_cdf(x), p, 1e-14 * std::max(p, 1e-3)) << p;
  }
  EXPECT_EQ(normal_quantile(0.5), 0.0);
}

TEST(SizeDistribution, UniformLaw) {
  const SpeciesSpec s = species_with("{law: uniform, min: 8.0e-5, max: 1.2e-4}");
  EXPECT_FALSE(s.monodisperse());
  EXPECT_EQ(s.d_min(), 8e-5);
  EXPECT_EQ(s.d_max(), 1.2e-4);
  expect_sample_matches(s.size, uniform_ref(8e-5, 1.2e-4));
}

TEST(SizeDistribution, TruncatedNormalLaw) {
  // Truncated asymmetrically: 2.67 std below the mean, 3.33 above.
  const SpeciesSpec s =
      species_with("{law: normal, mean: 1.0e-4, std: 1.5e-5, min: 6.0e-5, max: 1.5e-4}");
  expect_sample_matches(s.size, normal_ref(1e-4, 1.5e-5, 6e-5, 1.5e-4));
}

TEST(SizeDistribution, NormalTruncatedFarInATail) {
  // [mean + 2 std, mean + 4 std] keeps 2.3 % of the law: sampled through the mirrored tail.
  const SpeciesSpec s =
      species_with("{law: normal, mean: 1.0e-4, std: 1.0e-5, min: 1.2e-4, max: 1.4e-4}");
  expect_sample_matches(s.size, normal_ref(1e-4, 1e-5, 1.2e-4, 1.4e-4));
}

TEST(SizeDistribution, TruncatedLognormalLaw) {
  const SpeciesSpec s =
      species_with("{law: lognormal, median: 1.0e-4, sigma_ln: 0.3, min: 5.0e-5, max: 2.5e-4}");
  expect_sample_matches(s.size, lognormal_ref(1e-4, 0.3, 5e-5, 2.5e-4));
  // d32 = E[d^3] / E[d^2]: above the median for a right-skewed law.
  EXPECT_GT(s.diameter, 1e-4);
  EXPECT_DOUBLE_EQ(s.diameter, size_moment(s.size, 3) / size_moment(s.size, 2));
}

TEST(SizeDistribution, ListLawByNumberIsDealtExactly) {
  const SpeciesSpec s = species_with(
      "{law: list, diameters: [1.2e-4, 8.0e-5, 1.0e-4], fractions: [0.3, 0.2, 0.5], "
      "basis: number}");
  EXPECT_EQ(s.d_min(), 8e-5);
  EXPECT_EQ(s.d_max(), 1.2e-4);
  const std::vector<double> n = number_fractions(s.size);
  EXPECT_DOUBLE_EQ(n[0], 0.3);
  const std::vector<double> d = draw(s.size, 10007);
  // After every prefix of k draws, each class count is within one of n_i k.
  std::vector<double> count(3, 0);
  for (std::size_t k = 0; k < d.size(); ++k) {
    const auto i = std::find(s.size.diameters.begin(), s.size.diameters.end(), d[k]) -
                   s.size.diameters.begin();
    ASSERT_LT(i, 3);
    count[i] += 1;
    for (int c = 0; c < 3; ++c)
      ASSERT_LE(std::abs(count[c] - n[c] * (k + 1)), 1.0) << "after " << k + 1;
  }
  EXPECT_NEAR(size_moment(s.size, 1), 0.3 * 1.2e-4 + 0.2 * 8e-5 + 0.5 * 1e-4, 1e-18);
  EXPECT_EQ(size_quantile(s.size, 0.1), 8e-5);
  EXPECT_EQ(size_quantile(s.size, 0.5), 1e-4);
  EXPECT_EQ(size_quantile(s.size, 0.71), 1.2e-4);
  EXPECT_DOUBLE_EQ(size_cdf(s.size, 1e-4), 0.7);
}

TEST(SizeDistribution, ListLawByVolume) {
  // Half the solid volume in each size: number fractions n_i ~ f_i / d_i^3.
  const SpeciesSpec s = species_with(
      "{law: list, diameters: [1.0e-4, 2.0e-4], fractions: [0.5, 0.5], basis: volume}");
  const std::vector<double> n = number_fractions(s.size);
  EXPECT_DOUBLE_EQ(n[0], 8.0 / 9.0);
  EXPECT_DOUBLE_EQ(n[1], 1.0 / 9.0);
  const std::vector<double> d = draw(s.size, 9000);
  double v_small = 0, v_all = 0;
  for (double x : d) {
    v_all += x * x * x;
    if (x == 1e-4) v_small += x * x * x;
  }
  EXPECT_NEAR(v_small / v_all, 0.5, 1e-12);  // 8000 small, 1000 big: exact
}

TEST(SizeDistribution, SingleSizeSpecies) {
  const Scene sc =
      load_scene_text("species: [{name: s, diameter: 1.0e-4, density: 2500}]\n", "psd.yaml");
  const SpeciesSpec& s = sc.species[0];
  EXPECT_TRUE(s.monodisperse());
  EXPECT_EQ(s.d_min(), 1e-4);
  EXPECT_EQ(s.d_max(), 1e-4);
  const std::vector<double> d = draw(s.size, 10);
  for (double x : d) EXPECT_EQ(x, 1e-4);
}

TEST(SizeDistribution, SameSeedSameDiameters) {
  const SpeciesSpec s =
      species_with("{law: lognormal, median: 1.0e-4, sigma_ln: 0.3, min: 5.0e-5, max: 2.5e-4}");
  EXPECT_EQ(draw(s.size, 1000, 3), draw(s.size, 1000, 3));
  EXPECT_NE(draw(s.size, 1000, 3), draw(s.size, 1000, 4));
}
