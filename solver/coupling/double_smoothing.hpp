#pragma once
// Bidisperse voidage by double smoothing (thesis §3.4, eqs. 3.8-3.10).
//
// The fluid resolution is set by the small spheres (dx = 2 d_small); a big sphere is
// comparable to an SPH particle, so its volume smoothed with the fluid kernel gives
// voidages near zero next to it. Instead the big spheres are smoothed first with a
// kernel of their own size, h_j = c d_j (3.9), onto every SPH particle b:
//   phi_b = sum_{j big} V_j W(r_bj, h_j),
// and that solid fraction is smoothed again with the fluid kernel (3.10):
//   eps_a = 1 - sum_{i small} V_i W_ai - sum_b V_b phi_b W_ab / sum_b V_b W_ab  (W at h_a),
// V_b = m_b / rho_b. (3.10) prints V_BIG in the second sum; the volume of the SPH
// particle b is what makes it a kernel interpolation of phi, and the Shepard
// denominator keeps a uniform phi uniform next to the free surface.
// The small spheres' part (3.8) is compute_fluid_voidage with the big species skipped.
#include <cstdint>
#include <vector>

#include "dem/dem_particles.hpp"
#include "domain/cell_list.hpp"
#include "sph/fluid_particles.hpp"

namespace sphdem {

struct BigSphereFraction {
  std::vector<double> phi;         // sum_j V_j W(r_bj, h_j) per SPH particle (owned + halo)
  std::vector<double> phi_over_d;  // sum_j V_j / d_j W(r_bj, h_j): for the Sauter mean (2.80)
};

// (3.9) at the owned SPH particles. big_cells bins all spheres (owned + halo) at a
// cut-off >= 2 c max d_big; is_big[species] selects the big ones.
void smooth_big_spheres(const FluidParticles& f, const DemParticles& s, const CellList& big_cells,
                        const std::vector<std::uint8_t>& is_big, double h_over_d,
                        BigSphereFraction& out);

// (3.10): the Shepard interpolation of phi (and phi/d) at every owned SPH particle with
// its own kernel, over the SPH particles binned in fluid_cells (owned + halo, with phi
// filled on the halo). Results in `solid` and `solid_over_d` (owned entries).
void resmooth_with_fluid_kernel(const FluidParticles& f, const CellList& fluid_cells,
                                const BigSphereFraction& big, std::vector<double>& solid,
                                std::vector<double>& solid_over_d);

}  // namespace sphdem
