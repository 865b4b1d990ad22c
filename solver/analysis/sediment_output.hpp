#pragma once
// The end-of-run observables of a settling column (Zhao, Houlsby & Utili 2014), written
// by run_scene after the last step of every scene with spheres (on ranks, rank 0 writes
// them from the grid summed and the spheres and contacts gathered over the ranks):
//   DIR/bulk_density.csv      rho_bulk(z) (analysis/bulk_density.hpp), on a grid of spacing
//                             fluid.spacing with the kernel h = sigma dx; only with fluid
//                             and when every species has the same density (else rho_s is
//                             ambiguous)
//   DIR/size_thirds.csv       size distribution of the bottom, middle, top thirds
//                             (analysis/size_thirds.hpp), 10 bins over [d_min, d_max]
//   DIR/contact_network.csv   every contact: ids, centres, normal force
//   DIR/contact_network.vtp   the same as lines (analysis/contact_network.hpp)
#include <string>

namespace sphdem {

class Simulation;

void write_sediment_output(const Simulation& sim, const std::string& out_dir);

}  // namespace sphdem
