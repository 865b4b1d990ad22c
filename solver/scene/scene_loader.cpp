// Scene files: strict YAML reading (unknown keys, wrong types and out-of-range values
// are errors naming the file, the key and what is allowed; every problem of a file is
// reported at once, scene/scene_problems.hpp), --set overrides, and the resolved scene
// written back as YAML.
#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <optional>
#include <set>
#include <sstream>

#include "coupling/hindered_settling.hpp"
#include "scene/contact_stiffness_rule.hpp"
#include "scene/did_you_mean.hpp"
#include "scene/fidelity.hpp"
#include "scene/kernel_width_rule.hpp"
#include "scene/map_reader.hpp"
#include "scene/scene.hpp"
#include "scene/scene_limits.hpp"
#include "scene/scene_problems.hpp"
#include "scene/sound_speed_rule.hpp"

namespace sphdem {

int Scene::species_index(const std::string& n) const {
  for (std::size_t s = 0; s < species.size(); ++s)
    if (species[s].name == n) return static_cast<int>(s);
  return -1;
}

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
const std::vector<std::string> kPipelineNames = {"voidage_height", "interfaces", "com_tracks",
                                                 "snapshots"};

std::vector<std::string> species_names(const Scene& sc) {
  std::vector<std::string> names;
  for (const auto& s : sc.species) names.push_back(s.name);
  return names;
}

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

// Fractions that must sum to 1 (number fractions of a mixture, list-law fractions).
void check_sum_to_one(MapReader& r, const std::string& k, const std::vector<double>& f) {
  double sum = 0.0;
  for (double x : f) sum += x;
  if (std::abs(sum - 1.0) > 1e-6) r.fail(r.key(k), fmt::format("must sum to 1 (got {})", sum));
}

// A species name a group or key refers to: one listed under 'species' (a misspelling
// gets a did-you-mean). False when it is not.
bool known_species(MapReader& r, const Scene& sc, const std::string& key, const std::string& name) {
  if (sc.species_index(name) >= 0) return true;
  r.fail(key, fmt::format("'{}' is not a species listed under 'species'{}", name,
                          did_you_mean(name, species_names(sc))));
  return false;
}

// particles.N.species of a random group: one name, or a list of names with their number
// fractions in particles.N.fractions (optional for one name). False when the species are
// not known (the group's checks that need them are skipped).
bool read_mixture(MapReader& r, const Scene& sc, ParticleGroupSpec& g) {
  const YAML::Node n = r.child("species");
  if (!n) {
    r.fail(r.key("species"), "is required: a species name or a list of names");
    return false;
  }
  if (n.IsScalar()) {
    g.mixture = {n.Scalar()};
  } else if (n.IsSequence() && n.size() > 0) {
    for (std::size_t i = 0; i < n.size(); ++i) {
      if (!n[i].IsScalar()) {
        r.fail(fmt::format("{}.{}", r.key("species"), i), "must be a species name");
        return false;
      }
      g.mixture.push_back(n[i].Scalar());
    }
  } else {
    r.fail(r.key("species"), "must be a species name or a non-empty list of names");
    return false;
  }
  bool ok = true;
  for (std::size_t i = 0; i < g.mixture.size(); ++i) {
    const std::string k =
        n.IsScalar() ? r.key("species") : fmt::format("{}.{}", r.key("species"), i);
    ok = known_species(r, sc, k, g.mixture[i]) && ok;
    for (std::size_t j = 0; j < i; ++j)
      if (g.mixture[j] == g.mixture[i]) {
        r.fail(k, fmt::format("'{}' is listed twice", g.mixture[i]));
        ok = false;
        break;
      }
  }
  g.species = g.mixture.front();
  if (g.mixture.size() > 1 && !r.has("fractions"))
    r.fail(r.key("fractions"),
           "is required with a list of species: one number fraction per species, summing to 1");
  if (r.has("fractions")) {
    if (const auto f = r.numbers("fractions", 0.0, 1.0, true)) {
      g.fractions = *f;
      if (g.fractions.size() != g.mixture.size())
        r.fail(r.key("fractions"),
               fmt::format("must have one entry per species ({} species, {} fractions)",
                           g.mixture.size(), g.fractions.size()));
      check_sum_to_one(r, "fractions", g.fractions);
    }
  }
  if (g.mixture.size() == 1) g.fractions = {1.0};  // what case.yaml implies when it writes one name
  return ok;
}

// species.N.size_distribution: one of the laws of size_distribution.hpp. Only the keys
// of the chosen law are allowed. Nothing when the law or one of its values is bad.
std::optional<SizeDistribution> read_size_distribution(const YAML::Node& node,
                                                       const std::string& path,
                                                       SceneProblems& problems) {
  MapReader r(node, path, problems);
  SizeDistribution L;
  if (!r.has("law")) {
    r.fail(r.key("law"), "is required: one of list, uniform, normal, lognormal");
    r.finish(false);  // which keys apply depends on the law
    return std::nullopt;
  }
  const std::optional<std::string> law_given =
      r.choice("law", "", {"list", "uniform", "normal", "lognormal"});
  if (!law_given) {
    r.finish(false);
    return std::nullopt;
  }
  const std::string& law = *law_given;
  auto bounds = [&] {
    L.min = r.required("min", 0.0, kInf, true);
    L.max = r.required("max", 0.0, kInf, true);
    if (r.clean() && L.max <= L.min)
      r.fail(r.key("max"), fmt::format("must be > min = {} (got {})", L.min, L.max));
  };
  if (law == "list") {
    L.law = SizeLaw::kList;
    const auto diameters = r.numbers("diameters", 0.0, kInf, true);
    if (!r.has("fractions"))
      r.fail(r.key("fractions"), "is required: one fraction per diameter, summing to 1");
    else if (const auto fractions = r.numbers("fractions", 0.0, 1.0, true)) {
      L.fractions = *fractions;
      if (diameters && L.fractions.size() != diameters->size())
        r.fail(r.key("fractions"),
               fmt::format("must have one entry per diameter ({} diameters, {} fractions)",
                           diameters->size(), L.fractions.size()));
      check_sum_to_one(r, "fractions", L.fractions);
    }
    if (diameters) {
      L.diameters = *diameters;
      std::vector<double> sorted = L.diameters;
      std::sort(sorted.begin(), sorted.end());
      for (std::size_t i = 1; i < sorted.size(); ++i)
        if (sorted[i] == sorted[i - 1]) {
          r.fail(r.key("diameters"),
                 fmt::format("each diameter may appear once ({} is given twice)", sorted[i]));
          break;
        }
      L.min = sorted.front();
      L.max = sorted.back();
    }
    if (!r.has("basis"))
      r.fail(r.key("basis"), "is required: number or volume (what the fractions count)");
    else
      L.by_volume =
          r.choice("basis", "", {"number", "volume"}) == std::optional<std::string>("volume");
  } else if (law == "uniform") {
    L.law = SizeLaw::kUniform;
    bounds();
  } else {
    const bool normal = law == "normal";
    L.law = normal ? SizeLaw::kNormal : SizeLaw::kLognormal;
    if (normal) {
      L.mean = r.required("mean", 0.0, kInf, true);
      L.std = r.required("std", 0.0, kInf, true);
    } else {
      L.median = r.required("median", 0.0, kInf, true);
      L.sigma_ln = r.required("sigma_ln", 0.0, kInf, true);
    }
    bounds();
    const double kept = r.clean() ? truncation_mass(L) : 1.0;
    if (!(kept >= 1e-3))
      r.fail(
          r.key("min"),
          fmt::format("the truncation [min, max] = [{}, {}] keeps only {:.3g} % of the {} law; "
                      "it must keep at least 0.1 % (check {}, min and max)",
                      L.min, L.max, 100.0 * kept, law, normal ? "mean, std" : "median, sigma_ln"));
  }
  const bool ok = r.clean();
  r.finish();
  return ok ? std::optional<SizeDistribution>(L) : std::nullopt;
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
  if (std::abs(ny - std::round(ny)) > 1e-6)
    why = fmt::format("{} m does not divide the width {} m", dx, sc.box.length(1));
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

Scene parse(const YAML::Node& root, SceneProblems& problems) {
  Scene sc;
  sc.source = problems.file();
  bool kernel_auto = true, drag_kernel_given = false, stiffness_auto = true;
  MapReader top(root, "", problems);
  top.expect({"name", "description", "domain", "gravity", "fluid", "species", "particles",
              "contact", "drag", "coupling", "time", "startup", "output", "checkpoint", "watchdog",
              "insitu", "fidelity"});
  sc.name = top.text("name", "scene");
  sc.description = top.text("description", "");
  // the preset's values are the defaults of the keys it names (scene/fidelity.hpp)
  sc.fidelity =
      top.choice("fidelity", "balanced", {"fast", "balanced", "accurate"}).value_or("balanced");
  const FidelityPreset& preset = *find_fidelity_preset(sc.fidelity);
  sc.fluid.resolution = preset.resolution;
  sc.fluid.sound_speed_factor = preset.sound_speed_factor;
  sc.time.cfl = preset.cfl;
  sc.time.dem_steps_per_contact = preset.dem_steps_per_contact;
  sc.contact.max_overlap = preset.max_overlap;
  bool resolution_given = false;

  // Checks against the box run only on a box the file gave without a problem (a default
  // box in place of a bad one would give problems the file does not have).
  bool box_ok = true;
  {
    MapReader r(top.child("domain"), "domain", problems);
    const auto size = r.vec3("size", {0.004, 0.004, 0.006});
    box_ok = r.clean();
    if (box_ok && !(size[0] > 0 && size[1] > 0 && size[2] > 0)) {
      r.fail("domain.size", "all three lengths must be > 0 (m)");
      box_ok = false;
    }
    sc.box.lo = {0, 0, 0};
    sc.box.hi = box_ok ? size : std::array<double, 3>{0.004, 0.004, 0.006};
    sc.box.periodic = {true, true, false};
    r.finish();
  }
  sc.gravity = top.vec3("gravity", {0, 0, -9.81});

  {
    MapReader r(top.child("fluid"), "fluid", problems);
    FluidSpec& f = sc.fluid;
    f.enabled = r.boolean("enabled", f.enabled);
    f.density = r.number("density", f.density, 0, kInf, true);
    f.viscosity = r.number("viscosity", f.viscosity, 0, kInf, true);
    f.spacing = r.number("spacing", f.spacing, 0, kInf, true);
    f.smoothing_factor = r.number("smoothing_factor", f.smoothing_factor, 1.0, 3.0);
    const bool lattice_ok = r.clean();  // spacing and smoothing_factor
    f.fill_height = r.number("fill_height", 0.0, 0.0, box_ok ? sc.box.length(2) : kInf);
    f.expected_speed = r.number("expected_speed", 0.0, 0.0, kInf);
    f.sound_speed = r.number("sound_speed", 0.0, 0.0, kInf);
    f.sound_speed_factor = r.number("sound_speed_factor", f.sound_speed_factor, 5.0, 100.0);
    resolution_given = r.has("resolution");
    f.resolution = r.number("resolution", f.resolution, 0.25, 4.0);
    f.alpha_artificial = r.number("alpha_artificial", f.alpha_artificial, 0.0, 2.0);
    f.density_diffusion = r.number("density_diffusion", f.density_diffusion, 0.0, 1.0);
    f.gamma = r.integer("gamma", f.gamma, 1, 7);
    const int min_layers = static_cast<int>(std::ceil(2.0 * f.smoothing_factor - 1e-9));
    f.wall_layers = r.integer("wall_layers", std::max(3, min_layers), min_layers, 8);
    const bool fill_ok = r.clean();
    r.finish();
    for (int d = 0; d < 2 && f.enabled && box_ok && lattice_ok; ++d) {  // no fluid: nothing to fit
      const double halo = kernel_reach_with_margin(f.lattice_h());
      if (sc.box.length(d) < 2.0 * halo) {
        r.fail("domain.size", fmt::format("the periodic width {} m must be >= 4.8 smoothing_factor "
                                          "spacing = {} m (twice the kernel support with margin)",
                                          sc.box.length(d), 2.0 * halo));
        break;
      }
      const double n = sc.box.length(d) / f.spacing;
      if (std::abs(n - std::round(n)) > 1e-6) {
        r.fail("fluid.spacing",
               fmt::format("must divide the periodic width {} m into a whole number "
                           "of layers (got {} layers)",
                           sc.box.length(d), n));
        break;
      }
    }
    if (f.enabled && box_ok && fill_ok && sc.fill_height() < 3 * f.spacing)
      r.fail("fluid.fill_height", "must hold at least 3 fluid layers");
  }

  // Species with a problem are kept (so that groups naming them find them) but marked:
  // the checks that need their sizes are skipped.
  std::vector<bool> species_ok;
  {
    const YAML::Node list = top.child("species");
    if (list && !list.IsSequence())
      top.fail("species", "must be a list of {name, diameter, density}");
    for (std::size_t s = 0; list && list.IsSequence() && s < list.size(); ++s) {
      MapReader r(list[s], fmt::format("species.{}", s), problems);
      SpeciesSpec sp;
      sp.name = r.text("name", "");
      if (sp.name.empty() || sp.name.find_first_of(":, ") != std::string::npos)
        r.fail(r.key("name"), "must be a non-empty name without ':', ',' or spaces");
      else if (sc.species_index(sp.name) >= 0)
        r.fail(r.key("name"), "duplicate species name '" + sp.name + "'");
      const bool one_size = r.has("diameter"), law = r.has("size_distribution");
      if (one_size && law) {
        r.fail(r.key("size_distribution"),
               "give either 'diameter' (one size) or 'size_distribution', not both");
      } else if (law) {
        const auto size = read_size_distribution(r.child("size_distribution"),
                                                 r.key("size_distribution"), problems);
        if (size) {
          sp.size = *size;
          sp.diameter = sauter_mean(sp.size);
        }
      } else if (!one_size) {
        r.fail(r.key("diameter"), "is required: a number in (0, inf], or give 'size_distribution'");
      } else {
        sp.diameter = r.required("diameter", 0.0, kInf, true);
        sp.size.min = sp.size.max = sp.diameter;
      }
      sp.density = r.required("density", 0.0, kInf, true);
      species_ok.push_back(r.clean());
      r.finish();
      sc.species.push_back(sp);
    }
  }

  {
    const YAML::Node list = top.child("particles");
    if (list && !list.IsSequence()) top.fail("particles", "must be a list of particle groups");
    for (std::size_t gi = 0; list && list.IsSequence() && gi < list.size(); ++gi) {
      MapReader r(list[gi], fmt::format("particles.{}", gi), problems);
      ParticleGroupSpec g;
      const std::optional<std::string> type_given =
          r.choice("type", "single", {"single", "lattice", "random"});
      if (!type_given) {  // which keys apply depends on the type
        r.finish(false);
        continue;
      }
      const std::string& type = *type_given;
      g.kind = type == "single"    ? ParticleGroupSpec::Kind::kSingle
               : type == "lattice" ? ParticleGroupSpec::Kind::kLattice
                                   : ParticleGroupSpec::Kind::kRandom;
      // the group's species, known and read without a problem: their sizes can be checked
      bool species_known = false;
      if (g.kind == ParticleGroupSpec::Kind::kRandom) {
        species_known = read_mixture(r, sc, g);
      } else if (g.kind == ParticleGroupSpec::Kind::kLattice && r.has("species") &&
                 r.child("species").IsSequence()) {
        // a mixed lattice (bidisperse block, thesis §4.6): species dealt to the sites by quota,
        // shuffled
        species_known = read_mixture(r, sc, g);
        for (std::size_t i = 0; species_known && i < g.mixture.size(); ++i)
          if (!sc.species[sc.species_index(g.mixture[i])].monodisperse())
            r.fail(fmt::format("{}.{}", r.key("species"), i),
                   fmt::format("species '{}' has a size_distribution; a lattice needs species with "
                               "one diameter",
                               g.mixture[i]));
      } else {
        g.species = r.text("species", "");
        species_known = known_species(r, sc, r.key("species"), g.species);
        if (species_known && !sc.species[sc.species_index(g.species)].monodisperse())
          r.fail(r.key("species"),
                 fmt::format("species '{}' has a size_distribution; a {} group needs a species "
                             "with one diameter (type random takes a size law)",
                             g.species, type));
      }
      for (const std::string& name :
           g.mixture.empty() ? std::vector<std::string>{g.species} : g.mixture)
        species_known = species_known && species_ok[sc.species_index(name)];
      const double radius =
          species_known ? 0.5 * sc.species[sc.species_index(g.species)].diameter : 0.0;
      g.velocity = r.vec3("velocity", {0, 0, 0});
      g.velocity_jitter = r.number("velocity_jitter", 0.0, 0.0, kInf);
      g.velocity_seed = r.whole64("velocity_seed", 1, 0, std::numeric_limits<std::int64_t>::max());
      g.rigid = r.boolean("rigid", false);
      if (g.kind == ParticleGroupSpec::Kind::kLattice)
        g.fcc = r.choice("lattice", "simple_cubic", {"simple_cubic", "fcc"}) ==
                std::optional<std::string>("fcc");
      if (g.kind == ParticleGroupSpec::Kind::kSingle) {
        const std::size_t before = problems.count();
        g.position =
            r.vec3("position", {0.5 * sc.box.hi[0], 0.5 * sc.box.hi[1], 0.5 * sc.box.hi[2]});
        if (box_ok && problems.count() == before) {
          bool inside = true;
          for (int d = 0; d < 3; ++d)
            inside = inside && g.position[d] >= sc.box.lo[d] && g.position[d] <= sc.box.hi[d];
          if (!inside)
            r.fail(r.key("position"), "must lie inside domain.size");
          else if (g.position[2] < radius)
            r.fail(r.key("position"), "the sphere would cut the bottom wall (z < radius)");
        }
      } else {
        const std::size_t before = problems.count();
        g.lo = r.vec3("min", sc.box.lo);
        g.hi = r.vec3("max", sc.box.hi);
        bool below = false, above = false, empty = false;
        for (int d = 0; d < 3; ++d) {
          below = below || g.lo[d] < sc.box.lo[d];
          above = above || g.hi[d] > sc.box.hi[d];
          empty = empty || g.hi[d] <= g.lo[d];
        }
        if (box_ok && problems.count() == before) {
          if (below)
            r.fail(r.key("min"), "region must satisfy 0 <= min < max <= domain.size (min < 0)");
          if (above)
            r.fail(r.key("max"),
                   "region must satisfy 0 <= min < max <= domain.size (max > domain.size)");
          if (empty)
            r.fail(r.key("max"), "region must satisfy 0 <= min < max <= domain.size (max <= min)");
        }
        if (g.kind == ParticleGroupSpec::Kind::kLattice) {
          // the closest packing of the lattice: simple cubic 1 - pi/6, fcc 1 - pi/(3 sqrt 2)
          const double densest = g.fcc ? 1.0 - M_PI / (3.0 * std::sqrt(2.0)) : 1.0 - M_PI / 6.0;
          g.voidage = r.number("voidage", g.voidage, densest, 1.0, false, true);
          if (g.mixture.size() > 1)
            g.seed = r.whole64("seed", 0, 0, std::numeric_limits<std::int64_t>::max());
        } else {
          // 1 - 0.64: no random packing is denser than random close packing. Random
          // sequential addition stops far earlier (random_packing.hpp) and says so.
          g.voidage = r.number("voidage", g.voidage, 0.36, 1.0, false, true);
          g.seed = r.whole64("seed", 0, 0, std::numeric_limits<std::int64_t>::max());
        }
      }
      r.finish();
      sc.particles.push_back(g);
    }
  }

  {
    MapReader r(top.child("contact"), "contact", problems);
    r.choice("model", "linear_spring_dashpot", {"linear_spring_dashpot"});
    LinearSpringDashpot& n = sc.contact.normal;
    // a number, or auto (the default): resolved below once the fluid and drag are known
    stiffness_auto = !r.has("stiffness") ||
                     (r.child("stiffness").IsScalar() && r.child("stiffness").Scalar() == "auto");
    if (!stiffness_auto) n.k = r.number("stiffness", n.k, 0.0, kInf, true);
    sc.contact.max_overlap = r.number("max_overlap", sc.contact.max_overlap, 0.0, 0.2, true);
    const bool has_damping = r.has("damping"), has_e = r.has("restitution");
    if (has_damping && has_e)
      r.fail("contact.restitution", "give either 'damping' (kg/s) or 'restitution', not both");
    n.beta = r.number("damping", 0.0, 0.0, kInf);
    n.restitution = has_e ? r.number("restitution", 1.0, 0.0, 1.0, true) : -1.0;
    n.clip_attraction = r.boolean("clip_attraction", false);
    sc.contact.skin = r.number("skin", sc.contact.skin, 0.0, 2.0);
    bool tangential_known = true;
    {
      // Keys other than 'model' exist only for a model that has them (unknown otherwise).
      MapReader t(r.child("tangential"), "contact.tangential", problems);
      TangentialParams& tp = sc.contact.tangential;
      const std::optional<std::string> model =
          t.choice("model", "none", {"none", "linear_history"});
      tp = TangentialParams{};
      tangential_known = model.has_value();
      if (model == std::optional<std::string>("linear_history")) {
        tp.model = TangentialParams::Model::kLinearHistory;
        tp.stiffness_ratio = t.number("stiffness_ratio", tp.stiffness_ratio, 0.0, 1.0, true);
        const bool has_gamma = t.has("damping"), has_et = t.has("restitution");
        if (has_gamma && has_et)
          t.fail("contact.tangential.restitution",
                 "give either 'damping' (kg/s) or 'restitution', not both");
        tp.damping = t.number("damping", 0.0, 0.0, kInf);
        tp.restitution = has_et ? t.number("restitution", 1.0, 0.0, 1.0, true) : -1.0;
        tp.friction = t.required("friction", 0.0, kInf);
      }
      t.finish(tangential_known);
    }
    {
      MapReader t(r.child("rolling"), "contact.rolling", problems);
      RollingParams& rp = sc.contact.rolling;
      const std::optional<std::string> model = t.choice("model", "none", {"none", "epsd"});
      rp = RollingParams{};
      if (model == std::optional<std::string>("epsd")) {
        rp.model = RollingParams::Model::kEpsd;
        rp.friction = t.required("friction", 0.0, 1.0);
        rp.damping_ratio = t.number("damping_ratio", rp.damping_ratio, 0.0, kInf);
        if (tangential_known && sc.contact.tangential.model == TangentialParams::Model::kNone)
          t.fail("contact.rolling.model",
                 "'epsd' needs tangential friction (contact.tangential.model: "
                 "linear_history); the registered combinations of tangential + "
                 "rolling are none + none, linear_history + none, linear_history + epsd");
      }
      t.finish(model.has_value());
    }
    r.finish();
  }
  {
    MapReader r(top.child("drag"), "drag", problems);
    std::vector<std::string> names;
    for (const drag::DragLawInfo& info : drag::kDragLaws) names.push_back(info.name);
    const std::string law = r.choice("law", "di_felice", names).value_or("di_felice");
    drag::drag_law_from_name(law, sc.drag);
    r.finish();
  }
  {
    MapReader r(top.child("coupling"), "coupling", problems);
    sc.voidage_floor = r.number("voidage_floor", sc.voidage_floor, 0.05, 0.95);
    const std::optional<std::string> sm =
        r.choice("voidage_smoothing", "single", {"single", "double"});
    sc.double_smoothing.enabled = sm == std::optional<std::string>("double");
    if (sc.double_smoothing.enabled) {
      sc.double_smoothing.h_over_d =
          r.number("big_h_over_d", sc.double_smoothing.h_over_d, 0.5, 5.0);
      if (r.has("big_species")) {
        const YAML::Node n = r.child("big_species");
        if (!n.IsSequence() || n.size() == 0)
          r.fail(r.key("big_species"), "must be a non-empty list of species names");
        for (std::size_t i = 0; n.IsSequence() && i < n.size(); ++i) {
          const std::string k = fmt::format("{}.{}", r.key("big_species"), i);
          if (!n[i].IsScalar())
            r.fail(k, "must be the name of a species listed under 'species'");
          else if (known_species(r, sc, k, n[i].Scalar()))
            sc.double_smoothing.big_species.push_back(n[i].Scalar());
        }
      } else {  // default: the species with the largest diameter
        std::size_t big = 0;
        for (std::size_t i = 1; i < sc.species.size(); ++i)
          if (sc.species[i].d_max() > sc.species[big].d_max()) big = i;
        if (!sc.species.empty()) sc.double_smoothing.big_species = {sc.species[big].name};
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
    const bool variational_applies = sc.fluid.enabled && !sc.double_smoothing.enabled;
    const std::optional<std::string> pc =
        r.choice("pressure_coupling", variational_applies ? "variational" : "interpolated",
                 {"interpolated", "variational"});
    sc.pressure_coupling = pc.value_or("interpolated") == "variational"
                               ? PressureCoupling::kVariational
                               : PressureCoupling::kInterpolated;
    if (sm && sc.pressure_coupling == PressureCoupling::kVariational && sc.double_smoothing.enabled)
      r.fail(r.key("pressure_coupling"),
             "variational needs voidage_smoothing: single (the gradient of the "
             "double-smoothed voidage is not implemented); use interpolated");
    // default: on wherever it applies (the variational coupling under gravity along -z)
    const bool split_applies = sc.pressure_coupling == PressureCoupling::kVariational &&
                               sc.gravity[0] == 0.0 && sc.gravity[1] == 0.0 && sc.gravity[2] < 0.0;
    sc.hydrostatic_split = r.boolean("hydrostatic_split", split_applies);
    if (pc && sc.hydrostatic_split && sc.pressure_coupling != PressureCoupling::kVariational)
      r.fail(r.key("hydrostatic_split"), "true needs pressure_coupling: variational");
    else if (sc.hydrostatic_split &&
             (sc.gravity[0] != 0.0 || sc.gravity[1] != 0.0 || sc.gravity[2] >= 0.0))
      r.fail(r.key("hydrostatic_split"),
             "true needs gravity along -z (gravity: [0, 0, g] with g < 0)");
    // a number, or auto (the default): resolved below once c0 is known
    kernel_auto =
        !r.has("sphere_kernel_scale") || (r.child("sphere_kernel_scale").IsScalar() &&
                                          r.child("sphere_kernel_scale").Scalar() == "auto");
    if (!kernel_auto) sc.sphere_kernel_scale = r.number("sphere_kernel_scale", 1.0, 1.0, 3.0);
    drag_kernel_given = r.has("drag_kernel_scale");
    if (drag_kernel_given) sc.drag_kernel_scale = r.number("drag_kernel_scale", 1.0, 1.0, 3.0);
    r.finish();
  }
  {
    MapReader r(top.child("time"), "time", problems);
    sc.time.end = r.number("end", sc.time.end, 0.0, kInf, true);
    sc.time.cfl = r.number("cfl", sc.time.cfl, 0.0, 1.0, true);
    sc.time.dem_steps_per_contact =
        r.number("dem_steps_per_contact", sc.time.dem_steps_per_contact, 5.0, 1000.0);
    sc.time.multirate = r.boolean("multirate", sc.time.multirate);
    sc.time.multirate_margin = r.number("multirate_margin", sc.time.multirate_margin, 0.0, 100.0);
    sc.time.max_dt_sph = r.number("max_dt_sph", sc.time.max_dt_sph, 0.0, kInf, true);
    r.finish();
  }
  {
    MapReader r(top.child("startup"), "startup", problems);
    sc.startup.relax_steps = r.integer("relax_steps", sc.startup.relax_steps, 0, 1000000);
    sc.startup.damping = r.number("damping", sc.startup.damping, 0.0, 1.0, false, true);
    r.finish();
  }
  {
    MapReader r(top.child("output"), "output", problems);
    sc.output.log_interval = r.number("log_interval", 0.0, 0.0, kInf);
    sc.output.progress_interval =
        r.number("progress_interval", sc.output.progress_interval, 0.0, kInf);
    {
      MapReader v(r.child("vtk"), "output.vtk", problems);
      sc.output.vtk_every = v.number("every", 0.0, 0.0, kInf);
      v.finish();
    }
    r.finish();
  }
  {
    MapReader r(top.child("checkpoint"), "checkpoint", problems);
    CheckpointSpec& c = sc.checkpoint;
    c.every = r.number("every", c.every, 0.0, kInf);
    c.wall_interval = r.number("wall_interval", c.wall_interval, 0.0, kInf);
    c.keep = r.integer("keep", c.keep, 1, 1000);
    c.at_end = r.boolean("at_end", c.at_end);
    r.finish();
  }
  {
    MapReader r(top.child("watchdog"), "watchdog", problems);
    WatchdogSpec& w = sc.watchdog;
    w.enabled = r.boolean("enabled", w.enabled);
    w.density_error = r.number("density_error", w.density_error, 0.0, kInf, true);
    w.overlap = r.number("overlap", w.overlap, 0.0, kInf, true);
    w.safeguard_share = r.number("safeguard_share", w.safeguard_share, 0.0, 1.0);
    r.finish();
  }
  {
    MapReader r(top.child("insitu"), "insitu", problems);
    InSituSpec& in = sc.insitu;
    in.enabled = r.boolean("enabled", in.enabled);
    in.every = r.number("every", 0.0, 0.0, kInf);
    if (r.has("pipelines")) {
      const YAML::Node list = r.child("pipelines");
      if (!list.IsSequence()) r.fail("insitu.pipelines", "must be a list of pipeline names");
      std::vector<std::string> names;
      for (std::size_t k = 0; list.IsSequence() && k < list.size(); ++k) {
        const std::string name = list[k].IsScalar() ? list[k].Scalar() : "";
        if (std::find(kPipelineNames.begin(), kPipelineNames.end(), name) == kPipelineNames.end())
          r.fail(fmt::format("insitu.pipelines.{}", k),
                 fmt::format("must be one of: {} (got '{}'){}", fmt::join(kPipelineNames, ", "),
                             name, did_you_mean(name, kPipelineNames)));
        names.push_back(name);
      }
      if (list.IsSequence()) in.pipelines = names;
    }
    in.snapshot_every = r.integer("snapshot_every", in.snapshot_every, 1, 1000000);
    in.grid_spacing = r.number("grid_spacing", 0.0, 0.0, kInf);
    in.reference_velocity = r.number("reference_velocity", in.reference_velocity, -1.0, kInf);
    r.finish();
  }
  top.finish();
  // The values below are resolved from the ones above: only from a scene without problems.
  problems.throw_if_any();

  // Resolve the automatic values, so case.yaml records what actually ran.
  const double g = sc.gravity_magnitude();
  if (sc.fluid.fill_height <= 0) sc.fluid.fill_height = sc.box.length(2);
  if (sc.fluid.expected_speed <= 0) {
    double u = 0.0;
    for (const auto& s : sc.species) {  // the drag law's terminal speed in clear fluid
      const double v =
          terminal_speed(sc.drag, s.d_max(), s.density, sc.fluid.density, sc.fluid.viscosity, g);
      u = std::max(u, std::isfinite(v) ? v : stokes_speed(s, sc.fluid, g));
    }
    sc.fluid.expected_speed = u;
  }
  if (sc.fluid.resolution != 1.0) resolve_resolution(sc, resolution_given, problems);
  if (sc.fluid.sound_speed <= 0) {  // f max(u_m, sqrt(2 g H)), and the buoyancy bound
    const double um = std::max(sc.fluid.expected_speed, std::sqrt(2.0 * g * sc.fill_height()));
    sc.fluid.sound_speed =
        std::max(sc.fluid.sound_speed_factor * std::max(um, 1e-6), buoyancy_sound_speed(sc));
  }
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
  resolve_sphere_kernel(sc, kernel_auto, drag_kernel_given, problems);
  problems.throw_if_any();
  if (stiffness_auto) {
    const StiffnessChoice c = choose_contact_stiffness(sc);
    sc.contact.normal.k = c.k;
    sc.contact.stiffness_reason = c.reason;
    finite("contact.stiffness", c.k,
           "contact.max_overlap, the species, the groups' speeds, gravity and the fluid");
  }
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
  auto vec = [&](const std::array<double, 3>& v) {
    e << YAML::Flow << YAML::BeginSeq << v[0] << v[1] << v[2] << YAML::EndSeq;
  };
  e << YAML::BeginMap;
  e << YAML::Key << "name" << YAML::Value << sc.name;
  e << YAML::Key << "description" << YAML::Value << sc.description;
  e << YAML::Key << "fidelity" << YAML::Value << sc.fidelity;
  e << YAML::Key << "domain" << YAML::Value << YAML::BeginMap << YAML::Key << "size" << YAML::Value;
  vec(sc.box.hi);
  e << YAML::EndMap;
  e << YAML::Key << "gravity" << YAML::Value;
  vec(sc.gravity);
  const FluidSpec& f = sc.fluid;
  e << YAML::Key << "fluid" << YAML::Value << YAML::BeginMap;
  e << YAML::Key << "density" << YAML::Value << f.density << YAML::Key << "viscosity" << YAML::Value
    << f.viscosity;
  e << YAML::Key << "spacing" << YAML::Value << f.spacing << YAML::Key << "smoothing_factor"
    << YAML::Value << f.smoothing_factor;
  e << YAML::Key << "fill_height" << YAML::Value << f.fill_height << YAML::Key << "expected_speed"
    << YAML::Value << f.expected_speed;
  e << YAML::Key << "sound_speed" << YAML::Value << f.sound_speed << YAML::Key
    << "sound_speed_factor" << YAML::Value << f.sound_speed_factor << YAML::Key << "resolution"
    << YAML::Value << f.resolution << YAML::Key << "alpha_artificial" << YAML::Value
    << f.alpha_artificial << YAML::Key << "density_diffusion" << YAML::Value << f.density_diffusion;
  e << YAML::Key << "gamma" << YAML::Value << f.gamma << YAML::Key << "wall_layers" << YAML::Value
    << f.wall_layers;
  e << YAML::Key << "enabled" << YAML::Value << f.enabled;
  e << YAML::EndMap;
  e << YAML::Key << "species" << YAML::Value << YAML::BeginSeq;
  for (const auto& s : sc.species) {
    e << YAML::Flow << YAML::BeginMap << YAML::Key << "name" << YAML::Value << s.name;
    if (s.monodisperse()) {
      e << YAML::Key << "diameter" << YAML::Value << s.diameter;
    } else {
      const SizeDistribution& L = s.size;
      e << YAML::Key << "size_distribution" << YAML::Value << YAML::BeginMap << YAML::Key << "law"
        << YAML::Value << size_law_name(L.law);
      switch (L.law) {
        case SizeLaw::kList:
          e << YAML::Key << "diameters" << YAML::Value << YAML::Flow << L.diameters << YAML::Key
            << "fractions" << YAML::Value << YAML::Flow << L.fractions << YAML::Key << "basis"
            << YAML::Value << (L.by_volume ? "volume" : "number");
          break;
        case SizeLaw::kNormal:
          e << YAML::Key << "mean" << YAML::Value << L.mean << YAML::Key << "std" << YAML::Value
            << L.std;
          break;
        case SizeLaw::kLognormal:
          e << YAML::Key << "median" << YAML::Value << L.median << YAML::Key << "sigma_ln"
            << YAML::Value << L.sigma_ln;
          break;
        default:
          break;
      }
      if (L.law != SizeLaw::kList)
        e << YAML::Key << "min" << YAML::Value << L.min << YAML::Key << "max" << YAML::Value
          << L.max;
      e << YAML::EndMap;
    }
    e << YAML::Key << "density" << YAML::Value << s.density << YAML::EndMap;
  }
  e << YAML::EndSeq;
  e << YAML::Key << "particles" << YAML::Value << YAML::BeginSeq;
  for (const auto& g : sc.particles) {
    e << YAML::BeginMap;
    const bool single = g.kind == ParticleGroupSpec::Kind::kSingle;
    const bool random = g.kind == ParticleGroupSpec::Kind::kRandom;
    e << YAML::Key << "type" << YAML::Value << (single ? "single" : random ? "random" : "lattice");
    if (g.mixture.size() > 1) {
      e << YAML::Key << "species" << YAML::Value << YAML::Flow << g.mixture;
      e << YAML::Key << "fractions" << YAML::Value << YAML::Flow << g.fractions;
    } else {
      e << YAML::Key << "species" << YAML::Value << g.species;
    }
    if (single) {
      e << YAML::Key << "position" << YAML::Value;
      vec(g.position);
    } else {
      e << YAML::Key << "min" << YAML::Value;
      vec(g.lo);
      e << YAML::Key << "max" << YAML::Value;
      vec(g.hi);
      e << YAML::Key << "voidage" << YAML::Value << g.voidage;
      if (!random) e << YAML::Key << "lattice" << YAML::Value << (g.fcc ? "fcc" : "simple_cubic");
      if (random || g.mixture.size() > 1) e << YAML::Key << "seed" << YAML::Value << g.seed;
    }
    e << YAML::Key << "velocity" << YAML::Value;
    vec(g.velocity);
    e << YAML::Key << "velocity_jitter" << YAML::Value << g.velocity_jitter << YAML::Key
      << "velocity_seed" << YAML::Value << g.velocity_seed;
    e << YAML::Key << "rigid" << YAML::Value << g.rigid << YAML::EndMap;
  }
  e << YAML::EndSeq;
  const LinearSpringDashpot& n = sc.contact.normal;
  e << YAML::Key << "contact" << YAML::Value << YAML::BeginMap << YAML::Key << "model"
    << YAML::Value << "linear_spring_dashpot" << YAML::Key << "stiffness" << YAML::Value << n.k;
  if (n.restitution > 0)
    e << YAML::Key << "restitution" << YAML::Value << n.restitution;
  else
    e << YAML::Key << "damping" << YAML::Value << n.beta;
  e << YAML::Key << "clip_attraction" << YAML::Value << n.clip_attraction << YAML::Key << "skin"
    << YAML::Value << sc.contact.skin << YAML::Key << "max_overlap" << YAML::Value
    << sc.contact.max_overlap;
  const TangentialParams& tp = sc.contact.tangential;
  e << YAML::Key << "tangential" << YAML::Value << YAML::BeginMap;
  if (tp.model == TangentialParams::Model::kNone) {
    e << YAML::Key << "model" << YAML::Value << "none";
  } else {
    e << YAML::Key << "model" << YAML::Value << "linear_history" << YAML::Key << "stiffness_ratio"
      << YAML::Value << tp.stiffness_ratio;
    if (tp.restitution > 0)
      e << YAML::Key << "restitution" << YAML::Value << tp.restitution;
    else
      e << YAML::Key << "damping" << YAML::Value << tp.damping;
    e << YAML::Key << "friction" << YAML::Value << tp.friction;
  }
  e << YAML::EndMap;
  const RollingParams& rp = sc.contact.rolling;
  e << YAML::Key << "rolling" << YAML::Value << YAML::BeginMap;
  if (rp.model == RollingParams::Model::kNone) {
    e << YAML::Key << "model" << YAML::Value << "none";
  } else {
    e << YAML::Key << "model" << YAML::Value << "epsd" << YAML::Key << "friction" << YAML::Value
      << rp.friction << YAML::Key << "damping_ratio" << YAML::Value << rp.damping_ratio;
  }
  e << YAML::EndMap << YAML::EndMap;
  e << YAML::Key << "drag" << YAML::Value << YAML::BeginMap << YAML::Key << "law" << YAML::Value
    << drag::drag_law_name(sc.drag) << YAML::EndMap;
  e << YAML::Key << "coupling" << YAML::Value << YAML::BeginMap << YAML::Key << "voidage_floor"
    << YAML::Value << sc.voidage_floor << YAML::Key << "voidage_smoothing" << YAML::Value
    << (sc.double_smoothing.enabled ? "double" : "single") << YAML::Key << "pressure_coupling"
    << YAML::Value
    << (sc.pressure_coupling == PressureCoupling::kVariational ? "variational" : "interpolated")
    << YAML::Key << "hydrostatic_split" << YAML::Value << sc.hydrostatic_split << YAML::Key
    << "sphere_kernel_scale" << YAML::Value << sc.sphere_kernel_scale << YAML::Key
    << "drag_kernel_scale" << YAML::Value << sc.drag_kernel_scale;
  if (sc.double_smoothing.enabled)
    e << YAML::Key << "big_species" << YAML::Value << YAML::Flow << sc.double_smoothing.big_species
      << YAML::Key << "big_h_over_d" << YAML::Value << sc.double_smoothing.h_over_d;
  e << YAML::EndMap;
  e << YAML::Key << "time" << YAML::Value << YAML::BeginMap << YAML::Key << "end" << YAML::Value
    << sc.time.end << YAML::Key << "cfl" << YAML::Value << sc.time.cfl << YAML::Key
    << "dem_steps_per_contact" << YAML::Value << sc.time.dem_steps_per_contact << YAML::Key
    << "multirate" << YAML::Value << sc.time.multirate << YAML::Key << "multirate_margin"
    << YAML::Value << sc.time.multirate_margin << YAML::Key << "max_dt_sph" << YAML::Value
    << sc.time.max_dt_sph << YAML::EndMap;
  e << YAML::Key << "startup" << YAML::Value << YAML::BeginMap << YAML::Key << "relax_steps"
    << YAML::Value << sc.startup.relax_steps << YAML::Key << "damping" << YAML::Value
    << sc.startup.damping << YAML::EndMap;
  e << YAML::Key << "output" << YAML::Value << YAML::BeginMap << YAML::Key << "log_interval"
    << YAML::Value << sc.output.log_interval << YAML::Key << "progress_interval" << YAML::Value
    << sc.output.progress_interval << YAML::Key << "vtk" << YAML::Value << YAML::BeginMap
    << YAML::Key << "every" << YAML::Value << sc.output.vtk_every << YAML::EndMap << YAML::EndMap;
  const CheckpointSpec& c = sc.checkpoint;
  e << YAML::Key << "checkpoint" << YAML::Value << YAML::BeginMap << YAML::Key << "every"
    << YAML::Value << c.every << YAML::Key << "wall_interval" << YAML::Value << c.wall_interval
    << YAML::Key << "keep" << YAML::Value << c.keep << YAML::Key << "at_end" << YAML::Value
    << c.at_end << YAML::EndMap;
  const WatchdogSpec& w = sc.watchdog;
  e << YAML::Key << "watchdog" << YAML::Value << YAML::BeginMap << YAML::Key << "enabled"
    << YAML::Value << w.enabled << YAML::Key << "density_error" << YAML::Value << w.density_error
    << YAML::Key << "overlap" << YAML::Value << w.overlap << YAML::Key << "safeguard_share"
    << YAML::Value << w.safeguard_share << YAML::EndMap;
  const InSituSpec& in = sc.insitu;
  e << YAML::Key << "insitu" << YAML::Value << YAML::BeginMap << YAML::Key << "enabled"
    << YAML::Value << in.enabled << YAML::Key << "every" << YAML::Value << in.every << YAML::Key
    << "pipelines" << YAML::Value << YAML::Flow << in.pipelines << YAML::Key << "snapshot_every"
    << YAML::Value << in.snapshot_every << YAML::Key << "grid_spacing" << YAML::Value
    << in.grid_spacing << YAML::Key << "reference_velocity" << YAML::Value << in.reference_velocity
    << YAML::EndMap;
  e << YAML::EndMap;
  return std::string(e.c_str()) + "\n";
}

}  // namespace sphdem
