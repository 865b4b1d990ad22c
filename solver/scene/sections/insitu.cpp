// The insitu section: which Catalyst pipelines run, how often, on which voidage grid,
// and the Kynch line of the figures.
#include <fmt/format.h>

#include <algorithm>

#include "scene/did_you_mean.hpp"
#include "scene/sections/sections.hpp"

namespace sphdem {

void read_insitu(MapReader& top, Scene& sc, ReadContext& cx) {
  MapReader r(top.child("insitu"), "insitu", cx.problems);
  InSituSpec& in = sc.insitu;
  in.enabled = r.boolean("enabled");
  in.every = r.number("every");
  in.pipelines = choices_of(r.row("pipelines"));  // default: every pipeline
  if (r.has("pipelines")) {
    const std::vector<std::string> allowed = in.pipelines;
    const YAML::Node list = r.child("pipelines");
    if (!list.IsSequence()) r.fail("insitu.pipelines", "must be a list of pipeline names");
    std::vector<std::string> names;
    for (std::size_t k = 0; list.IsSequence() && k < list.size(); ++k) {
      const std::string name = list[k].IsScalar() ? list[k].Scalar() : "";
      if (std::find(allowed.begin(), allowed.end(), name) == allowed.end())
        r.fail(fmt::format("insitu.pipelines.{}", k),
               fmt::format("must be one of: {} (got '{}'){}", fmt::join(allowed, ", "), name,
                           did_you_mean(name, allowed)));
      names.push_back(name);
    }
    if (list.IsSequence()) in.pipelines = names;
  }
  in.snapshot_every = r.integer("snapshot_every");
  in.grid_spacing = r.number("grid_spacing");
  in.reference_velocity = r.number("reference_velocity");
  r.finish();
}

void write_insitu(YAML::Emitter& e, const Scene& sc) {
  const InSituSpec& in = sc.insitu;
  e << YAML::Key << "insitu" << YAML::Value << YAML::BeginMap << YAML::Key << "enabled"
    << YAML::Value << in.enabled << YAML::Key << "every" << YAML::Value << in.every << YAML::Key
    << "pipelines" << YAML::Value << YAML::Flow << in.pipelines << YAML::Key << "snapshot_every"
    << YAML::Value << in.snapshot_every << YAML::Key << "grid_spacing" << YAML::Value
    << in.grid_spacing << YAML::Key << "reference_velocity" << YAML::Value << in.reference_velocity
    << YAML::EndMap;
}

}  // namespace sphdem
