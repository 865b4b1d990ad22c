#include "analysis/bulk_density.hpp"

#include <fmt/format.h>

#include <fstream>
#include <stdexcept>

namespace sphdem {

BulkDensityProfile bulk_density_profile(const std::vector<double>& voidage, const GridSpec& g,
                                        double rho_f, double rho_s, double z_top) {
  const std::size_t nx = g.extent[1] - g.extent[0] + 1, ny = g.extent[3] - g.extent[2] + 1;
  if (voidage.size() != g.count())
    throw std::invalid_argument("bulk_density_profile: voidage does not match the grid");
  BulkDensityProfile p;
  std::size_t layer = 0;
  for (int k = g.extent[4]; k <= g.extent[5]; ++k, ++layer) {
    const double z = g.origin[2] + k * g.spacing[2];
    if (z < 0.0 || z > z_top) continue;
    double sum = 0;
    for (std::size_t n = layer * nx * ny; n < (layer + 1) * nx * ny; ++n) sum += voidage[n];
    const double eps = sum / static_cast<double>(nx * ny);
    p.z.push_back(z);
    p.voidage.push_back(eps);
    p.bulk_density.push_back(eps * rho_f + (1.0 - eps) * rho_s);  // eq. 14
  }
  return p;
}

void write_bulk_density_csv(const BulkDensityProfile& p, const std::string& path) {
  std::ofstream out(path);
  if (!out) throw std::runtime_error("cannot write " + path);
  out << "z,voidage,bulk_density\n";
  for (std::size_t k = 0; k < p.z.size(); ++k)
    out << fmt::format("{:.9g},{:.9g},{:.9g}\n", p.z[k], p.voidage[k], p.bulk_density[k]);
}

}  // namespace sphdem
