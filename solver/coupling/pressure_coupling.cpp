#include "coupling/pressure_coupling.hpp"

#include "coupling/interpolation.hpp"

namespace sphdem {

double couple_pressure_variationally(FluidParticles& f, DemParticles& s,
                                     const FluidSpherePairs& pairs, const Halo& halo,
                                     PairAccumulator& acc, const HydrostaticPressure& ph) {
  return interpolate_fluid_at_spheres(s, f, pairs, halo, acc, &ph);
}

}  // namespace sphdem
