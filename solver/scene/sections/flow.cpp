// The flow section: U(t) of a column periodic in z (domain.periodic_z), a piecewise linear
// schedule the flow controller follows (propagator/flow_controller.hpp).
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <utility>

#include "scene/kernel_width_rule.hpp"
#include "scene/sections/sections.hpp"

namespace sphdem {

namespace {

// The spheres' extent along z per group: [low, high] of their centres' reach.
std::pair<double, double> group_extent_z(const Scene& sc, const ParticleGroupSpec& g) {
  double d = 0.0;  // the largest diameter of the group's species (unknown ones add none)
  for (const auto& name : g.mixture.empty() ? std::vector<std::string>{g.species} : g.mixture)
    if (const int k = sc.species_index(name); k >= 0) d = std::max(d, sc.species[k].d_max());
  if (g.kind == ParticleGroupSpec::Kind::kSingle)
    return {g.position[2] - 0.5 * d, g.position[2] + 0.5 * d};
  return {g.lo[2], g.hi[2]};
}

// The distributor and the top plane against the groups, and U against the terminal speeds.
void check_planes(MapReader& r, const Scene& sc) {
  const FlowSpec& f = sc.flow;
  const double Lz = sc.box.length(2);
  double d_max = 0.0;
  for (const SpeciesSpec& sp : sc.species) d_max = std::max(d_max, sp.d_max());
  for (std::size_t k = 0; k < sc.particles.size(); ++k) {
    const auto [low, high] = group_extent_z(sc, sc.particles[k]);
    if (f.distributor && (low < sc.box.lo[2] || high >= sc.box.hi[2] - 1e-12 * Lz))
      r.fail(fmt::format("particles.{}.max", k),
             fmt::format("the group spans z {} to {} m, across the distributor at z = 0 (the "
                         "periodic face); a bed on it lies within [0, Lz) and below the top",
                         low, high));
    if (f.top_plane > 0.0 && high > f.top_plane)
      r.fail("flow.top_plane", fmt::format("must be above every group: particles.{} reaches z = "
                                           "{} m, the plane is at {} m",
                                           k, high, f.top_plane));
  }
  if (f.top_plane > 0.0 && f.top_plane > Lz - d_max)
    r.fail("flow.top_plane",
           fmt::format("must be at most Lz - the largest diameter = {} m (spheres held there "
                       "would touch the bed's across the periodic face), got {} m",
                       Lz - d_max, f.top_plane));
  if (f.top_plane > 0.0) return;
  double u_max = 0.0;
  for (const double U : f.superficial_velocity) u_max = std::max(u_max, U);
  const double g = sc.gravity_magnitude();
  std::vector<char> mobile(sc.species.size(), 0);  // species of a group that can move
  for (const ParticleGroupSpec& grp : sc.particles)
    if (!grp.fixed)
      for (const std::string& name :
           grp.mixture.empty() ? std::vector<std::string>{grp.species} : grp.mixture)
        if (const int k = sc.species_index(name); k >= 0) mobile[k] = 1;
  for (std::size_t k = 0; k < sc.species.size(); ++k) {
    const SpeciesSpec& sp = sc.species[k];
    if (!mobile[k]) continue;
    const double u_t =
        terminal_speed(sc.drag, sp.d_min(), sp.density, sc.fluid.density, sc.fluid.viscosity, g);
    if (std::isfinite(u_t) && u_max > u_t) {
      r.fail("flow.superficial_velocity",
             fmt::format("U reaches {} m/s, past the terminal speed {:.4g} m/s of species '{}' "
                         "(its smallest spheres, drag.law): the flow would carry them round the "
                         "periodic column; set flow.top_plane to hold them",
                         u_max, u_t, sp.name));
      return;
    }
  }
}

}  // namespace

void read_flow(MapReader& top, Scene& sc, ReadContext& cx) {
  MapReader r(top.child("flow"), "flow", cx.problems);
  FlowSpec& f = sc.flow;
  const bool given =
      r.has("times") || r.has("superficial_velocity") || r.has("distributor") || r.has("top_plane");
  if (r.has("times"))
    if (const auto t = r.numbers("times")) f.times = *t;
  if (r.has("superficial_velocity"))
    if (const auto u = r.numbers("superficial_velocity")) f.superficial_velocity = *u;
  f.distributor = r.boolean("distributor");
  f.top_plane = r.number("top_plane");
  const bool clean = r.clean();
  r.finish();
  if (!given) return;
  if (!sc.periodic_z()) {
    r.fail("flow",
           "a flow is imposed only on a column periodic in z; set domain.periodic_z: true "
           "(a column with a wall at z = 0 has no flow through it)");
    return;
  }
  if (!clean) return;
  if (f.times.size() != f.superficial_velocity.size())
    r.fail("flow.superficial_velocity",
           fmt::format("needs one value per entry of flow.times ({}), got {}", f.times.size(),
                       f.superficial_velocity.size()));
  for (std::size_t k = 1; k < f.times.size(); ++k)
    if (!(f.times[k] > f.times[k - 1])) {
      r.fail("flow.times", fmt::format("must increase: entry {} ({} s) is not after entry {} "
                                       "({} s)",
                                       k, f.times[k], k - 1, f.times[k - 1]));
      break;
    }
  check_planes(r, sc);
}

void write_flow(YAML::Emitter& e, const Scene& sc) {
  if (!sc.periodic_z()) return;
  e << YAML::Key << "flow" << YAML::Value << YAML::BeginMap;
  e << YAML::Key << "times" << YAML::Value << YAML::Flow << sc.flow.times;
  e << YAML::Key << "superficial_velocity" << YAML::Value << YAML::Flow
    << sc.flow.superficial_velocity;
  e << YAML::Key << "distributor" << YAML::Value << sc.flow.distributor;
  e << YAML::Key << "top_plane" << YAML::Value << sc.flow.top_plane;
  e << YAML::EndMap;
}

}  // namespace sphdem
