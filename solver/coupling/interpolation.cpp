#include "coupling/interpolation.hpp"

#include <omp.h>

#include "coupling/drag_law_table.hpp"
#include "domain/row_partition.hpp"
#include "sph/pair_isa.hpp"

namespace sphdem {

namespace {

// A sphere's row of sums, two blocks of eight: eight weighted by the drag's kernel W_jb
// (the first block, one vector add per pair); then the first five of them over the kernel's
// upstream half only (with pairs.upstream; one vector add per pair, its last three lanes
// zero) and three that carry the fluid's force: m_b theta_b W_jb (interpolated), or the
// variational pairs' V_a P_a grad_a W_aj.
enum { kS, kEps, kUx, kUy, kUz, kDs, kDw, kPad, kUpstream, kGx = kUpstream + 5, kGy, kGz, kRow };
constexpr int kWeighted = 8;
// The least share of the Shepard sum S_j the upstream half must hold to be read alone: about
// half in the bulk; less within a kernel of the floor, where the whole kernel is read.
constexpr double kUpstreamShareMin = 0.25;
// The first block as one vector (one AVX-512 register, or four SSE2 ones; GCC/Clang).
using Block = double __attribute__((vector_size(kWeighted * sizeof(double))));
// The lanes of the first block the upstream block repeats: kS, kEps, kUx, kUy, kUz.
constexpr Block kUpstreamLanes = {1.0, 1.0, 1.0, 1.0, 1.0, 0.0, 0.0, 0.0};
static_assert(kS == 0 && kEps == 1 && kUx == 2 && kUy == 3 && kUz == 4 && kRow == 2 * kWeighted);
inline void add_block(double* r, double w, const Block& q) {  // r[0..8) += w q
  Block v;
  __builtin_memcpy(&v, r, sizeof v);
  v += w * q;
  __builtin_memcpy(r, &v, sizeof v);
}

// What a mobile fluid particle b gives the first block per unit W_jb: V_b, V_b eps_b,
// V_b u_b, and V_b d_b, V_b where there are solids (the Sauter mean, Shepard-averaged);
// zeros for a wall particle.
void stage_fluid(const FluidParticles& f, double* staged) {
  const long nf = static_cast<long>(f.n_owned);
#pragma omp parallel for schedule(static)
  for (long b = 0; b < nf; ++b) {
    double* q = staged + kWeighted * b;
    const double vb = f.kind[b] == kFluid ? f.mass[b] / f.rho[b] : 0.0;
    const double vd = f.d_sauter[b] > 0.0 ? vb : 0.0;
    q[kS] = vb;
    q[kEps] = vb * f.eps_drag[b];
    q[kUx] = vb * f.vx[b];
    q[kUy] = vb * f.vy[b];
    q[kUz] = vb * f.vz[b];
    q[kDs] = vd * f.d_sauter[b];
    q[kDw] = vd;
    q[kPad] = 0.0;
  }
}

// The thread's share of the fluid rows: every pair adds its drag-weighted block and its
// force part to the row of the sphere image; with kPressure the variational pairs (and the
// fluid's own share of them, added to its acceleration), else m_b theta_b W_jb.
template <bool kPressure>
inline double scatter_rows(FluidParticles& f, const DemParticles& s, const FluidSpherePairs& pairs,
                           const double* staged, PairAccumulator& acc,
                           const HydrostaticPressure& ph) {
  const long nf = static_cast<long>(f.n_owned);
  const int t = omp_get_thread_num();
  const std::uint32_t* __restrict sphere = pairs.sphere.data();
  const double* __restrict wd = pairs.drag_w().data();
  const double* __restrict grad = pairs.grad.data();
  double walls_on_spheres_z = 0.0;
  const double ux = pairs.upstream[0], uy = pairs.upstream[1], uz = pairs.upstream[2];
  const bool upstream = ux != 0.0 || uy != 0.0 || uz != 0.0;
  // rows differ in length: contiguous shares of equal entries (domain/row_partition.hpp),
  // whose spheres' rows stay in the thread's cache
  const auto [lo, hi] = thread_rows(pairs.list.offset, nf, kFluidRowCost);
  for (std::size_t b = lo; b < hi; ++b) {
    const bool mobile = f.kind[b] == kFluid;
    if (!kPressure && !mobile) continue;
    Block q;
    __builtin_memcpy(&q, staged + kWeighted * b, sizeof q);
    const Block q_upstream = q * kUpstreamLanes;
    const double xb = f.x[b], yb = f.y[b], zb = f.z[b], mb = f.mass[b];
    const double p_dyn = kPressure ? f.P[b] - ph(zb) : 0.0;
    const double vp = mb / f.rho[b] * p_dyn;  // V_b P_b
    const Block theta = {0.0, 0.0, 0.0, 0.0, 0.0, mb * f.thx[b], mb * f.thy[b], mb * f.thz[b]};
    double gx = 0.0, gy = 0.0, gz = 0.0;  // sum_j V_j grad_b W_bj = -grad eps_b
    for (std::uint32_t k = pairs.begin(b); k < pairs.end(b); ++k) {
      const std::uint32_t j = sphere[k];
      double* __restrict r = acc.row(t, j);  // a halo image's row goes to its owner later
      const double w = wd[k];
      add_block(r, w, q);
      // the second block in one vector add: the upstream sums (a pair on the other side adds
      // zeros: branch-free, as the sides of a sphere's pairs come in no order) and the force
      const double dx = xb - s.x[j], dy = yb - s.y[j], dz = zb - s.z[j];
      const double w_upstream = upstream && dx * ux + dy * uy + dz * uz >= 0.0 ? w : 0.0;
      if constexpr (kPressure) {  // per unit sphere volume
        const double gf = grad[k], c = s.volume(j) * gf, pg = vp * gf;
        gx += c * dx;
        gy += c * dy;
        gz += c * dz;
        const Block force = {0.0, 0.0, 0.0, 0.0, 0.0, dx, dy, dz};
        add_block(r + kUpstream, 1.0, w_upstream * q_upstream + pg * force);
      } else {
        add_block(r + kUpstream, 1.0, w_upstream * q_upstream + w * theta);
      }
    }
    if constexpr (kPressure) {
      if (!mobile) {  // a wall particle: what it pushes on the spheres, V_b P_b sum_j V_j dW/dz_b
        walls_on_spheres_z += vp * gz;
        continue;
      }
      const double p_over_rho = p_dyn / f.rho[b];
      f.ax[b] -= p_over_rho * gx;
      f.ay[b] -= p_over_rho * gy;
      f.az[b] -=
          p_over_rho * gz + ph.gradient_z(zb) * f.eps[b] / f.rho[b];  // -grad P_h / rho_intrinsic
    }
  }
  return walls_on_spheres_z;
}

SPHDEM_TARGET_AVX512 double scatter_avx512(FluidParticles& f, const DemParticles& s,
                                           const FluidSpherePairs& pairs, const double* staged,
                                           PairAccumulator& acc, const HydrostaticPressure* ph) {
  return ph ? scatter_rows<true>(f, s, pairs, staged, acc, *ph)
            : scatter_rows<false>(f, s, pairs, staged, acc, {});
}

double scatter_baseline(FluidParticles& f, const DemParticles& s, const FluidSpherePairs& pairs,
                        const double* staged, PairAccumulator& acc, const HydrostaticPressure* ph) {
  return ph ? scatter_rows<true>(f, s, pairs, staged, acc, *ph)
            : scatter_rows<false>(f, s, pairs, staged, acc, {});
}

}  // namespace

double interpolate_fluid_at_spheres(DemParticles& s, FluidParticles& f,
                                    const FluidSpherePairs& pairs, const Halo& halo,
                                    PairAccumulator& acc, const HydrostaticPressure* pressure,
                                    PairIsa isa) {
  const std::size_t ns = s.n_owned;
  acc.reset(s.size(), kRow);
  double* staged = acc.staged(kWeighted * f.n_owned);
  stage_fluid(f, staged);
  double walls_on_spheres_z = 0.0;
#pragma omp parallel reduction(+ : walls_on_spheres_z)
  walls_on_spheres_z += isa == PairIsa::kAvx512
                            ? scatter_avx512(f, s, pairs, staged, acc, pressure)
                            : scatter_baseline(f, s, pairs, staged, acc, pressure);
  double* sums = acc.fold();        // rows of the threads' sums
  halo.add_to_sources(sums, kRow);  // the halo images' sums to their owners
#pragma omp parallel for schedule(static)
  for (long j = 0; j < static_cast<long>(ns); ++j) {
    const auto sum = [&](int field) { return sums[j * kRow + field]; };
    const double S = sum(kS);
    s.shepard[j] = S;
    if (S > 0.0) {
      // the drag's voidage and fluid velocity from the upstream half where it holds enough
      // and the sphere is not alone (where the clear liquid is all there is to read)
      const double S_up = sum(kUpstream + kS);
      const bool among_spheres = sum(kEps) < kLoneSphereVoidage * S;
      const int from = S_up >= kUpstreamShareMin * S && among_spheres ? kUpstream : 0;
      const double inv = 1.0 / (from ? S_up : S);
      s.eps[j] = sum(from + kEps) * inv;
      s.ufx[j] = sum(from + kUx) * inv;
      s.ufy[j] = sum(from + kUy) * inv;
      s.ufz[j] = sum(from + kUz) * inv;
      const double dw = sum(kDw);
      s.d_sauter[j] = dw > 0.0 ? sum(kDs) / dw : 2.0 * s.radius[j];
    } else {
      s.d_sauter[j] = 2.0 * s.radius[j];
      s.eps[j] = 1.0;
      s.ufx[j] = s.ufy[j] = s.ufz[j] = 0.0;
    }
    // the pressure force / V_j, sum_a V_a P_a grad_a W_aj, and the buoyancy -grad P_h
    if (pressure) {
      s.gx[j] = sum(kGx);
      s.gy[j] = sum(kGy);
      s.gz[j] = sum(kGz) - pressure->gradient_z(s.z[j]);
    } else if (S > 0.0) {  // (2.69)
      const double inv = 1.0 / S;
      s.gx[j] = sum(kGx) * inv;
      s.gy[j] = sum(kGy) * inv;
      s.gz[j] = sum(kGz) * inv;
    } else {
      s.gx[j] = s.gy[j] = s.gz[j] = 0.0;
    }
  }
  return walls_on_spheres_z;
}

}  // namespace sphdem
