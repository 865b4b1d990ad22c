// The top level of a scene: name, description, fidelity, domain, gravity.
#include "scene/sections/sections.hpp"

namespace sphdem {

void read_top(MapReader& top, Scene& sc, ReadContext& cx) {
  sc.name = top.text("name");
  sc.description = top.text("description");
  // the preset's values are the defaults of the keys it names (scene/fidelity.hpp)
  sc.fidelity = top.choice("fidelity").value_or(std::string(scene_key("fidelity").text));
  cx.preset = find_fidelity_preset(sc.fidelity);
  // Checks against the box run only on a box the file gave without a problem (a default
  // box in place of a bad one would give problems the file does not have).
  MapReader r(top.child("domain"), "domain", cx.problems);
  const std::array<double, 3> size = r.vec3("size");
  cx.box_ok = r.clean();
  sc.box.lo = {0, 0, 0};
  sc.box.hi = cx.box_ok ? size : scene_key("domain.size").vector;
  sc.box.periodic = {true, true, r.boolean("periodic_z")};
  r.finish();
  sc.gravity = top.vec3("gravity");
}

void write_top(YAML::Emitter& e, const Scene& sc) {
  e << YAML::Key << "name" << YAML::Value << sc.name;
  e << YAML::Key << "description" << YAML::Value << sc.description;
  e << YAML::Key << "fidelity" << YAML::Value << sc.fidelity;
  e << YAML::Key << "domain" << YAML::Value << YAML::BeginMap << YAML::Key << "size" << YAML::Value;
  emit_vec3(e, sc.box.hi);
  e << YAML::Key << "periodic_z" << YAML::Value << sc.periodic_z();
  e << YAML::EndMap;
  e << YAML::Key << "gravity" << YAML::Value;
  emit_vec3(e, sc.gravity);
}

void emit_vec3(YAML::Emitter& e, const std::array<double, 3>& v) {
  e << YAML::Flow << YAML::BeginSeq << v[0] << v[1] << v[2] << YAML::EndSeq;
}

}  // namespace sphdem
