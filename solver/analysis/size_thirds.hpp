#pragma once
// Particle size distribution of the bottom, middle and top thirds of the spheres
// (Zhao, Houlsby & Utili 2014, §3.3.1, Figs. 6-7): the spheres sorted by height and cut
// into three layers holding the same number of spheres (the first n mod 3 thirds from
// the bottom hold one more). Per third: count, number-mean diameter, the number
// percentiles d10, d50, d90 (the diameter below which 10, 50, 90 % of the spheres of the
// third lie; linear interpolation between order statistics), and the counts per size
// bin. Coarse grains at the base: mean_d of the bottom third above the top third's.
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "dem/dem_particles.hpp"

namespace sphdem {

struct SizeThird {
  std::size_t count = 0;
  double z_min = 0, z_max = 0;         // heights of the lowest and highest centre in the third (m)
  double mean_d = 0;                   // (m)
  double d10 = 0, d50 = 0, d90 = 0;    // (m)
  std::vector<std::size_t> bin_count;  // spheres per size bin
};

struct SizeThirds {
  std::vector<double> bin_edges;   // n_bins + 1 edges (m)
  std::array<SizeThird, 3> third;  // bottom, middle, top
  double std_d = 0;                // standard deviation of d over all the spheres (m)
};

// Number percentile p in [0, 1] of sorted values (linear between order statistics).
double number_percentile(const std::vector<double>& sorted, double p);

// Owned spheres only; bins: n_bins equal bins over [d_lo, d_hi] (a diameter equal to
// d_hi goes into the last bin; one outside the range is counted in neither).
SizeThirds size_thirds(const DemParticles& s, double d_lo, double d_hi, int n_bins);
// The same from the spheres' heights, ids and diameters (gathered from ranks).
SizeThirds size_thirds(const std::vector<double>& z, const std::vector<std::int64_t>& id,
                       const std::vector<double>& diameter, double d_lo, double d_hi, int n_bins);

// CSV: one row per third: third,count,z_min,z_max,mean_d,d10,d50,d90, then one column per
// bin, named by its edges "n_[lo,hi)" in metres.
void write_size_thirds_csv(const SizeThirds& t, const std::string& path);

}  // namespace sphdem
