// The flow section: U(t) of a column periodic in z (domain.periodic_z), a piecewise linear
// schedule the flow controller follows (propagator/flow_controller.hpp).
#include <fmt/format.h>

#include "scene/sections/sections.hpp"

namespace sphdem {

void read_flow(MapReader& top, Scene& sc, ReadContext& cx) {
  MapReader r(top.child("flow"), "flow", cx.problems);
  FlowSpec& f = sc.flow;
  const bool given = r.has("times") || r.has("superficial_velocity");
  if (r.has("times"))
    if (const auto t = r.numbers("times")) f.times = *t;
  if (r.has("superficial_velocity"))
    if (const auto u = r.numbers("superficial_velocity")) f.superficial_velocity = *u;
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
}

void write_flow(YAML::Emitter& e, const Scene& sc) {
  if (!sc.periodic_z()) return;
  e << YAML::Key << "flow" << YAML::Value << YAML::BeginMap;
  e << YAML::Key << "times" << YAML::Value << YAML::Flow << sc.flow.times;
  e << YAML::Key << "superficial_velocity" << YAML::Value << YAML::Flow
    << sc.flow.superficial_velocity;
  e << YAML::EndMap;
}

}  // namespace sphdem
