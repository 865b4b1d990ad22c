#pragma once
// Bulk density profile of the mixture (Zhao, Houlsby & Utili 2014, eq. 14, Fig. 8):
//   rho_bulk(z) = eps(z) rho_f + (1 - eps(z)) rho_s,
// eps(z) the solver's voidage on the analysis grid (analysis/voidage_grid.hpp) averaged
// over the nodes of each horizontal layer. Within a kernel support of the wall the kernel
// reaches below z = 0 where there are no spheres, so eps is over-estimated there and
// rho_bulk under-estimated (the solver's own first layers have the same truncation).
#include <string>
#include <vector>

#include "analysis/voidage_grid.hpp"

namespace sphdem {

struct BulkDensityProfile {
  std::vector<double> z;             // layer height (m)
  std::vector<double> voidage;       // layer mean of eps
  std::vector<double> bulk_density;  // (kg/m^3)
};

// Layers of `grid` with 0 <= z <= z_top; `voidage` in the grid's VTK order (x fastest).
BulkDensityProfile bulk_density_profile(const std::vector<double>& voidage, const GridSpec& grid,
                                        double rho_f, double rho_s, double z_top);

// CSV: z,voidage,bulk_density.
void write_bulk_density_csv(const BulkDensityProfile& p, const std::string& path);

}  // namespace sphdem
