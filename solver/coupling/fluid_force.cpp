// The libm functions the drag laws call, declared with their vector forms (the OpenMP
// simd ABI that libmvec implements) so that the AVX-512 loop below calls those. The
// glibc headers declare them only under -ffast-math; this file alone sees them,
// before any header that calls them.
extern "C" {
__attribute__((simd("notinbranch"))) double exp(double) noexcept;
__attribute__((simd("notinbranch"))) double log10(double) noexcept;
__attribute__((simd("notinbranch"))) double pow(double, double) noexcept;
}

#include "coupling/fluid_force.hpp"

#include <algorithm>
#include <cmath>

#include "coupling/drag_linearisation.hpp"

namespace sphdem {
namespace {

// The sphere fields the passes read and write, as plain pointers (the lanes load them directly).
struct SphereFields {
  const double *shepard, *eps, *ufx, *ufy, *ufz, *vx, *vy, *vz, *radius, *d_sauter, *mass, *gx, *gy,
      *gz;
  double *fx, *fy, *fz, *fmx, *fmy, *fmz;
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
        d_sauter(s.d_sauter.data()),
        mass(s.mass.data()),
        gx(s.gx.data()),
        gy(s.gy.data()),
        gz(s.gz.data()),
        fx(nullptr),
        fy(nullptr),
        fz(nullptr),
        fmx(nullptr),
        fmy(nullptr),
        fmz(nullptr) {}
  explicit SphereFields(DemParticles& s) : SphereFields(static_cast<const DemParticles&>(s)) {
    fx = s.fx.data();
    fy = s.fy.data();
    fz = s.fz.data();
    fmx = s.fmx.data();
    fmy = s.fmy.data();
    fmz = s.fmz.data();
  }
};

// The voidage the slip (2.74) of sphere j sees: 1 where no fluid reaches it. (Every load
// unconditional, here and below: a load under a condition keeps a loop out of lanes.)
inline double slip_voidage(const SphereFields& s, std::size_t j) {
  const double eps = s.eps[j];
  return s.shepard[j] > 0.0 ? eps : 1.0;
}

// c_j of sphere j at the superficial slip u_s (its law's, 0 where no fluid reaches it).
template <class Law>
inline double coefficient_at(const Law& law, const SphereFields& s, const drag::Fluid& fluid,
                             std::size_t j, double eps, double usx, double usy, double usz) {
  const double us = std::sqrt(usx * usx + usy * usy + usz * usz);
  const double c = drag::drag_coefficient(law, eps, us, 2.0 * s.radius[j], s.d_sauter[j], fluid);
  return s.shepard[j] > 0.0 ? c : 0.0;
}

template <class Law>
inline double coefficient_of(const Law& law, const SphereFields& s, const drag::Fluid& fluid,
                             std::size_t j) {
  const double eps = slip_voidage(s, j);
  return coefficient_at(law, s, fluid, j, eps, eps * (s.ufx[j] - s.vx[j]),
                        eps * (s.ufy[j] - s.vy[j]), eps * (s.ufz[j] - s.vz[j]));
}

// (2.68) on sphere j: the force into f after the window's share went to fm; its
// relaxation rate c eps / m returned.
template <bool kMean, class Law>
inline double fluid_force_of(const Law& law, const SphereFields& s, const drag::Fluid& fluid,
                             const FluidForceWindow& w, std::size_t j, double* c) {
  const double eps = slip_voidage(s, j);
  const double usx = eps * (s.ufx[j] - s.vx[j]);
  const double usy = eps * (s.ufy[j] - s.vy[j]);
  const double usz = eps * (s.ufz[j] - s.vz[j]);
  const double cj = coefficient_at(law, s, fluid, j, eps, usx, usy, usz);
  c[j] = cj;
  const bool reached = s.shepard[j] > 0.0;
  const double r = s.radius[j];
  const double V = 4.0 / 3.0 * 3.14159265358979323846 * r * r * r;
  const double gx = s.gx[j], gy = s.gy[j], gz = s.gz[j];
  const double fx = reached ? V * gx + cj * usx : 0.0;
  const double fy = reached ? V * gy + cj * usy : 0.0;
  const double fz = reached ? V * gz + cj * usz : 0.0;
  if constexpr (kMean) {  // trapezoidal impulse of the sub-step: 0.5 dt (f_old + f_new)
    const double vp2 = w.variational ? 2.0 * V : 0.0;
    s.fmx[j] += w.weight * (s.fx[j] + fx - vp2 * gx);
    s.fmy[j] += w.weight * (s.fy[j] + fy - vp2 * gy);
    s.fmz[j] += w.weight * (s.fz[j] + fz - vp2 * gz);
  }
  s.fx[j] = fx;
  s.fy[j] = fy;
  s.fz[j] = fz;
  return cj * s.eps[j] / s.mass[j];
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

template <bool kMean, class Law>
double forces_scalar(const Law& law, const SphereFields& s, const drag::Fluid& fluid,
                     const FluidForceWindow& w, std::size_t begin, std::size_t end, double* c) {
  double rate_max = 0.0;
  for (std::size_t j = begin; j < end; ++j)
    rate_max = std::max(rate_max, fluid_force_of<kMean>(law, s, fluid, w, j, c));
  return rate_max;
}

template <bool kMean, class Law>
SPHDEM_TARGET_AVX512 double forces_avx512(const Law& law, const SphereFields& s,
                                          const drag::Fluid& fluid, const FluidForceWindow& w,
                                          std::size_t begin, std::size_t end, double* c) {
  const Law l = law;
  const drag::Fluid f = fluid;
  const FluidForceWindow window = w;
  double rate_max = 0.0;
#pragma omp simd reduction(max : rate_max)
  for (std::size_t j = begin; j < end; ++j) {
    const double rate = fluid_force_of<kMean>(l, s, f, window, j, c);
    rate_max = rate > rate_max ? rate : rate_max;
  }
  return rate_max;
}

}  // namespace

void drag_coefficients(const drag::DragLaw& law, const DemParticles& s, const drag::Fluid& fluid,
                       std::size_t begin, std::size_t end, double* c, PairIsa isa) {
  const SphereFields fields(s);
  std::visit(
      [&](const auto& l) {
        if (isa == PairIsa::kAvx512)
          coefficients_avx512(l, fields, fluid, begin, end, c);
        else
          coefficients_scalar(l, fields, fluid, begin, end, c);
      },
      law);
}

void drag_gains(const drag::DragLaw& law, const DemParticles& s, const drag::Fluid& fluid,
                std::size_t begin, std::size_t end, double* gain) {
  const SphereFields f(s);
  std::visit(
      [&](const auto& l) {
        for (std::size_t j = begin; j < end; ++j) {
          const double eps = slip_voidage(f, j);
          const double usx = eps * (f.ufx[j] - f.vx[j]), usy = eps * (f.ufy[j] - f.vy[j]),
                       usz = eps * (f.ufz[j] - f.vz[j]);
          const double us = std::sqrt(usx * usx + usy * usy + usz * usz);
          const double c =
              drag::linearised_coefficient(l, eps, us, 2.0 * f.radius[j], f.d_sauter[j], fluid);
          gain[j] = f.shepard[j] > 0.0 ? c * f.eps[j] : 0.0;
        }
      },
      law);
}

double fluid_forces(const drag::DragLaw& law, DemParticles& s, const drag::Fluid& fluid,
                    std::size_t begin, std::size_t end, const FluidForceWindow& window, double* c,
                    PairIsa isa) {
  const SphereFields fields(s);
  return std::visit(
      [&](const auto& l) {
        if (isa == PairIsa::kAvx512)
          return window.accumulate_mean
                     ? forces_avx512<true>(l, fields, fluid, window, begin, end, c)
                     : forces_avx512<false>(l, fields, fluid, window, begin, end, c);
        return window.accumulate_mean
                   ? forces_scalar<true>(l, fields, fluid, window, begin, end, c)
                   : forces_scalar<false>(l, fields, fluid, window, begin, end, c);
      },
      law);
}

}  // namespace sphdem
