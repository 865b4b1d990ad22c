#pragma once
// The drag coefficients c_j (f_d = c_j u_s, 2.73-2.87) of a range of spheres in one pass,
// from the superficial slip u_s = eps_j (u_f - v_j) (2.74) at their current velocities,
// for the DEM sub-step's force pass to read. Where the CPU has AVX-512 the pass runs in
// eight lanes with the vector forms of exp, log10 and pow (glibc's libmvec, within
// 4 ulp of libm); elsewhere it is the scalar loop. A sphere no fluid particle reaches
// (Shepard sum 0) gets c = 0.
#include <cstddef>

#include "coupling/drag_laws.hpp"
#include "dem/dem_particles.hpp"
#include "sph/pair_isa.hpp"

namespace sphdem {

template <class Law>
void drag_coefficients(const Law& law, const DemParticles& s, const drag::Fluid& fluid,
                       std::size_t begin, std::size_t end, double* c, PairIsa isa);

}  // namespace sphdem
