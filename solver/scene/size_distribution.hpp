#pragma once
// Law of the sphere diameters of one species (scene key species.N.size_distribution).
//
// Every law is a law of the NUMBER of spheres: each sphere's diameter is one draw.
// A list law may be given by volume fractions f_i; they become number fractions
//   n_i = (f_i / d_i^3) / sum_k (f_k / d_k^3).
// Continuous laws are truncated to [min, max] and sampled by inverting their CDF, so a
// draw never falls outside [min, max] and no draw is rejected.
// Draws use std::mt19937_64 (its output is fixed by the C++ standard) and our own
// bits-to-double conversion, so a seed gives the same diameters on every platform.
#include <cstddef>
#include <cstdint>
#include <random>
#include <vector>

namespace sphdem {

enum class SizeLaw { kSingle, kList, kUniform, kNormal, kLognormal };

struct SizeDistribution {
  SizeLaw law = SizeLaw::kSingle;
  std::vector<double> diameters;        // list: class diameters (m)
  std::vector<double> fractions;        // list: fractions as given (they sum to 1)
  bool by_volume = false;               // list: `fractions` are volume fractions (else number)
  double mean = 0.0, std = 0.0;         // normal: of d (m), before truncation
  double median = 0.0, sigma_ln = 0.0;  // lognormal: ln d ~ N(ln median, sigma_ln^2)
  double min = 0.0, max = 0.0;          // support: uniform bounds, truncation of normal and
                                        // lognormal, smallest and largest list class, or the
                                        // diameter of a single-size species
};

const char* size_law_name(SizeLaw law);  // "single", "list", "uniform", "normal", "lognormal"

// Number fractions n_i of a list law (converted from volume fractions if by_volume).
std::vector<double> number_fractions(const SizeDistribution& law);
// P(D <= d) of the number law.
double size_cdf(const SizeDistribution& law, double d);
// Inverse of size_cdf for u in [0, 1]; a list law returns the class holding u.
double size_quantile(const SizeDistribution& law, double u);
// Number moment E[D^k] (closed forms; truncated normal by the moment recursion).
double size_moment(const SizeDistribution& law, int k);
// Share of the untruncated normal or lognormal law that lies in [min, max] (1 otherwise).
double truncation_mass(const SizeDistribution& law);
// Sauter mean d32 = E[D^3] / E[D^2].
inline double sauter_mean(const SizeDistribution& law) {
  return size_moment(law, 3) / size_moment(law, 2);
}

// Standard normal CDF Phi and its inverse (Acklam's rational start, one Halley step:
// relative error near 1e-15).
double normal_cdf(double x);
double normal_quantile(double p);

// A uniform double in [0, 1) from the top 53 bits of one draw.
inline double uniform01(std::mt19937_64& rng) {
  return static_cast<double>(rng() >> 11) * 0x1.0p-53;
}

// Deals items among classes in proportion to `shares` (summing to 1): each call returns
// the class furthest behind its quota, share_i (k + 1) - count_i, lowest index on ties.
// After any k calls every count is within one of share_i k, so a composition is
// honoured exactly rather than up to sampling noise.
class QuotaDealer {
 public:
  explicit QuotaDealer(std::vector<double> shares);
  std::size_t next();

 private:
  std::vector<double> shares_;
  std::vector<std::uint64_t> count_;
  std::uint64_t dealt_ = 0;
};

// Draws diameters of one species: continuous laws by inverse CDF from `rng`; a list law
// through a QuotaDealer over its number fractions (exact composition, no randomness);
// a single-size species always gives its diameter.
class SizeSampler {
 public:
  explicit SizeSampler(const SizeDistribution& law);
  double next(std::mt19937_64& rng);

 private:
  SizeDistribution law_;
  QuotaDealer classes_;
};

}  // namespace sphdem
