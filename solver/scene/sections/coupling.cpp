// The drag and coupling sections: the drag law, the voidage (floor, single or double
// smoothing) and how the fluid pressure acts on the spheres (pressure_coupling, the
// hydrostatic split, the spheres' and the drag's kernel widths).
#include <fmt/format.h>

#include <optional>

#include "scene/sections/sections.hpp"

namespace sphdem {

void read_coupling(MapReader& top, Scene& sc, ReadContext& cx) {
  {
    MapReader r(top.child("drag"), "drag", cx.problems);
    const std::string law = r.choice("law").value_or(std::string(scene_key("drag.law").text));
    drag::drag_law_from_name(law, sc.drag);
    r.finish();
  }
  MapReader r(top.child("coupling"), "coupling", cx.problems);
  sc.voidage_floor = r.number("voidage_floor");
  const std::optional<std::string> sm = r.choice("voidage_smoothing");
  DoubleSmoothingSpec& ds = sc.double_smoothing;
  ds.enabled = sm == std::optional<std::string>("double");
  if (ds.enabled) {
    ds.h_over_d = r.number("big_h_over_d");
    if (r.has("big_species")) {
      const YAML::Node n = r.child("big_species");
      if (!n.IsSequence() || n.size() == 0)
        r.fail(r.key("big_species"), "must be a non-empty list of species names");
      for (std::size_t i = 0; n.IsSequence() && i < n.size(); ++i) {
        const std::string k = fmt::format("{}.{}", r.key("big_species"), i);
        if (!n[i].IsScalar())
          r.fail(k, "must be the name of a species listed under 'species'");
        else if (known_species(r, sc, k, n[i].Scalar()))
          ds.big_species.push_back(n[i].Scalar());
      }
    } else {  // default: the species with the largest diameter
      std::size_t big = 0;
      for (std::size_t i = 1; i < sc.species.size(); ++i)
        if (sc.species[i].d_max() > sc.species[big].d_max()) big = i;
      if (!sc.species.empty()) ds.big_species = {sc.species[big].name};
    }
  } else if (sm) {  // (a bad voidage_smoothing leaves it open whether these apply)
    for (const char* k : {"big_species", "big_h_over_d"})
      if (r.has(k)) r.fail(r.key(k), "applies only with voidage_smoothing: double");
  } else {
    r.has("big_species");
    r.has("big_h_over_d");
  }
  // default: variational (conserves energy where the voidage varies), interpolated with
  // the double smoothing (whose voidage gradient the variational form lacks) or no fluid
  const bool variational_applies = sc.fluid.enabled && !ds.enabled;
  const std::optional<std::string> pc =
      r.choice("pressure_coupling", variational_applies ? "variational" : "interpolated");
  sc.pressure_coupling = pc.value_or("interpolated") == "variational"
                             ? PressureCoupling::kVariational
                             : PressureCoupling::kInterpolated;
  if (sm && sc.pressure_coupling == PressureCoupling::kVariational && ds.enabled)
    r.fail(r.key("pressure_coupling"),
           "variational needs voidage_smoothing: single (the gradient of the "
           "double-smoothed voidage is not implemented); use interpolated");
  // default: on wherever it applies (the variational coupling under gravity along -z)
  const bool along_minus_z = sc.gravity[0] == 0.0 && sc.gravity[1] == 0.0 && sc.gravity[2] < 0.0;
  const bool split_applies =
      sc.pressure_coupling == PressureCoupling::kVariational && along_minus_z && !sc.periodic_z();
  sc.hydrostatic_split = r.boolean("hydrostatic_split", split_applies);
  if (sc.hydrostatic_split && sc.periodic_z())  // no free surface to hang P_h from
    r.fail(r.key("hydrostatic_split"),
           "true needs a free surface; a column periodic in z (domain.periodic_z) has none, and "
           "its mean pressure gradient is the flow's body force");
  else if (pc && sc.hydrostatic_split && sc.pressure_coupling != PressureCoupling::kVariational)
    r.fail(r.key("hydrostatic_split"), "true needs pressure_coupling: variational");
  else if (sc.hydrostatic_split && !along_minus_z)
    r.fail(r.key("hydrostatic_split"),
           "true needs gravity along -z (gravity: [0, 0, g] with g < 0)");
  // a number, or auto (the default): resolved once c0 is known
  sc.sphere_kernel_scale = 1.0;
  cx.kernel_auto = r.number_or_auto("sphere_kernel_scale", sc.sphere_kernel_scale);
  cx.drag_kernel_given = r.has("drag_kernel_scale");
  sc.drag_kernel_scale = r.number("drag_kernel_scale");
  // default: on under gravity (the side it points to is the upstream half of the kernel)
  const bool gravity = sc.gravity[0] != 0.0 || sc.gravity[1] != 0.0 || sc.gravity[2] != 0.0;
  sc.drag_upstream = r.boolean("drag_upstream", gravity && sc.fluid.enabled);
  if (sc.drag_upstream && !gravity)
    r.fail(r.key("drag_upstream"),
           "true needs gravity (the side it points to is the upstream half)");
  // default: off; for a suspension settling onto the floor (a falling block's or cloud's
  // lower face would read the clear liquid under it: validation/README.md, session 45)
  sc.drag_voidage_upstream = r.boolean("drag_voidage_upstream", false);
  if (sc.drag_voidage_upstream && !along_minus_z)
    r.fail(r.key("drag_voidage_upstream"),
           "true needs gravity along -z (gravity: [0, 0, g] with g < 0)");
  else if (sc.drag_voidage_upstream && !sc.drag_upstream)
    r.fail(r.key("drag_voidage_upstream"),
           "true needs drag_upstream: true (the spheres read these fluid particles from below)");
  r.finish();
}

void write_coupling(YAML::Emitter& e, const Scene& sc) {
  e << YAML::Key << "drag" << YAML::Value << YAML::BeginMap << YAML::Key << "law" << YAML::Value
    << drag::drag_law_name(sc.drag) << YAML::EndMap;
  e << YAML::Key << "coupling" << YAML::Value << YAML::BeginMap << YAML::Key << "voidage_floor"
    << YAML::Value << sc.voidage_floor << YAML::Key << "voidage_smoothing" << YAML::Value
    << (sc.double_smoothing.enabled ? "double" : "single") << YAML::Key << "pressure_coupling"
    << YAML::Value
    << (sc.pressure_coupling == PressureCoupling::kVariational ? "variational" : "interpolated")
    << YAML::Key << "hydrostatic_split" << YAML::Value << sc.hydrostatic_split << YAML::Key
    << "sphere_kernel_scale" << YAML::Value << sc.sphere_kernel_scale << YAML::Key
    << "drag_kernel_scale" << YAML::Value << sc.drag_kernel_scale << YAML::Key << "drag_upstream"
    << YAML::Value << sc.drag_upstream << YAML::Key << "drag_voidage_upstream" << YAML::Value
    << sc.drag_voidage_upstream;
  if (sc.double_smoothing.enabled)
    e << YAML::Key << "big_species" << YAML::Value << YAML::Flow << sc.double_smoothing.big_species
      << YAML::Key << "big_h_over_d" << YAML::Value << sc.double_smoothing.h_over_d;
  e << YAML::EndMap;
}

}  // namespace sphdem
