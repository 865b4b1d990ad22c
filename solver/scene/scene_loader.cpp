// Scene files: strict YAML reading (unknown keys, wrong types and out-of-range values
// are errors naming the file, the key and what is allowed; every problem of a file is
// reported at once, scene/scene_problems.hpp), --set overrides, and the resolved scene
// written back as YAML.
#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <optional>
#include <sstream>

#include "coupling/hindered_settling.hpp"
#include "scene/contact_stiffness_rule.hpp"
#include "scene/kernel_width_rule.hpp"
#include "scene/map_reader.hpp"
#include "scene/scene.hpp"
#include "scene/scene_limits.hpp"
#include "scene/scene_problems.hpp"
#include "scene/sections/sections.hpp"
#include "scene/sound_speed_rule.hpp"

namespace sphdem {

int Scene::species_index(const std::string& n) const {
  for (std::size_t s = 0; s < species.size(); ++s)
    if (species[s].name == n) return static_cast<int>(s);
  return -1;
}

namespace {

// A list index of a --set path: digits only (std::stoul would take "-1" and "1x").
std::optional<std::size_t> list_index(const std::string& part) {
  if (part.empty() || part.size() > 9 ||
      !std::all_of(part.begin(), part.end(), [](char c) { return c >= '0' && c <= '9'; }))
    return std::nullopt;
  return std::stoul(part);
}

// One --set key.path=value into the YAML tree; a bad assignment is a problem and is skipped.
void apply_override(YAML::Node root, const std::string& assignment, SceneProblems& problems) {
  auto fail = [&](const std::string& what) {
    problems.add_line(fmt::format("{}: --set '{}': {}", problems.file(), assignment, what));
  };
  const auto eq = assignment.find('=');
  if (eq == std::string::npos || eq == 0) return fail("expected key.path=value");
  const std::string path = assignment.substr(0, eq);
  YAML::Node value;
  try {
    value = YAML::Load(assignment.substr(eq + 1));
  } catch (const YAML::Exception& e) {
    return fail(fmt::format("value is not valid YAML ({})", e.what()));
  }
  std::vector<std::string> parts;
  std::stringstream ss(path);
  for (std::string p; std::getline(ss, p, '.');) parts.push_back(p);
  if (path.back() == '.' || std::find(parts.begin(), parts.end(), "") != parts.end())
    return fail("the key path has an empty part");
  YAML::Node node = root;
  for (std::size_t k = 0; k < parts.size(); ++k) {
    const bool last = k + 1 == parts.size();
    if (node.IsScalar())
      return fail(fmt::format("'{}' holds a value, not a map of keys",
                              fmt::join(parts.begin(), parts.begin() + k, ".")));
    if (node.IsSequence()) {
      const std::optional<std::size_t> idx = list_index(parts[k]);
      if (!idx || *idx >= node.size())
        return fail(fmt::format("'{}' must be an index in [0, {})", parts[k], node.size()));
      if (last)
        node[*idx] = value;
      else
        node.reset(node[*idx]);
    } else {
      if (last)
        node[parts[k]] = value;
      else {
        if (!node[parts[k]]) node[parts[k]] = YAML::Node(YAML::NodeType::Map);
        node.reset(node[parts[k]]);
      }
    }
  }
  problems.override_applied(path, assignment);
}

// The largest Stokes speed of a species: that of its largest sphere.
double stokes_speed(const SpeciesSpec& s, const FluidSpec& f, double g) {
  return std::abs(s.density - f.density) * g * s.d_max() * s.d_max() / (18.0 * f.viscosity);
}

// coupling.sphere_kernel_scale (auto: scene/kernel_width_rule.hpp) and drag_kernel_scale,
// then what the periodic width must hold: the spheres' halo reaches 2 H, with margin.
void resolve_sphere_kernel(Scene& sc, bool kernel_auto, bool drag_kernel_given,
                           SceneProblems& problems) {
  auto fail = [&](const std::string& key, const std::string& what) {
    problems.add("coupling." + key, what);
  };
  if (kernel_auto) {
    const KernelWidthChoice c = choose_sphere_kernel_width(sc);
    sc.sphere_kernel_scale = c.scale;
    sc.sphere_kernel_reason = "auto: " + c.reason;
    if (!drag_kernel_given) sc.drag_kernel_scale = c.drag_scale;
  } else if (!drag_kernel_given) {
    sc.drag_kernel_scale = sc.sphere_kernel_scale;
  }
  if (sc.drag_kernel_scale > sc.sphere_kernel_scale)
    fail("drag_kernel_scale", fmt::format("must be in [1, sphere_kernel_scale = {}] (got {})",
                                          sc.sphere_kernel_scale, sc.drag_kernel_scale));
  const double reach = kernel_reach_with_margin(sc.sphere_kernel_scale * sc.fluid.lattice_h());
  for (int d = 0; d < 2 && sc.fluid.enabled; ++d)
    if (sc.box.length(d) < reach) {
      fail("sphere_kernel_scale",
           fmt::format("{} needs a periodic width >= 2.4 sphere_kernel_scale smoothing_factor "
                       "spacing = {} m (the spheres' kernel support with margin); domain.size "
                       "gives {} m",
                       sc.sphere_kernel_scale, reach, sc.box.length(d)));
      break;
    }
}

// fluid.resolution (a preset's, or the scene's): dx = spacing / resolution, rounded to
// whole layers of the periodic widths. A preset's is dropped, with a note, where the box
// would not hold the kernel, the column fewer than 3 layers, or a sphere would fill more
// of its kernel than scene/scene_limits.hpp allows; the scene's own fails there instead.
void resolve_resolution(Scene& sc, bool given, SceneProblems& problems) {
  FluidSpec& f = sc.fluid;
  const double old_dx = f.spacing, res = f.resolution;
  f.resolution = 1.0;
  if (!f.enabled) return;
  const double dx = sc.box.length(0) / std::max(1.0, std::round(sc.box.length(0) * res / old_dx));
  const double h = f.smoothing_factor * dx;
  const double ny = sc.box.length(1) / dx, support = 2.0 * kernel_reach_with_margin(h);
  double d_max = 0.0;
  for (const SpeciesSpec& s : sc.species) d_max = std::max(d_max, s.d_max());
  std::string why;
  const double nz = sc.box.length(2) / dx;
  if (std::abs(ny - std::round(ny)) > 1e-6)
    why = fmt::format("{} m does not divide the width {} m", dx, sc.box.length(1));
  else if (sc.periodic_z() && std::abs(nz - std::round(nz)) > 1e-6)
    why = fmt::format("{} m does not divide the periodic height {} m", dx, sc.box.length(2));
  else if (std::min(sc.box.length(0), sc.box.length(1)) < support)
    why = fmt::format("the box is narrower than 4.8 smoothing_factor dx = {} m", support);
  else if (sc.fill_height() < 3 * dx)
    why = "the column would hold fewer than 3 layers";
  else if (sphere_kernel_share(d_max, h) > kSelfVoidageLimit)
    why = fmt::format("a {} m sphere would fill more than {} of its kernel", d_max,
                      kSelfVoidageLimit);
  if (why.empty()) {
    f.spacing = dx;
    sc.fidelity_note =
        fmt::format("fluid.spacing {} m -> {:.6g} m (resolution {})", old_dx, dx, res);
    return;
  }
  if (given)
    problems.add("fluid.resolution", fmt::format("{} gives dx = {:.6g} m, but {}", res, dx, why));
  else
    sc.fidelity_note = fmt::format("the preset's resolution {} not applied: {}", res, why);
}

// The bed's buoyant weight per area over rho_f g (Scene::bed_head): each group's solid
// volume, (1 - voidage) of its region or its one sphere, of the mobile groups.
double bed_head(const Scene& sc) {
  double head = 0.0;
  for (const ParticleGroupSpec& grp : sc.particles) {
    if (grp.fixed) continue;
    const SpeciesSpec& sp = sc.species[sc.species_index(grp.species)];
    double solid = M_PI * std::pow(sp.diameter, 3) / 6.0;
    if (grp.kind != ParticleGroupSpec::Kind::kSingle)
      solid = (1.0 - grp.voidage) * (grp.hi[0] - grp.lo[0]) * (grp.hi[1] - grp.lo[1]) *
              (grp.hi[2] - grp.lo[2]);
    head += solid * std::max(0.0, sp.density - sc.fluid.density);
  }
  return head / (sc.fluid.density * sc.box.length(0) * sc.box.length(1));
}

Scene parse(const YAML::Node& root, SceneProblems& problems) {
  Scene sc;
  sc.source = problems.file();
  MapReader top(root, "", problems);
  top.expect_table_keys();
  ReadContext cx{problems};
  read_top(top, sc, cx);
  read_fluid(top, sc, cx);
  read_species(top, sc, cx);
  read_particles(top, sc, cx);
  read_contact(top, sc, cx);
  read_coupling(top, sc, cx);
  read_flow(top, sc, cx);
  read_run_control(top, sc, cx);
  read_insitu(top, sc, cx);
  top.finish();
  // The values below are resolved from the ones above: only from a scene without problems.
  problems.throw_if_any();

  // Resolve the automatic values, so case.yaml records what actually ran.
  const double g = sc.gravity_magnitude();
  if (sc.periodic_z() && sc.flow.distributor) sc.bed_head = bed_head(sc);
  if (sc.fluid.fill_height <= 0) sc.fluid.fill_height = sc.box.length(2);
  if (sc.fluid.expected_speed <= 0) {
    double u = 0.0;
    for (const auto& s : sc.species) {  // the drag law's terminal speed in clear fluid
      const double v =
          terminal_speed(sc.drag, s.d_max(), s.density, sc.fluid.density, sc.fluid.viscosity, g);
      u = std::max(u, std::isfinite(v) ? v : stokes_speed(s, sc.fluid, g));
    }
    for (const double U : sc.flow.superficial_velocity) u = std::max(u, std::abs(U));
    sc.fluid.expected_speed = u;
  }
  if (sc.fluid.resolution != 1.0) resolve_resolution(sc, cx.resolution_given, problems);
  if (sc.fluid.sound_speed <= 0) sc.fluid.sound_speed = automatic_sound_speed(sc);
  // The automatic values come from the file's own, and extreme ones (a density of 1e300)
  // leave them infinite or NaN: no run can use that, and case.yaml cannot record it.
  auto finite = [&](const char* key, double v, const char* from) {
    if (!std::isfinite(v))
      problems.add(key, fmt::format("its automatic value is {} (from {}); give it, or bring those "
                                    "into a physical range",
                                    v, from));
    return std::isfinite(v);
  };
  if (finite("fluid.expected_speed", sc.fluid.expected_speed,
             "the species' diameters and densities, fluid.density, fluid.viscosity, gravity and "
             "drag.law"))
    finite("fluid.sound_speed", sc.fluid.sound_speed,
           "fluid.expected_speed, fluid.sound_speed_factor, gravity and the fill height");
  problems.throw_if_any();
  resolve_sphere_kernel(sc, cx.kernel_auto, cx.drag_kernel_given, problems);
  problems.throw_if_any();
  if (cx.stiffness_auto) {
    const StiffnessChoice c = choose_contact_stiffness(sc);
    sc.contact.normal.k = c.k;
    sc.contact.stiffness_reason = c.reason;
    finite("contact.stiffness", c.k,
           "contact.max_overlap, the species, the groups' speeds, gravity and the fluid");
  }
  if (cx.density_alarm_auto)
    sc.watchdog.density_error =
        std::clamp(kDensityAlarmFactor * sound_speed_report(sc).expected_density_error(),
                   kDensityAlarmFloor, kDensityAlarmFactor * kDensityAlarmFloor);
  if (sc.output.log_interval <= 0) sc.output.log_interval = sc.time.end / 200.0;
  if (sc.insitu.every <= 0) sc.insitu.every = sc.time.end / 50.0;
  if (sc.insitu.grid_spacing <= 0) sc.insitu.grid_spacing = sc.fluid.spacing;
  if (sc.insitu.reference_velocity ==
      0.0) {  // auto: hindered settling of the first block or suspension
    sc.insitu.reference_velocity = -1.0;
    for (const auto& grp : sc.particles) {
      if (grp.kind == ParticleGroupSpec::Kind::kSingle) continue;
      // The group's (first) species; for a size law, diameter is its Sauter mean d32.
      const SpeciesSpec& sp = sc.species[sc.species_index(grp.species)];
      sc.insitu.reference_velocity = di_felice_hindered_settling(
          sp.diameter, sp.density, sc.fluid.density, sc.fluid.viscosity, g, grp.voidage);
      break;
    }
    finite("insitu.reference_velocity", sc.insitu.reference_velocity,
           "the first block's or suspension's species and voidage, and the fluid");
  }
  problems.throw_if_any();
  return sc;
}

}  // namespace

Scene load_scene_text(const std::string& yaml, const std::string& source_name,
                      const std::vector<std::string>& overrides) {
  YAML::Node root;
  try {
    root = YAML::Load(yaml);
  } catch (const YAML::Exception& e) {
    throw SceneError(fmt::format("{}: not valid YAML: {}", source_name, e.what()));
  }
  if (!root || root.IsNull()) root = YAML::Node(YAML::NodeType::Map);
  SceneProblems problems(source_name);
  if (!root.IsMap()) problems.stop("", "must be a map of keys");  // nothing to read on
  for (const auto& o : overrides) apply_override(root, o, problems);
  return parse(root, problems);
}

Scene load_scene(const std::string& path, const std::vector<std::string>& overrides) {
  std::ifstream in(path);
  if (!in) throw SceneError(fmt::format("{}: cannot open the scene file", path));
  std::stringstream ss;
  ss << in.rdbuf();
  return load_scene_text(ss.str(), path, overrides);
}

std::string scene_to_yaml(const Scene& sc) {
  YAML::Emitter e;
  e.SetDoublePrecision(17);  // bit-exact reload of the resolved values
  e << YAML::BeginMap;
  write_top(e, sc);
  write_fluid(e, sc);
  write_species(e, sc);
  write_particles(e, sc);
  write_contact(e, sc);
  write_coupling(e, sc);
  write_flow(e, sc);
  write_run_control(e, sc);
  write_insitu(e, sc);
  e << YAML::EndMap;
  return std::string(e.c_str()) + "\n";
}

}  // namespace sphdem
