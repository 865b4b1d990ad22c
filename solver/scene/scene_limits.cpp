#include "scene/scene_limits.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "coupling/drag_law_table.hpp"
#include "scene/contact_stiffness_rule.hpp"
#include "scene/kernel_width_rule.hpp"
#include "scene/sound_speed_rule.hpp"
#include "sph/kernel.hpp"

namespace sphdem {

namespace {
constexpr double kWeaklyCompressibleLimit = 0.01;
constexpr double kOverlapLimit = 0.1;  // of d
}  // namespace

namespace {

// The couplings a scene's spheres cannot run with: a drag law without a voidage function
// among spheres closer than a lone one's (its drag would not rise with concentration,
// 2.73/2.75 against 2.76), no drag on spheres free to move (nothing couples them), and the
// double smoothing over spheres that can settle into a bed (it forces the interpolated
// coupling, linearly unstable over a packed bed: packed_bed_stability_validation).
void append_coupling_breaches(const Scene& sc, std::vector<LimitBreach>& out) {
  const drag::DragLawInfo& law = drag::drag_law_info(sc.drag);
  const bool no_drag = std::holds_alternative<drag::NoDrag>(sc.drag);
  for (std::size_t k = 0; k < sc.particles.size(); ++k) {
    const ParticleGroupSpec& g = sc.particles[k];
    const double eps = g.kind == ParticleGroupSpec::Kind::kSingle ? 1.0 : g.voidage;
    if (!law.voidage_function && !no_drag && eps < kLoneSphereVoidage) {
      std::vector<std::string> valid;
      for (const drag::DragLawInfo& other : drag::kDragLaws)
        if (other.voidage_function) valid.push_back(other.name);
      out.push_back(
          {"drag.law",
           fmt::format("particles.{} sits at voidage {} but {} ({}) has no voidage function: "
                       "its drag is a lone sphere's at any concentration, so the group would "
                       "settle as fast as one sphere; allowed: {} only where every group's "
                       "voidage is >= {} (single spheres); choose one of {}",
                       k, eps, law.name, law.equations, law.name, kLoneSphereVoidage,
                       fmt::join(valid, ", "))});
    }
    if (no_drag && !g.rigid)  // (the loader makes a fixed group rigid)
      out.push_back(
          {"drag.law", fmt::format("particles.{} is free to move but drag.law none couples no "
                                   "sphere to the fluid (a measuring device for fixed beds); "
                                   "allowed: none only when every group is rigid or fixed; "
                                   "choose a drag law, or set particles.{}.fixed",
                                   k, k)});
  }
  const bool mobile = std::any_of(sc.particles.begin(), sc.particles.end(),
                                  [](const ParticleGroupSpec& g) { return !g.rigid; });
  if (sc.double_smoothing.enabled && mobile && sc.gravity_magnitude() > 0.0)
    out.push_back(
        {"coupling.voidage_smoothing",
         "double smoothing forces the interpolated pressure coupling, which is linearly "
         "unstable over the packed bed that mobile spheres settle into (the fluid's kinetic "
         "energy grows without bound there: packed_bed_stability_validation); allowed: double "
         "only when every particles group is rigid or fixed (constant-porosity blocks); use "
         "single"});
}

}  // namespace

double sphere_kernel_share(double d, double h) {
  return M_PI / 6.0 * d * d * d * kernel::w(0.0, h);
}

std::vector<LimitBreach> scene_limit_breaches(const Scene& sc) {
  std::vector<LimitBreach> out;
  const double g = sc.gravity_magnitude();
  const FluidSpec& fl = sc.fluid;
  for (std::size_t k = 0; k < sc.species.size(); ++k) {
    const SpeciesSpec& sp = sc.species[k];
    const std::string key = fmt::format("species.{}", k);
    // double smoothing (3.8-3.10) spreads a big sphere over its own kernel and then the
    // fluid's: about one kernel of the two widths in quadrature
    const DoubleSmoothingSpec& ds = sc.double_smoothing;
    const bool big = ds.enabled && std::find(ds.big_species.begin(), ds.big_species.end(),
                                             sp.name) != ds.big_species.end();
    const double d = sp.d_max();
    const double h = std::hypot(sc.drag_kernel_scale * fl.lattice_h(), big ? ds.h_over_d * d : 0.0);
    const double self = sphere_kernel_share(d, h);
    if (fl.enabled && self > kSelfVoidageLimit)
      out.push_back(
          {"fluid.spacing",
           fmt::format("species '{}': a sphere of d = {} m fills {:.3g} of its drag kernel "
                       "(V W(0), h = {:.3g} m, d/h = {:.3g}), so its drag is that of a suspension "
                       "at voidage {:.3g}, not of a lone sphere; allowed: V W(0) <= {} "
                       "(d/h <= {:.3g}); raise fluid.spacing to >= {:.3g} m",
                       sp.name, d, self, h, d / h, 1.0 - self, kSelfVoidageLimit,
                       d / h * std::cbrt(kSelfVoidageLimit / self),
                       fl.spacing * std::cbrt(self / kSelfVoidageLimit))});
    if (!fl.enabled) continue;
    if (g > 0.0 && sp.density < fl.density)
      out.push_back({key + ".density",
                     fmt::format("species '{}' ({} kg/m^3) is lighter than the fluid ({} kg/m^3): "
                                 "it would rise through the free surface, above which there is "
                                 "no fluid; allowed: density >= fluid.density",
                                 sp.name, sp.density, fl.density)});
    const drag::DragLawInfo& law = drag::drag_law_info(sc.drag);
    if (std::isfinite(law.reynolds_max) && g > 0.0) {
      const double d = sp.d_max();
      const double v = terminal_speed(sc.drag, d, sp.density, fl.density, fl.viscosity, g);
      const double re = fl.density * v * d / fl.viscosity;
      if (re > law.reynolds_max) {
        std::vector<std::string> valid;
        for (const drag::DragLawInfo& other : drag::kDragLaws)
          if (other.reynolds_max >= re && other.voidage_function) valid.push_back(other.name);
        out.push_back(
            {"drag.law",
             fmt::format("species '{}' settles at a terminal Reynolds number {:.3g} by {} "
                         "({}), valid to Re = {}; choose a law valid at this Re ({})",
                         sp.name, re, law.name, law.equations, law.reynolds_max,
                         fmt::join(valid, ", "))});
      }
    }
  }
  if (fl.enabled) append_coupling_breaches(sc, out);
  if (fl.enabled) {
    const SoundSpeedReport c = sound_speed_report(sc);
    if (c.expected_density_error() > kWeaklyCompressibleLimit * (1.0 + 1e-9))
      out.push_back(
          {"fluid.sound_speed",
           fmt::format("c0 = {} m/s gives an expected density error of {:.2g} % (Mach {:.3g}, "
                       "g H/c0^2 = {:.2g} %), past the weakly compressible limit of 1 %; raise "
                       "fluid.sound_speed to >= {:.3g} m/s (or 0 for the automatic c0)",
                       c.c0, 100 * c.expected_density_error(), c.mach, 100 * c.hydrostatic,
                       c.c0 * std::sqrt(c.expected_density_error() / kWeaklyCompressibleLimit))});
    if (c.buoyancy > kBuoyancyErrorLimit * (1.0 + 1e-9))
      out.push_back(
          {"fluid.sound_speed",
           fmt::format("c0 = {} m/s compresses the fluid at the base by g H/c0^2 = {:.2g} %, which "
                       "buoys the lightest species {:.2g} % more than its buoyant weight "
                       "(rho_p - rho_f) g V: its settling speed would be that much too slow, "
                       "past the limit of {} %; raise fluid.sound_speed to >= {:.3g} m/s (or 0 "
                       "for the automatic c0)",
                       c.c0, 100 * c.hydrostatic, 100 * c.buoyancy, 100 * kBuoyancyErrorLimit,
                       buoyancy_sound_speed(sc, kBuoyancyErrorLimit))});
  }
  // (blocks moving rigidly, thesis 4.5, have no contacts to bound)
  const bool all_rigid = std::all_of(sc.particles.begin(), sc.particles.end(),
                                     [](const ParticleGroupSpec& g) { return g.rigid; });
  if (!sc.species.empty() && sc.contact.normal.k > 0.0 && !all_rigid) {
    const ExpectedOverlaps o = expected_overlaps(sc);
    const double impact = o.impact, at_rest = o.at_rest, worst = o.worst();
    if (worst > kOverlapLimit) {
      // overlaps scale as k^-1/2 at impact and k^-1 at rest
      const double k_needed =
          sc.contact.normal.k *
          std::max((impact / kOverlapLimit) * (impact / kOverlapLimit), at_rest / kOverlapLimit);
      out.push_back(
          {"contact.stiffness",
           fmt::format("k = {} N/m lets spheres overlap by {:.2g} d ({}), past the soft-sphere "
                       "limit of {} d; raise contact.stiffness to >= {:.2g} N/m, or auto",
                       sc.contact.normal.k, worst, impact >= at_rest ? "at impact" : "at rest",
                       kOverlapLimit, k_needed)});
    }
  }
  return out;
}

std::string describe_breaches(const Scene& sc, const std::vector<LimitBreach>& breaches) {
  std::string s;
  for (const LimitBreach& b : breaches)
    s += fmt::format("{}: key '{}': {}\n", sc.source, b.key, b.message);
  return s;
}

void refuse_scene_past_limits(const Scene& sc) {
  const std::vector<LimitBreach> b = scene_limit_breaches(sc);
  if (b.empty()) return;
  std::string s = describe_breaches(sc, b);
  s.pop_back();
  throw SceneError(fmt::format("the scene is past the model's limits ({}):\n{}", b.size(), s));
}

}  // namespace sphdem
