// How a run advances and what it writes on the way: time, startup, output, checkpoint
// and watchdog.
#include "scene/sections/sections.hpp"

namespace sphdem {

void read_run_control(MapReader& top, Scene& sc, ReadContext& cx) {
  {
    MapReader r(top.child("time"), "time", cx.problems);
    TimeSpec& t = sc.time;
    t.end = r.number("end");
    t.cfl = r.number("cfl", cx.preset->cfl);
    t.dem_steps_per_contact = r.number("dem_steps_per_contact", cx.preset->dem_steps_per_contact);
    t.multirate = r.boolean("multirate");
    t.multirate_margin = r.number("multirate_margin");
    t.max_dt_sph = r.number("max_dt_sph");
    r.finish();
  }
  {
    MapReader r(top.child("startup"), "startup", cx.problems);
    sc.startup.relax_steps = r.integer("relax_steps");
    sc.startup.damping = r.number("damping");
    r.finish();
  }
  {
    MapReader r(top.child("output"), "output", cx.problems);
    sc.output.log_interval = r.number("log_interval");
    sc.output.progress_interval = r.number("progress_interval");
    {
      MapReader v(r.child("vtk"), "output.vtk", cx.problems);
      sc.output.vtk_every = v.number("every");
      v.finish();
    }
    r.finish();
  }
  {
    MapReader r(top.child("checkpoint"), "checkpoint", cx.problems);
    CheckpointSpec& c = sc.checkpoint;
    c.every = r.number("every");
    c.wall_interval = r.number("wall_interval");
    c.keep = r.integer("keep");
    c.at_end = r.boolean("at_end");
    r.finish();
  }
  {
    MapReader r(top.child("watchdog"), "watchdog", cx.problems);
    WatchdogSpec& w = sc.watchdog;
    w.enabled = r.boolean("enabled");
    cx.density_alarm_auto = r.number_or_auto("density_error", w.density_error);
    w.overlap = r.number("overlap");
    w.safeguard_share = r.number("safeguard_share");
    r.finish();
  }
}

void write_run_control(YAML::Emitter& e, const Scene& sc) {
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
}

}  // namespace sphdem
