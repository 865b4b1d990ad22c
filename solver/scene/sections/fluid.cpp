// The fluid section: the SPH fluid's material, lattice and numerical parameters.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "scene/sections/sections.hpp"

namespace sphdem {

void read_fluid(MapReader& top, Scene& sc, ReadContext& cx) {
  MapReader r(top.child("fluid"), "fluid", cx.problems);
  FluidSpec& f = sc.fluid;
  f.enabled = r.boolean("enabled");
  f.density = r.number("density");
  f.viscosity = r.number("viscosity");
  f.spacing = r.number("spacing");
  f.smoothing_factor = r.number("smoothing_factor");
  const bool lattice_ok = r.clean();  // spacing and smoothing_factor
  const bool fill_given = r.has("fill_height"), walls_given = r.has("wall_layers");
  f.fill_height = r.number_within("fill_height", scene_default("fluid.fill_height"), 0.0,
                                  cx.box_ok ? sc.box.length(2) : kInf);
  f.expected_speed = r.number("expected_speed");
  f.sound_speed = r.number("sound_speed");
  f.sound_speed_factor = r.number("sound_speed_factor", cx.preset->sound_speed_factor);
  cx.resolution_given = r.has("resolution");
  f.resolution = r.number("resolution", cx.preset->resolution);
  f.alpha_artificial = r.number("alpha_artificial");
  f.density_diffusion = r.number("density_diffusion");
  f.density_diffusion_form = r.choice("density_diffusion_form").value_or("auto");
  f.gamma = r.integer("gamma");
  const int min_layers = static_cast<int>(std::ceil(2.0 * f.smoothing_factor - 1e-9));
  f.wall_layers = r.integer("wall_layers", std::max(3, min_layers), min_layers);
  const bool fill_ok = r.clean();
  r.finish();
  if (sc.periodic_z()) {  // no wall, no free surface: the keys of either do not apply
    for (const auto& [given, key] :
         {std::pair{fill_given, "fluid.fill_height"}, std::pair{walls_given, "fluid.wall_layers"}})
      if (given)
        r.fail(key,
               "a column periodic in z (domain.periodic_z: true) has no wall and no free "
               "surface; leave this key out");
  }
  const int periodic_axes = sc.periodic_z() ? 3 : 2;
  for (int d = 0; d < periodic_axes && f.enabled && cx.box_ok && lattice_ok;
       ++d) {  // no fluid: nothing to fit
    const double halo = kernel_reach_with_margin(f.lattice_h());
    if (sc.box.length(d) < 2.0 * halo) {
      r.fail("domain.size", fmt::format("the periodic width {} m must be >= 4.8 smoothing_factor "
                                        "spacing = {} m (twice the kernel support with margin)",
                                        sc.box.length(d), 2.0 * halo));
      break;
    }
    const double n = sc.box.length(d) / f.spacing;
    if (std::abs(n - std::round(n)) > 1e-6) {
      r.fail("fluid.spacing", fmt::format("must divide the periodic width {} m into a whole number "
                                          "of layers (got {} layers)",
                                          sc.box.length(d), n));
      break;
    }
  }
  if (f.enabled && cx.box_ok && fill_ok && sc.fill_height() < 3 * f.spacing)
    r.fail("fluid.fill_height", "must hold at least 3 fluid layers");
}

void write_fluid(YAML::Emitter& e, const Scene& sc) {
  const FluidSpec& f = sc.fluid;
  e << YAML::Key << "fluid" << YAML::Value << YAML::BeginMap;
  e << YAML::Key << "density" << YAML::Value << f.density << YAML::Key << "viscosity" << YAML::Value
    << f.viscosity;
  e << YAML::Key << "spacing" << YAML::Value << f.spacing << YAML::Key << "smoothing_factor"
    << YAML::Value << f.smoothing_factor;
  if (!sc.periodic_z()) e << YAML::Key << "fill_height" << YAML::Value << f.fill_height;
  e << YAML::Key << "expected_speed" << YAML::Value << f.expected_speed;
  e << YAML::Key << "sound_speed" << YAML::Value << f.sound_speed << YAML::Key
    << "sound_speed_factor" << YAML::Value << f.sound_speed_factor << YAML::Key << "resolution"
    << YAML::Value << f.resolution << YAML::Key << "alpha_artificial" << YAML::Value
    << f.alpha_artificial << YAML::Key << "density_diffusion" << YAML::Value << f.density_diffusion;
  e << YAML::Key << "density_diffusion_form" << YAML::Value << f.density_diffusion_form;
  e << YAML::Key << "gamma" << YAML::Value << f.gamma;
  if (!sc.periodic_z()) e << YAML::Key << "wall_layers" << YAML::Value << f.wall_layers;
  e << YAML::Key << "enabled" << YAML::Value << f.enabled;
  e << YAML::EndMap;
}

}  // namespace sphdem
