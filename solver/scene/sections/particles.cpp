// The particles section: groups of spheres (one sphere, a lattice block, a random
// suspension) and their species, region and initial velocity.
#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <optional>

#include "scene/sections/sections.hpp"

namespace sphdem {

namespace {

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
    if (const auto f = r.numbers("fractions")) {
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

ParticleGroupSpec::Kind group_kind(const std::string& type) {
  return type == "single"    ? ParticleGroupSpec::Kind::kSingle
         : type == "lattice" ? ParticleGroupSpec::Kind::kLattice
                             : ParticleGroupSpec::Kind::kRandom;
}

}  // namespace

void read_particles(MapReader& top, Scene& sc, ReadContext& cx) {
  const YAML::Node list = top.child("particles");
  if (list && !list.IsSequence()) top.fail("particles", "must be a list of particle groups");
  for (std::size_t gi = 0; list && list.IsSequence() && gi < list.size(); ++gi) {
    MapReader r(list[gi], fmt::format("particles.{}", gi), cx.problems);
    ParticleGroupSpec g;
    const std::optional<std::string> type_given = r.choice("type");
    if (!type_given) {  // which keys apply depends on the type
      r.finish(false);
      continue;
    }
    const std::string& type = *type_given;
    g.kind = group_kind(type);
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
      g.species = r.text("species");
      species_known = known_species(r, sc, r.key("species"), g.species);
      if (species_known && !sc.species[sc.species_index(g.species)].monodisperse())
        r.fail(r.key("species"),
               fmt::format("species '{}' has a size_distribution; a {} group needs a species "
                           "with one diameter (type random takes a size law)",
                           g.species, type));
    }
    for (const std::string& name :
         g.mixture.empty() ? std::vector<std::string>{g.species} : g.mixture)
      species_known = species_known && cx.species_ok[sc.species_index(name)];
    const double radius =
        species_known ? 0.5 * sc.species[sc.species_index(g.species)].diameter : 0.0;
    g.velocity = r.vec3("velocity");
    g.velocity_jitter = r.number("velocity_jitter");
    g.velocity_seed = r.whole64("velocity_seed");
    g.fixed = r.boolean("fixed");
    if (g.fixed && (g.velocity != std::array<double, 3>{0, 0, 0} || g.velocity_jitter > 0))
      r.fail(r.key("fixed"),
             "a fixed group never moves: its velocity and velocity_jitter must be 0");
    g.rigid = r.boolean("rigid") || g.fixed;
    if (g.kind == ParticleGroupSpec::Kind::kLattice)
      g.fcc = r.choice("lattice") == std::optional<std::string>("fcc");
    if (g.kind == ParticleGroupSpec::Kind::kSingle) {
      const std::size_t before = cx.problems.count();
      g.position = r.vec3("position", {0.5 * sc.box.hi[0], 0.5 * sc.box.hi[1], 0.5 * sc.box.hi[2]});
      if (cx.box_ok && cx.problems.count() == before) {
        bool inside = true;
        for (int d = 0; d < 3; ++d)
          inside = inside && g.position[d] >= sc.box.lo[d] && g.position[d] <= sc.box.hi[d];
        if (!inside)
          r.fail(r.key("position"), "must lie inside domain.size");
        else if (g.position[2] < radius)
          r.fail(r.key("position"), "the sphere would cut the bottom wall (z < radius)");
      }
    } else {
      const std::size_t before = cx.problems.count();
      g.lo = r.vec3("min", sc.box.lo);
      g.hi = r.vec3("max", sc.box.hi);
      bool below = false, above = false, empty = false;
      for (int d = 0; d < 3; ++d) {
        below = below || g.lo[d] < sc.box.lo[d];
        above = above || g.hi[d] > sc.box.hi[d];
        empty = empty || g.hi[d] <= g.lo[d];
      }
      if (cx.box_ok && cx.problems.count() == before) {
        if (below)
          r.fail(r.key("min"), "region must satisfy 0 <= min < max <= domain.size (min < 0)");
        if (above)
          r.fail(r.key("max"),
                 "region must satisfy 0 <= min < max <= domain.size (max > domain.size)");
        if (empty)
          r.fail(r.key("max"), "region must satisfy 0 <= min < max <= domain.size (max <= min)");
      }
      // the densest packing: simple cubic 1 - pi/6, fcc 1 - pi/(3 sqrt 2); a random
      // packing no denser than random close packing, 1 - 0.64 (its placement stops
      // earlier, random_packing.hpp, and says so)
      const double densest = g.kind == ParticleGroupSpec::Kind::kRandom ? 0.36
                             : g.fcc ? 1.0 - M_PI / (3.0 * std::sqrt(2.0))
                                     : 1.0 - M_PI / 6.0;
      g.voidage = r.number_within("voidage", scene_default("particles.N.voidage"), densest, 1.0);
      if (g.kind == ParticleGroupSpec::Kind::kRandom || g.mixture.size() > 1)
        g.seed = r.whole64("seed");
    }
    r.finish();
    sc.particles.push_back(g);
  }
}

void write_particles(YAML::Emitter& e, const Scene& sc) {
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
      emit_vec3(e, g.position);
    } else {
      e << YAML::Key << "min" << YAML::Value;
      emit_vec3(e, g.lo);
      e << YAML::Key << "max" << YAML::Value;
      emit_vec3(e, g.hi);
      e << YAML::Key << "voidage" << YAML::Value << g.voidage;
      if (!random) e << YAML::Key << "lattice" << YAML::Value << (g.fcc ? "fcc" : "simple_cubic");
      if (random || g.mixture.size() > 1) e << YAML::Key << "seed" << YAML::Value << g.seed;
    }
    e << YAML::Key << "velocity" << YAML::Value;
    emit_vec3(e, g.velocity);
    e << YAML::Key << "velocity_jitter" << YAML::Value << g.velocity_jitter << YAML::Key
      << "velocity_seed" << YAML::Value << g.velocity_seed;
    e << YAML::Key << "rigid" << YAML::Value << g.rigid << YAML::Key << "fixed" << YAML::Value
      << g.fixed << YAML::EndMap;
  }
  e << YAML::EndSeq;
}

}  // namespace sphdem
