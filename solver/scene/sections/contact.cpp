// The contact section: the normal spring-dashpot and its tangential (friction) and
// rolling parts. Keys other than a part's 'model' exist only for a model that has them.
#include <fmt/format.h>

#include <optional>

#include "scene/sections/sections.hpp"

namespace sphdem {

void read_contact(MapReader& top, Scene& sc, ReadContext& cx) {
  MapReader r(top.child("contact"), "contact", cx.problems);
  r.choice("model");
  LinearSpringDashpot& n = sc.contact.normal;
  // a number, or auto (the default): resolved once the fluid and drag are known
  cx.stiffness_auto = r.number_or_auto("stiffness", n.k);
  sc.contact.max_overlap = r.number("max_overlap", cx.preset->max_overlap);
  const bool has_damping = r.has("damping"), has_e = r.has("restitution");
  if (has_damping && has_e)
    r.fail("contact.restitution", "give either 'damping' (kg/s) or 'restitution', not both");
  n.beta = r.number("damping");
  n.restitution = has_e ? r.number("restitution") : -1.0;
  n.clip_attraction = r.boolean("clip_attraction");
  sc.contact.skin = r.number("skin");
  bool tangential_known = true;
  {
    MapReader t(r.child("tangential"), "contact.tangential", cx.problems);
    TangentialParams& tp = sc.contact.tangential;
    const std::optional<std::string> model = t.choice("model");
    tp = TangentialParams{};
    tangential_known = model.has_value();
    if (model == std::optional<std::string>("linear_history")) {
      tp.model = TangentialParams::Model::kLinearHistory;
      tp.stiffness_ratio = t.number("stiffness_ratio");
      const bool has_gamma = t.has("damping"), has_et = t.has("restitution");
      if (has_gamma && has_et)
        t.fail("contact.tangential.restitution",
               "give either 'damping' (kg/s) or 'restitution', not both");
      tp.damping = t.number("damping");
      tp.restitution = has_et ? t.number("restitution") : -1.0;
      tp.friction = t.required("friction");
    }
    t.finish(tangential_known);
  }
  {
    MapReader t(r.child("rolling"), "contact.rolling", cx.problems);
    RollingParams& rp = sc.contact.rolling;
    const std::optional<std::string> model = t.choice("model");
    rp = RollingParams{};
    if (model == std::optional<std::string>("epsd")) {
      rp.model = RollingParams::Model::kEpsd;
      rp.friction = t.required("friction");
      rp.damping_ratio = t.number("damping_ratio");
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

void write_contact(YAML::Emitter& e, const Scene& sc) {
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
}

}  // namespace sphdem
