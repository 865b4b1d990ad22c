#pragma once
// Fluid force on the spheres (2.68): f_j = V_j (-grad P + div tau)_j + c_j u_s, with the
// superficial slip u_s = eps_j (u_f - v_j) (2.74) and the drag coefficient c_j of the
// sphere's law at that slip (2.73-2.87). The interpolated fluid fields are held fixed over
// the DEM sub-steps; the drag follows the sphere's velocity. A sphere no fluid particle
// reaches (Shepard sum 0) gets c = 0 and no fluid force.
//
// Where the CPU has AVX-512 the passes run in eight lanes with the vector forms of exp,
// log10 and pow (glibc's libmvec, within 4 ulp of libm); elsewhere they are scalar loops.
#include <cstddef>
#include <vector>

#include "coupling/drag_law_table.hpp"
#include "dem/dem_particles.hpp"
#include "sph/pair_isa.hpp"

namespace sphdem {

// The drag coefficients c_j of spheres [begin, end) at their current velocities. (Each
// entry point visits the law once and runs the loop of that law's evaluator.)
void drag_coefficients(const drag::DragLaw& law, const DemParticles& s, const drag::Fluid& fluid,
                       std::size_t begin, std::size_t end, double* c, PairIsa isa);

// The drag exchange's gains g_j = eps_j d|f_j|/d|u_s| of spheres [begin, end) at their
// current velocities: d f_j / d u_f along the slip (2.68, 2.74) with the law linearised
// (coupling/drag_linearisation.hpp), so that the exchange's explicit limit and its
// backward Euler hold for the fastest rate the law relaxes at, not its secant c eps.
void drag_gains(const drag::DragLaw& law, const DemParticles& s, const drag::Fluid& fluid,
                std::size_t begin, std::size_t end, double* gain);

// What a DEM sub-step does with the new fluid force besides keeping it in (fx, fy, fz):
// with `accumulate_mean`, the trapezoid of the sub-step, weight (f_old + f_new), goes to
// the mean force fm (the variational coupling's constant pressure part, 2 V g, not in it).
struct FluidForceWindow {
  bool accumulate_mean = false;
  double weight = 0;
  bool variational = false;
};

// Spheres per block of a force pass: a block's fluid forces are still in the cache when
// its sphere rows use them.
inline constexpr std::size_t kSphereBlock = 256;

// What the spheres' fluid force passes leave behind: each owned sphere's drag coefficient
// (the drag exchange's gains, coupling/drag_exchange.hpp) and the largest relaxation rate
// (which bounds the next half step's sub-step), with the lanes the passes run in.
// The drag's state over the sub-steps besides each sphere's coefficient (DemParticles'
// drag_c, which migrates and re-sorts with its sphere).
struct SphereDrag {
  double rate_max = 0;  // 0 before the first pass and without fluid
  PairIsa isa = best_pair_isa();
};

// The fluid force on spheres [begin, end) into (fx, fy, fz) after its share of the window
// went to fm, their drag coefficients into c; returns the largest drag relaxation rate
// c_j eps_j / m_j among them (d f / d v = -c eps).
double fluid_forces(const drag::DragLaw& law, DemParticles& s, const drag::Fluid& fluid,
                    std::size_t begin, std::size_t end, const FluidForceWindow& window, double* c,
                    PairIsa isa);

}  // namespace sphdem
