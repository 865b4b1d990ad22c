#include "scene/kernel_width_rule.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <variant>

namespace sphdem {

double settling_speed(const drag::DragLaw& law, double d, double rho_p, double rho_f, double mu,
                      double g, double eps) {
  if (std::holds_alternative<drag::NoDrag>(law)) return HUGE_VAL;  // nothing holds it back
  // the buoyant weight less the suspension's buoyancy, (rho_p - rho_av) V g (4.2-4.4)
  const double weight = eps * std::abs(rho_p - rho_f) * g * M_PI * d * d * d / 6.0;
  const drag::Fluid fluid{rho_f, mu};
  double lo = 0.0, hi = std::max(10.0 * weight / (3.0 * M_PI * mu * d), 1e-12);  // 10 x Stokes
  for (int k = 0; k < 200; ++k) {  // the drag grows with the slip
    const double v = 0.5 * (lo + hi);
    const double force =
        std::visit([&](const auto& l) { return l.coefficient(eps, v, d, fluid); }, law) * v;
    (force > weight ? hi : lo) = v;
  }
  return 0.5 * (lo + hi);
}

double terminal_speed(const drag::DragLaw& law, double d, double rho_p, double rho_f, double mu,
                      double g) {
  return settling_speed(law, d, rho_p, rho_f, mu, g, 1.0);
}

double extra_drag_ratio(const Scene& sc) {
  const double g = sc.gravity_magnitude();
  const FluidSpec& f = sc.fluid;
  if (!f.enabled || g <= 0.0) return 0.0;
  const double h = f.lattice_h(), h4 = h * h * h * h;
  double ratio = 0.0;
  for (const SpeciesSpec& s : sc.species) {
    const double d = s.d_max(), weight_density = std::abs(s.density - f.density);
    if (d <= 0.0 || weight_density <= 0.0) continue;
    const double v = terminal_speed(sc.drag, d, s.density, f.density, f.viscosity, g);
    const double volume = M_PI * d * d * d / 6.0;
    ratio = std::max(ratio, f.density * f.sound_speed * v * volume / (weight_density * g * h4));
  }
  return ratio;
}

KernelWidthChoice choose_sphere_kernel_width(const Scene& sc) {
  KernelWidthChoice c;
  if (sc.pressure_coupling != PressureCoupling::kVariational) {
    c.reason = "interpolated pressure coupling: the spheres' kernel at h";
    return c;
  }
  c.ratio = extra_drag_ratio(sc);
  c.scale = c.ratio <= 0.17 ? 1.0 : c.ratio <= 1.7 ? 1.25 : 1.5;
  c.reason = fmt::format(
      "variational pressure coupling, extra-drag ratio R = rho_f c0 v_T V / ((rho_p - rho_f) g "
      "h^4) = {:.3g}: {} (1 for R <= 0.17, 1.25 for R <= 1.7, else 1.5; bench/TRADEOFF.md)",
      c.ratio, c.scale == 1.0 ? "h" : fmt::format("{} h", c.scale));
  c.reason += "; the drag's fields at h";
  return c;
}

}  // namespace sphdem
