#pragma once
// Excess pore pressure at the base (Zhao, Houlsby & Utili 2014, Fig. 11 and eq. 15):
// the pore pressure P minus the hydrostatic pressure of clear water, normalised by the
// hydrostatic pressure at the base,
//   u_base / (rho_f |g| H) = mean over a in the first fluid layer of
//                            (P_a - rho_f |g| (H - z_a)) / (rho_f |g| H),
// with P the Tait gauge pressure (2.58, zero at the free surface) and H the free-surface
// height (`fluid.fill_height`; the mixture's height does not change as the grains
// settle). The first layer is the mobile fluid particles with z < dx (the lattice puts
// them at dx/2). Zero for water at rest; (1 - n)(rho_s/rho_f - 1) once a suspension of
// porosity n filling the column is carried by the fluid (eq. 15), up to the kernel sums'
// error times the absolute pressure, which this point reading carries: fluid_load_base
// below is the measure the validation uses and the one log.csv shows. This reading is kept
// for the tests (water at rest reads none) and is not shown to users: it departs from the
// load while a bed forms (validation/README.md, sessions 22-23 and 39).
#include "dem/dem_particles.hpp"
#include "domain/rank_comm.hpp"
#include "sph/fluid_particles.hpp"
#include "sph/hydrostatic_pressure.hpp"

namespace sphdem {

struct BasePorePressure {
  double rho_f = 1000.0;  // fluid density (kg/m^3)
  double g = 9.81;        // |g| (m/s^2)
  double H = 1.0;         // free-surface height (m)
  double dx = 1e-3;       // lattice spacing: the first layer is z < dx (m)
};

// NaN when the first layer holds no fluid particle.
// (comm: the ranks the particles are shared over; their sums are reduced.)
double excess_pore_pressure_base(const FluidParticles& f, const BasePorePressure& b,
                                 const RankComm& comm = RankComm(MPI_COMM_NULL));

// The spheres' contact load on the bottom wall (z = 0) in the same unit: the elastic
// normal force sum_i k max(0, r_i - z_i) over (area rho_f |g| H), k the normal stiffness
// of the linear contact law. A bed at rest puts eq. 15 here.
double wall_load_base(const DemParticles& s, double k, double area, const BasePorePressure& b,
                      const RankComm& comm = RankComm(MPI_COMM_NULL));

// The fluid's excess load on the bottom wall in the same unit: the mean excess pore
// pressure over the base as the wall feels it (a transducer's reading in the continuum,
// integral of P - rho_f |g| H over the base / area), measured as the forces the wall
// particles put on the column:
//   F = sum over mobile a of m_a theta_z,a  (the SPH pairs with the walls: the pairs
//                                            between mobile particles cancel in the sum)
//     + walls_on_spheres_z                  (the variational pairs of the wall particles
//                                            with the spheres, pressure_coupling.hpp)
//     - sum_a dP_h/dz(z_a) m_a eps_a / rho_a  (the hydrostatic split's analytic
//     - sum_j dP_h/dz(z_j) V_j                 forces, zero without it),
//   fluid_load = (F - |g| sum_a m_a - rho_f |g| sum_j V_j) / (area rho_f |g| H):
// the fluid's weight and the weight of the water the spheres displace are the clear
// column's load, so water at rest reads 0. With wall_load_base it closes the column's
// vertical momentum balance (solid + fluid, periodic sides; every force from below is in
// one of the two): fluid_load + wall_load = (1 - n)(rho_s/rho_f - 1) + (dP/dt) / (area
// rho_f |g| H), P the column's upward momentum, so a suspension in steady settling puts
// eq. 15 here. The first-layer mean above reads the pressure through the kernel sums'
// error: in the reduced sand column at rest 0.37 while the wall carries 0.91 x eq. 15 in
// contacts and this load is 0.014.
double fluid_load_base(const FluidParticles& f, const DemParticles& s, double walls_on_spheres_z,
                       const HydrostaticPressure& ph, double area, const BasePorePressure& b,
                       const RankComm& comm = RankComm(MPI_COMM_NULL));

}  // namespace sphdem
