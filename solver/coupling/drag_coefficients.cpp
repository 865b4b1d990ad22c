// The libm functions the drag laws call, declared with their vector forms (the OpenMP
// simd ABI that libmvec implements) so that the AVX-512 loop below calls those. The
// glibc headers declare them only under -ffast-math; this file alone sees them,
// before any header that calls them.
extern "C" {
__attribute__((simd("notinbranch"))) double exp(double) noexcept;
__attribute__((simd("notinbranch"))) double log10(double) noexcept;
__attribute__((simd("notinbranch"))) double pow(double, double) noexcept;
}

#include "coupling/drag_coefficients.hpp"

#include <cmath>

namespace sphdem {
namespace {

// The sphere fields a coefficient reads, as plain pointers (the lanes load them directly).
struct SphereFields {
  const double *shepard, *eps, *ufx, *ufy, *ufz, *vx, *vy, *vz, *radius, *d_sauter;
  explicit SphereFields(const DemParticles& s)
      : shepard(s.shepard.data()),
        eps(s.eps.data()),
        ufx(s.ufx.data()),
        ufy(s.ufy.data()),
        ufz(s.ufz.data()),
        vx(s.vx.data()),
        vy(s.vy.data()),
        vz(s.vz.data()),
        radius(s.radius.data()),
        d_sauter(s.d_sauter.data()) {}
};

template <class Law>
inline double coefficient_of(const Law& law, const SphereFields& s, const drag::Fluid& fluid,
                             std::size_t j) {
  const double shepard = s.shepard[j], eps_j = s.eps[j];
  const bool reached = shepard > 0.0;
  const double eps = reached ? eps_j : 1.0;
  const double usx = eps * (s.ufx[j] - s.vx[j]);
  const double usy = eps * (s.ufy[j] - s.vy[j]);
  const double usz = eps * (s.ufz[j] - s.vz[j]);
  const double us = std::sqrt(usx * usx + usy * usy + usz * usz);
  const double c = drag::drag_coefficient(law, eps, us, 2.0 * s.radius[j], s.d_sauter[j], fluid);
  return reached ? c : 0.0;
}

template <class Law>
void coefficients_scalar(const Law& law, const SphereFields& s, const drag::Fluid& fluid,
                         std::size_t begin, std::size_t end, double* c) {
  for (std::size_t j = begin; j < end; ++j) c[j] = coefficient_of(law, s, fluid, j);
}

template <class Law>
SPHDEM_TARGET_AVX512 void coefficients_avx512(const Law& law, const SphereFields& s,
                                              const drag::Fluid& fluid, std::size_t begin,
                                              std::size_t end, double* c) {
  const Law l = law;
  const drag::Fluid f = fluid;
#pragma omp simd
  for (std::size_t j = begin; j < end; ++j) c[j] = coefficient_of(l, s, f, j);
}

}  // namespace

template <class Law>
void drag_coefficients(const Law& law, const DemParticles& s, const drag::Fluid& fluid,
                       std::size_t begin, std::size_t end, double* c, PairIsa isa) {
  const SphereFields fields(s);
  if (isa == PairIsa::kAvx512)
    coefficients_avx512(law, fields, fluid, begin, end, c);
  else
    coefficients_scalar(law, fields, fluid, begin, end, c);
}

#define SPHDEM_DRAG_COEFFICIENTS(Law)                                                      \
  template void drag_coefficients<drag::Law>(const drag::Law&, const DemParticles&,        \
                                             const drag::Fluid&, std::size_t, std::size_t, \
                                             double*, PairIsa);
SPHDEM_DRAG_COEFFICIENTS(Stokes)
SPHDEM_DRAG_COEFFICIENTS(DiFeliceDallavalle)
SPHDEM_DRAG_COEFFICIENTS(CoulsonRichardson)
SPHDEM_DRAG_COEFFICIENTS(BrownLawler)
SPHDEM_DRAG_COEFFICIENTS(BeetstraPolydisperse)
SPHDEM_DRAG_COEFFICIENTS(NoDrag)
#undef SPHDEM_DRAG_COEFFICIENTS

}  // namespace sphdem
