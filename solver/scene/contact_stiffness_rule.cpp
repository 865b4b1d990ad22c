#include "scene/contact_stiffness_rule.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "scene/kernel_width_rule.hpp"

namespace sphdem {

namespace {

// The largest contact force in a random packing over the mean load on d^2 (with margin).
constexpr double kForceChains = 4.0;

// delta_max omega0 / v of a linear spring-dashpot with restitution e (2.46-2.47): with
// beta = 2 m12 eta and eta/omega = a = -ln(e)/pi, exp(-a asin(1/sqrt(1 + a^2))).
// 1 without a restitution (a fixed dashpot: the undamped bound).
double damping_factor(const LinearSpringDashpot& law) {
  if (!(law.restitution > 0.0 && law.restitution < 1.0)) return 1.0;
  const double a = -std::log(law.restitution) / M_PI;
  return std::exp(-a * std::asin(1.0 / std::sqrt(1.0 + a * a)));
}

// Solid volume a group places (its region times 1 - voidage; one sphere for a single).
double solid_volume(const Scene& sc, const ParticleGroupSpec& g) {
  if (g.kind == ParticleGroupSpec::Kind::kSingle) {
    const double d = sc.species[sc.species_index(g.species)].d_max();
    return M_PI * d * d * d / 6.0;
  }
  return (g.hi[0] - g.lo[0]) * (g.hi[1] - g.lo[1]) * (g.hi[2] - g.lo[2]) * (1.0 - g.voidage);
}

// The heaviest buoyant density of a group's species (a mixture: its heaviest).
double buoyant_density(const Scene& sc, const ParticleGroupSpec& g, double rho_f) {
  double rho = sc.species[sc.species_index(g.species)].density;
  for (const auto& name : g.mixture)
    rho = std::max(rho, sc.species[sc.species_index(name)].density);
  return std::max(rho - rho_f, 0.0);
}

}  // namespace

StiffnessChoice choose_contact_stiffness(const Scene& sc) {
  const double g = sc.gravity_magnitude();
  const double f = sc.contact.max_overlap;
  const bool fluid = sc.fluid.enabled;
  const double rho_f = fluid ? sc.fluid.density : 0.0;
  StiffnessChoice c;
  // The largest initial speed of a group, and the highest point a sphere starts from.
  double v_start = 0.0, z_top = 0.0;
  for (const auto& grp : sc.particles) {
    const double v =
        std::sqrt(grp.velocity[0] * grp.velocity[0] + grp.velocity[1] * grp.velocity[1] +
                  grp.velocity[2] * grp.velocity[2]) +
        std::sqrt(3.0) * grp.velocity_jitter;
    v_start = std::max(v_start, v);
    z_top =
        std::max(z_top, grp.kind == ParticleGroupSpec::Kind::kSingle ? grp.position[2] : grp.hi[2]);
  }
  // Impact: each species' largest sphere at the larger of its terminal (or free-fall) speed
  // and the groups' initial speed, against the wall (m12 = m).
  const double damping = damping_factor(sc.contact.normal);
  double k_impact = 0.0, k_static = 0.0;
  for (const SpeciesSpec& s : sc.species) {
    const double d = s.d_max(), m = s.density * M_PI * d * d * d / 6.0;
    double v = v_start;
    if (g > 0.0)
      v = std::max(v, fluid ? terminal_speed(sc.drag, d, s.density, rho_f, sc.fluid.viscosity, g)
                            : std::sqrt(2.0 * g * z_top));
    if (!std::isfinite(v)) v = std::sqrt(2.0 * g * z_top);  // no drag: free fall
    c.impact_speed = std::max(c.impact_speed, v);
    const double x = damping * v / (f * d);
    k_impact = std::max(k_impact, m * x * x);
  }
  // At rest: the whole solid's buoyant weight per unit floor area on the bottom sphere's d^2.
  double p = 0.0;
  for (const auto& grp : sc.particles)
    p += buoyant_density(sc, grp, rho_f) * g * solid_volume(sc, grp);
  p /= sc.box.length(0) * sc.box.length(1);
  double d_big = 0.0;
  for (const SpeciesSpec& s : sc.species) d_big = std::max(d_big, s.d_max());
  k_static = kForceChains * p * d_big / f;
  const double raw = std::max(k_impact, k_static);
  if (!(raw > 0.0)) {  // nothing moves nor weighs: any spring will do
    c.k = 1.0;
    c.reason = "no impact speed and no weight: k = 1 N/m";
  } else {
    const double scale = std::pow(10.0, std::floor(std::log10(raw)) - 1.0);
    c.k = std::ceil(raw / scale * (1.0 - 1e-12)) * scale;  // up to two significant digits
    c.reason = fmt::format(
        "auto: the softest k for overlaps <= {} d (contact.max_overlap): impact at {:.3g} m/s "
        "needs {:.3g} N/m, the sediment's buoyant weight ({:.3g} Pa on the floor, its force "
        "chains 4 times the mean load) {:.3g} N/m",
        f, c.impact_speed, k_impact, p, k_static);
  }
  c.impact_overlap = std::sqrt(k_impact / c.k) * f;  // overlap scales as 1/sqrt(k)
  c.static_overlap = k_static / c.k * f;             // and as 1/k
  return c;
}

}  // namespace sphdem
