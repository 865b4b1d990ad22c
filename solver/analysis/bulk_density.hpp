#pragma once
// Bulk density profile of the mixture (Zhao, Houlsby & Utili 2014, eq. 14, Fig. 8):
//   rho_bulk(z) = eps(z) rho_f + (1 - eps(z)) rho_s,
// eps(z) the grains' voidage at the lattice's h (analysis/voidage_grid.hpp:
// grain_voidage_on_grid; the solver's own field is smoother in a sediment, where its
// kernels are wider) averaged over the nodes of each horizontal layer. Within a kernel
// support of the wall the kernel reaches below z = 0 where there are no spheres, so eps is
// over-estimated there and rho_bulk under-estimated.
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
