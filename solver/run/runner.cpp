#include "run/runner.hpp"

#include <fmt/format.h>
#include <omp.h>
#include <sys/resource.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>

#include "analysis/diagnostics.hpp"
#include "analysis/neighbourhood_dump.hpp"
#include "analysis/sediment_output.hpp"
#include "analysis/watchdog.hpp"
#include "analysis/watchdog_warnings.hpp"
#include "coupling/drag_exchange.hpp"
#include "io/checkpoint_file.hpp"
#include "propagator/simulation.hpp"
#include "run/checkpoints.hpp"
#include "run/rank_forecast.hpp"
#include "run/rank_report.hpp"
#include "run/run_log.hpp"
#include "run/safeguard_tally.hpp"
#include "run/sediment_forecast.hpp"
#include "run/step_timing.hpp"
#include "scene/contact_stiffness_rule.hpp"
#include "scene/scene_limits.hpp"
#include "scene/sound_speed_rule.hpp"
#include "sph/kernel.hpp"
#include "sph/pair_isa.hpp"

namespace sphdem {

namespace {
using Clock = std::chrono::steady_clock;
double since(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

std::string format_duration(double s) {
  if (!std::isfinite(s)) return "?";
  if (s < 120) return fmt::format("{:.0f} s", s);
  if (s < 7200) return fmt::format("{:.1f} min", s / 60);
  return fmt::format("{:.1f} h", s / 3600);
}

// The process's peak resident set so far (Linux: ru_maxrss in KiB).
double peak_resident_mib() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss / 1024.0;
}

template <class V>
std::size_t bytes_of(V& container) {
  std::size_t b = 0;
  container.for_each_field([&](const FieldInfo&, auto& v) { b += v.capacity() * sizeof(v[0]); });
  return b;
}
}  // namespace

namespace {

// What the time loop carries besides the simulation: the clocks of the hooks, the log
// and the checkpoints, and the run's running totals. Checkpointed under "runner/".
struct LoopState {
  std::vector<double> next_hook, last_run;  // per hook (simulated time)
  std::vector<std::int64_t> hook_calls;
  double next_log = 0, next_checkpoint = 0;
  double dem_sphere_steps = 0;
  double largest_overlap = 0, largest_density_error = 0;  // over the logged steps
  SafeguardTally safeguards;

  void write(CheckpointWriter& w, const std::vector<PeriodicHook>& hooks) const {
    std::string names;
    for (const auto& h : hooks) names += h.name + "\n";
    w.text("runner/hook_names", names);
    w.array("runner/next_hook", next_hook);
    w.array("runner/last_run", last_run);
    w.array("runner/hook_calls", hook_calls);
    w.scalar("runner/next_log", next_log);
    w.scalar("runner/next_checkpoint", next_checkpoint);
    w.scalar("runner/dem_sphere_steps", dem_sphere_steps);
    w.scalar("runner/largest_overlap", largest_overlap);
    w.scalar("runner/largest_density_error", largest_density_error);
    const SafeguardTally& t = safeguards;
    w.array("runner/safeguard_counts",
            std::vector<std::int64_t>{t.steps, t.floor_steps, t.clamp_steps,
                                      static_cast<std::int64_t>(t.floor_largest),
                                      static_cast<std::int64_t>(t.clamp_largest)});
    w.array("runner/safeguard_particle_steps",
            std::vector<double>{t.floor_particle_steps, t.clamp_particle_steps});
  }

  // Hooks are matched by name; one the checkpoint does not know starts at the next
  // multiple of its interval.
  void read(const CheckpointReader& r, const std::vector<PeriodicHook>& hooks, double time) {
    std::vector<std::string> names;
    const std::string joined = r.text("runner/hook_names");
    for (std::size_t a = 0, b; (b = joined.find('\n', a)) != std::string::npos; a = b + 1)
      names.push_back(joined.substr(a, b - a));
    const auto nh = r.array<double>("runner/next_hook"), lr = r.array<double>("runner/last_run");
    const auto calls = r.array<std::int64_t>("runner/hook_calls");
    for (std::size_t k = 0; k < hooks.size(); ++k) {
      const auto it = std::find(names.begin(), names.end(), hooks[k].name);
      const std::size_t i = static_cast<std::size_t>(it - names.begin());
      if (it != names.end() && i < nh.size() && i < lr.size() && i < calls.size()) {
        next_hook[k] = nh[i];
        last_run[k] = lr[i];
        hook_calls[k] = calls[i];
      } else {
        next_hook[k] = std::ceil(time / hooks[k].interval * (1.0 - 1e-12)) * hooks[k].interval;
      }
    }
    next_log = r.scalar<double>("runner/next_log");
    next_checkpoint = r.scalar<double>("runner/next_checkpoint");
    dem_sphere_steps = r.scalar<double>("runner/dem_sphere_steps");
    largest_overlap = r.scalar<double>("runner/largest_overlap");
    largest_density_error = r.scalar<double>("runner/largest_density_error");
    const auto c = r.array<std::int64_t>("runner/safeguard_counts");
    const auto ps = r.array<double>("runner/safeguard_particle_steps");
    if (c.size() != 5 || ps.size() != 2)
      throw CheckpointError(r.path() + ": runner/safeguard_* have the wrong length");
    safeguards.steps = c[0];
    safeguards.floor_steps = c[1];
    safeguards.clamp_steps = c[2];
    safeguards.floor_largest = static_cast<std::size_t>(c[3]);
    safeguards.clamp_largest = static_cast<std::size_t>(c[4]);
    safeguards.floor_particle_steps = ps[0];
    safeguards.clamp_particle_steps = ps[1];
  }
};

const char* isa_name(PairIsa isa) {
  return isa == PairIsa::kAvx512 ? "x86-64-v4" : isa == PairIsa::kAvx2 ? "x86-64-v3" : "x86-64";
}

}  // namespace

RunSummary run_scene(const Scene& scene, RunOptions opt) {
  namespace fs = std::filesystem;
  refuse_scene_past_limits(scene);
  // On ranks (mpirun): every rank steps its share; rank 0 alone writes case.yaml, log.csv
  // and the progress lines, from diagnostics reduced over the ranks.
  const RankComm comm;
  const bool root = comm.rank() == 0;
  if (root) {
    fs::create_directories(opt.out_dir);
    std::ofstream cy(fs::path(opt.out_dir) / "case.yaml");
    cy << scene_to_yaml(scene);
  }
  std::ostream* out = root ? opt.progress : nullptr;
  const auto t_start = Clock::now();
  const CheckpointReader* resume = opt.resume;
  const int threads = omp_get_max_threads();
  if (resume) {
    const long was = static_cast<long>(resume->scalar<std::int64_t>("meta/threads"));
    const std::string isa = resume->text("meta/pair_isa");
    if (out)
      *out << fmt::format("sphdem: resuming from {} (t = {:.6g} s, step {})\n", resume->path(),
                          resume->scalar<double>("run/time"),
                          resume->scalar<std::int64_t>("run/step"));
    if (out && (was != threads || isa != isa_name(best_pair_isa())))
      *out << fmt::format(
          "sphdem: note: the checkpoint was written on {} thread(s) with {} lanes, this run "
          "has {} with {}: it continues the run exactly only on the same\n",
          was, isa, threads, isa_name(best_pair_isa()));
  }
  std::unique_ptr<Simulation> simulation = resume
                                               ? std::make_unique<Simulation>(scene, *resume, comm)
                                               : std::make_unique<Simulation>(scene, comm);
  Simulation& sim = *simulation;
  const std::uint64_t fluid_total = comm.sum(sim.fluid_count());
  const std::uint64_t wall_total = comm.sum(sim.wall_count());
  const std::uint64_t sphere_total = comm.sum(sim.spheres().n_owned);
  if (out && !resume)
    *out << fmt::format(
                "sphdem: {} fluid + {} wall SPH particles, {} spheres{}; relaxing {} "
                "steps\n",
                fluid_total, wall_total, sphere_total,
                comm.parallel() ? fmt::format(" on {} ranks", comm.size()) : "",
                scene.startup.relax_steps)
         << std::flush;
  if (!resume) sim.relax();
  const std::string log_path = (fs::path(opt.out_dir) / "log.csv").string();
  std::unique_ptr<RunLog> log;  // rank 0's
  if (root)
    log = resume ? std::make_unique<RunLog>(log_path, scene.species, sim.step_count())
                 : std::make_unique<RunLog>(log_path, scene.species);
  auto write_log = [&](const Diagnostics& d) {
    if (log) log->write(d);
  };

  LoopState st;
  st.next_hook.assign(opt.hooks.size(), 0.0);
  st.last_run.assign(opt.hooks.size(), -1.0);
  st.hook_calls.assign(opt.hooks.size(), 0);
  st.next_log = scene.output.log_interval;
  const CheckpointSpec& cs = scene.checkpoint;
  st.next_checkpoint = cs.every > 0 ? cs.every : HUGE_VAL;
  if (resume) {
    st.read(*resume, opt.hooks, sim.time());
    if (cs.every > 0 && !(st.next_checkpoint < HUGE_VAL))  // every set on resume
      st.next_checkpoint = std::ceil(sim.time() / cs.every * (1.0 + 1e-12)) * cs.every;
    if (cs.every <= 0) st.next_checkpoint = HUGE_VAL;
  }
  auto run_hooks = [&](bool last) {  // each hook at t = 0, every interval, and at the end
    bool fresh = false;              // the sphere copies brought up to date for the first hook
    for (std::size_t k = 0; k < opt.hooks.size(); ++k) {
      PeriodicHook& hk = opt.hooks[k];
      const bool due = sim.time() >= st.next_hook[k] * (1.0 - 1e-9);
      if (!due && !(last && st.last_run[k] != sim.time())) continue;
      if (!fresh) sim.refresh_sphere_copies();
      fresh = true;
      st.last_run[k] = sim.time();
      const auto t0 = Clock::now();
      hk.action(sim, st.hook_calls[k]++);
      hk.seconds += since(t0);
      while (st.next_hook[k] <= sim.time() * (1.0 + 1e-9)) st.next_hook[k] += hk.interval;
    }
  };
  if (!resume) {
    write_log(diagnostics(sim));
    run_hooks(false);
  }

  RunSummary r;
  CheckpointStore store(opt.out_dir, cs.keep, comm);
  auto write_checkpoint = [&] {
    const auto t0 = Clock::now();
    r.checkpoint = store.write(sim.step_count(), [&](CheckpointWriter& w) {
      sim.write_state(w);
      st.write(w, opt.hooks);
      w.text("scene/yaml", scene_to_yaml(scene));
      w.scalar<std::int64_t>("meta/threads", threads);
      w.text("meta/pair_isa", isa_name(best_pair_isa()));
    });
    ++r.checkpoints_written;
    r.checkpoint_seconds += since(t0);
  };

  // The watchdog's stop: the step's log row, the neighbourhood dump, and the message with
  // the last good checkpoint (the state now is not written).
  auto stop_by_watchdog = [&](const Simulation& s, const WatchdogAlarm& alarm) {
    const fs::path dir = fs::path(opt.out_dir) / "watchdog";
    fs::create_directories(dir);
    const std::string dump = (dir / fmt::format("step_{:012d}.vtp", s.step_count())).string();
    const double h = scene.fluid.lattice_h();
    double d_max = 0.0;
    for (const auto& sp : scene.species) d_max = std::max(d_max, sp.d_max());
    const double radius = std::max(3.0 * kernel::kSupport * h, 5.0 * d_max);
    std::string dumped;
    try {
      const std::size_t n = write_neighbourhood_vtp(s, alarm.x, alarm.y, alarm.z, radius,
                                                    alarm.sphere, alarm.index, dump);
      dumped = fmt::format("; its neighbourhood ({} particles within {:.3g} m) is in {}", n, radius,
                           dump);
    } catch (const std::exception& e) {
      dumped = fmt::format("; the neighbourhood dump failed: {}", e.what());
    }
    const auto last = CheckpointStore::list(opt.out_dir);
    return describe_alarm(alarm, s.step_count(), s.time()) + dumped +
           (last.empty() ? std::string("; no checkpoint was written")
                         : "; the last good checkpoint is " + last.back());
  };
  // Every rank takes the same decision: the watchdog's alarm on any rank stops them all
  // (the lowest alarmed rank's message), a stop request on any rank asks all to stop, and
  // the safeguards' counts are summed: one reduction a step.
  // the warnings (analysis/watchdog_warnings.hpp) ride on the same reduction
  WatchdogWarnings warnings(scene);
  auto after_step = [&](int& stop) {
    WatchdogReading reading;
    const auto alarm = watchdog_check(sim, scene.watchdog, &reading);
    std::vector<std::uint64_t> v{
        alarm ? 1u : 0u,
        static_cast<std::uint64_t>(opt.stop_requested ? opt.stop_requested() : 0),
        sim.voidage_clamped(),
        sim.omega_bounded(),
        reading.density_error > warnings.density_warning() ? 1u : 0u,
        reading.overlap > warnings.expected_overlap() ? 1u : 0u};
    if (comm.parallel()) {
      const std::vector<std::uint64_t> mine = v;
      comm.sum(v);
      v[1] = static_cast<std::uint64_t>(comm.max(static_cast<double>(mine[1])));
    }
    st.safeguards.add(v[2], v[3]);
    if (scene.watchdog.enabled)
      for (const std::string& w :
           warnings.observe({v[4] > 0, v[5] > 0, v[2], v[3]}, sim.step_count(), sim.time()))
        if (out) *out << "sphdem: warning " << w << "\n" << std::flush;
    stop = static_cast<int>(v[1]);
    if (v[0] == 0) return;
    write_log(diagnostics(sim));
    const int first = static_cast<int>(-comm.max(alarm ? -comm.rank() : -comm.size()));
    std::string why = alarm ? stop_by_watchdog(sim, *alarm) : std::string();
    throw WatchdogError(comm.broadcast(why, first));
  };

  double step_seconds = 0;
  const auto t_loop = Clock::now();
  auto t_progress = t_loop, t_checkpoint = t_loop;
  const long first_step = sim.step_count();
  const RankComm::Traffic traffic_at_loop = comm.traffic();
  const double sphere_steps_at_loop = st.dem_sphere_steps;
  const double end = scene.time.end;
  bool checkpoint_due = false;
  while (sim.time() < end * (1.0 - 1e-12)) {
    const auto t_step = Clock::now();
    sim.step();
    step_seconds += since(t_step);
    int stop = 0;
    after_step(stop);
    st.dem_sphere_steps += static_cast<double>(sim.dem_substeps()) * sphere_total;
    const bool last = sim.time() >= end * (1.0 - 1e-12);
    if (sim.time() >= st.next_log * (1.0 - 1e-9) || last) {
      const Diagnostics d = diagnostics(sim);
      st.largest_overlap = std::max(st.largest_overlap, d.max_overlap_over_d);
      st.largest_density_error = std::max(st.largest_density_error, d.max_density_error);
      write_log(d);
      while (st.next_log <= sim.time() * (1.0 + 1e-9)) st.next_log += scene.output.log_interval;
    }
    run_hooks(last);
    if (out && since(t_progress) >= scene.output.progress_interval) {
      t_progress = Clock::now();
      const double wall = since(t_loop);
      const double rate = (sim.step_count() - first_step) / wall;
      const double eta = rate > 0 ? (end - sim.time()) / sim.dt_sph() / rate : HUGE_VAL;
      *out << fmt::format(
                  "  t = {:.4e} / {:.4e} s ({:4.1f} %)  step {}  {:.1f} steps/s  dt = {:.3e} s  "
                  "ETA {}\n",
                  sim.time(), end, 100.0 * sim.time() / end, sim.step_count(), rate, sim.dt_sph(),
                  format_duration(eta))
           << std::flush;
    }
    // Checkpoints fall due by simulated time, by wall time or by a stop request, and are
    // written at the first step after which the next one re-sorts and rebuilds every list
    // (within 100 steps): writing one never changes the run's course.
    if (sim.time() >= st.next_checkpoint * (1.0 - 1e-9)) {
      checkpoint_due = true;
      while (st.next_checkpoint <= sim.time() * (1.0 + 1e-9)) st.next_checkpoint += cs.every;
    }
    if (cs.wall_interval > 0 && since(t_checkpoint) >= cs.wall_interval) checkpoint_due = true;
    if (stop && !r.stopped_by) {
      r.stopped_by = stop;
      checkpoint_due = true;
      if (out)
        *out << fmt::format("sphdem: stop requested (signal {}): writing a checkpoint{}\n", stop,
                            sim.rebuilds_all_next_step() ? "" : " at the next rebuild of the lists")
             << std::flush;
    }
    if (checkpoint_due && !last && sim.rebuilds_all_next_step()) {
      write_checkpoint();
      checkpoint_due = false;
      t_checkpoint = Clock::now();
      if (r.stopped_by) break;
    }
  }
  const bool finished = sim.time() >= end * (1.0 - 1e-12);
  if (finished && (cs.at_end || checkpoint_due)) write_checkpoint();
  if (finished) write_sediment_output(sim, opt.out_dir);
  r.safeguards = st.safeguards;
  r.steps = sim.step_count();
  r.step_seconds = step_seconds;
  r.hooks = opt.hooks;
  r.simulated_time = sim.time();
  r.wall_seconds = since(t_start);
  const double loop = since(t_loop);
  const double steps_here = static_cast<double>(sim.step_count() - first_step);
  r.fluid_particle_steps_per_second =
      static_cast<double>(comm.sum(sim.fluid().n_owned)) * steps_here / loop;
  r.sphere_particle_steps_per_second = st.dem_sphere_steps / loop;
  r.largest_overlap = st.largest_overlap;
  r.largest_density_error = st.largest_density_error;
  // the multi-rate tally's spheres, summed over the ranks (its half steps are every rank's)
  std::vector<double> near{sim.multirate_tally().near_spheres, sim.multirate_tally().owned_spheres};
  if (comm.parallel()) comm.sum(near);
  const long loop_steps = sim.step_count() - first_step;
  const double substeps = sphere_total > 0 && loop_steps > 0
                              ? (st.dem_sphere_steps - sphere_steps_at_loop) /
                                    static_cast<double>(sphere_total) / loop_steps
                              : 0.0;
  const std::string ranks_text = rank_report(sim, comm, traffic_at_loop, loop_steps, substeps);
  if (!out) return r;
  const auto& t = sim.timers().seconds;
  double total = 0;
  for (double x : t) total += x;
  std::string parts;
  for (int k = 0; k < PassTimers::kCount; ++k)
    parts +=
        fmt::format(" {} {:.0f}%", PassTimers::kNames[k], 100.0 * t[k] / std::max(total, 1e-30));
  *out << "sphdem: time per pass:" << parts << "\n";
  for (const auto& hk : opt.hooks)
    *out << fmt::format("sphdem: {}: {:.2f} s, {:.1f} % of the step time\n", hk.name, hk.seconds,
                        100.0 * hk.seconds / std::max(step_seconds, 1e-30));
  if (r.checkpoints_written > 0)
    *out << fmt::format("sphdem: {} checkpoint(s), {:.2f} s, {:.2f} % of the step time; last {}\n",
                        r.checkpoints_written, r.checkpoint_seconds,
                        100.0 * r.checkpoint_seconds / std::max(step_seconds, 1e-30), r.checkpoint);
  *out << "sphdem: " << r.safeguards.describe(fluid_total + wall_total) << "\n";
  if (fluid_total > 0)
    *out << fmt::format(
        "sphdem: largest density error over the logged steps {:.2g} % (expected {:.2g} % from c0; "
        "limit 1 %{})\n",
        100 * r.largest_density_error, 100 * sound_speed_report(scene).expected_density_error(),
        r.largest_density_error > 0.01 ? ": " + twice_the_sound_speed(scene) : "");
  if (sphere_total > 0)
    *out << fmt::format("sphdem: largest overlap over the logged steps {:.3g} d{}\n",
                        r.largest_overlap,
                        r.largest_overlap > scene.contact.max_overlap
                            ? fmt::format(" -- above contact.max_overlap = {}: a stiffer spring "
                                          "(contact.stiffness) or a slower impact",
                                          scene.contact.max_overlap)
                            : fmt::format(" (contact.max_overlap {})", scene.contact.max_overlap));
  if (const MultirateTally& m = sim.multirate_tally(); sim.multirate() && m.half_steps > 0)
    *out << fmt::format(
        "sphdem: time.multirate: the spheres out of contact took the fluid's step in {} of {} DEM "
        "half steps ({:.2g} % of the spheres sub-stepped in those); {} tried and sent back\n",
        m.multirate, m.half_steps, 100.0 * near[0] / std::max(near[1], 1.0), m.sent_back);
  *out << ranks_text;
  if (r.stopped_by)
    *out << fmt::format(
        "sphdem: stopped at t = {:.6g} s (step {}); checkpoint {}. Continue with: sphdem resume "
        "{}\n",
        r.simulated_time, r.steps, r.checkpoint.empty() ? "none" : r.checkpoint, opt.out_dir);
  else
    *out << fmt::format(
        "sphdem: done, {} steps to t = {:.4e} s in {} ({:.3g} SPH particle-steps/s)\n", r.steps,
        r.simulated_time, format_duration(r.wall_seconds), r.fluid_particle_steps_per_second);
  return r;
}

namespace {
// Fluid particles of the lattice start and the acoustic step cfl h / c0 (3.5), for the
// presets' estimates (the run's dt also has its viscous, force and drag bounds).
double fluid_lattice_count(const Scene& sc) {
  const double dx = sc.fluid.spacing;
  return sc.fluid.enabled ? std::round(sc.box.length(0) / dx) * std::round(sc.box.length(1) / dx) *
                                std::round(sc.fill_height() / dx)
                          : 0.0;
}
double acoustic_step(const Scene& sc) {
  return sc.time.cfl * sc.fluid.lattice_h() / sc.fluid.sound_speed;
}

std::string describe_presets(const Scene& sc, const std::vector<Scene>& presets, double wall) {
  std::string s = fmt::format(
      "fidelity         {} (fast | balanced | accurate; measured on reference scenes in "
      "bench/TRADEOFF.md){}\n",
      sc.fidelity, sc.fidelity_note.empty() ? "" : ": " + sc.fidelity_note);
  s += "  preset     dx (m)      fluid    c0 (m/s)  CFL   DEM/t_c  max overlap  density error  "
       "est. wall\n";
  const double n0 = std::max(fluid_lattice_count(sc), 1.0), dt0 = acoustic_step(sc);
  for (const Scene& p : presets) {
    const double scale = std::max(fluid_lattice_count(p), 1.0) / n0 * dt0 / acoustic_step(p);
    s += fmt::format("  {:<9}  {:<10.4g}  {:<7.0f}  {:<8.4g}  {:<4}  {:<7}  {:<11}  {:<13}  {}\n",
                     p.fidelity, p.fluid.spacing, fluid_lattice_count(p), p.fluid.sound_speed,
                     p.time.cfl, p.time.dem_steps_per_contact,
                     fmt::format("{:.3g} d", p.contact.max_overlap),
                     fmt::format("{:.2g} %", 100 * sound_speed_report(p).expected_density_error()),
                     format_duration(wall * scale));
  }
  return s;
}
}  // namespace

std::string describe_scene(const Scene& sc, const std::vector<Scene>& presets, int ranks) {
  const double resident_before = peak_resident_mib();
  const double start_cpu = process_cpu_seconds();  // the program's start, as a run's
  const auto t_setup = Clock::now();
  Simulation sim(sc);
  const double setup_wall = start_cpu + since(t_setup);
  std::string s;
  s += fmt::format("scene            {} ({})\n", sc.name, sc.source);
  if (sc.periodic_z())
    s += fmt::format(
        "domain           {} x {} x {} m, periodic in x, y and z, filled with fluid; U(t) of "
        "`flow` held by the mean pressure gradient (from {} m/s to {} m/s)\n",
        sc.box.length(0), sc.box.length(1), sc.box.length(2), sc.flow.superficial_velocity.front(),
        sc.flow.superficial_velocity.back());
  else
    s += fmt::format(
        "domain           {} x {} x {} m, periodic in x and y, wall at z = 0, fluid to z = {} m\n",
        sc.box.length(0), sc.box.length(1), sc.box.length(2), sc.fill_height());
  s += fmt::format(
      "SPH particles    {} fluid + {} wall ({} layers), spacing dx = {} m, h = {:.4g} m\n",
      sim.fluid_count(), sim.wall_count(), sc.periodic_z() ? 0 : sc.fluid.wall_layers,
      sc.fluid.spacing, sc.fluid.lattice_h());
  const auto& sp = sim.spheres();
  std::vector<std::size_t> count(sc.species.size(), 0);
  for (std::size_t j = 0; j < sp.n_owned; ++j) ++count[sp.species[j]];
  for (std::size_t k = 0; k < sc.species.size(); ++k) {
    const SpeciesSpec& spec = sc.species[k];
    if (spec.monodisperse()) {
      s += fmt::format("species {:<8} {} spheres, d = {} m, rho = {} kg/m^3, h/d = dx/d = {:.3g}\n",
                       spec.name, count[k], spec.diameter, spec.density,
                       sc.fluid.spacing / spec.diameter);
      continue;
    }
    double dmin = spec.d_max(), dmax = spec.d_min(), sum = 0.0;  // of the spheres placed
    for (std::size_t j = 0; j < sp.n_owned; ++j)
      if (sp.species[j] == k) {
        dmin = std::min(dmin, 2.0 * sp.radius[j]);
        dmax = std::max(dmax, 2.0 * sp.radius[j]);
        sum += 2.0 * sp.radius[j];
      }
    s += fmt::format(
        "species {:<8} {} spheres, {} law on [{}, {}] m (d32 = {:.4g} m; placed: mean {:.4g} m, "
        "{:.4g} .. {:.4g} m), rho = {} kg/m^3, h/d = dx/d = {:.3g} .. {:.3g}\n",
        spec.name, count[k], size_law_name(spec.size.law), spec.d_min(), spec.d_max(),
        spec.diameter, count[k] ? sum / count[k] : 0.0, dmin, dmax, spec.density,
        sc.fluid.spacing / spec.d_max(), sc.fluid.spacing / spec.d_min());
  }
  s += fmt::format(
      "fluid            rho_f = {} kg/m^3, mu = {} Pa s, c0 = {:.4g} m/s, B = {:.4g} Pa, u_m = "
      "{:.4g} m/s\n",
      sc.fluid.density, sc.fluid.viscosity, sc.fluid.sound_speed, sim.eos().B,
      sc.fluid.expected_speed);
  if (sc.fluid.enabled) {
    const SoundSpeedReport c = sound_speed_report(sc);
    s += fmt::format(
        "sound speed      c0 = {:.4g} m/s: Mach u_m/c0 = {:.3g}, expected density error {:.2g} % "
        "(Ma^2 = {:.2g} %, the column's weight g H/c0^2 = {:.2g} %; limit 1 %, log.csv "
        "max_density_error); the compression buoys the lightest species {:.2g} % more than its "
        "buoyant weight (automatic c0: <= {} %)\n",
        c.c0, c.mach, 100 * c.expected_density_error(), 100 * c.flow, 100 * c.hydrostatic,
        100 * c.buoyancy, 100 * kBuoyancyErrorTarget);
  }
  s += fmt::format("drag law         {}\n", drag::drag_law_name(sc.drag));
  s += fmt::format(
      "coupling         {}{}, spheres' kernel H = {} h, the drag's {} h{}{}{}\n",
      sc.pressure_coupling == PressureCoupling::kVariational ? "variational" : "interpolated",
      sc.hydrostatic_split ? " with the hydrostatic split" : "", sc.sphere_kernel_scale,
      sc.drag_kernel_scale, sc.drag_upstream ? " read from its upstream (gravity's) half" : "",
      sc.drag_voidage_upstream ? ", the fluid's drag voidage from the spheres below it" : "",
      sc.sphere_kernel_reason.empty() ? "" : " (" + sc.sphere_kernel_reason + ")");
  const double dt = sim.dt_sph();
  const int sub = sp.n_owned == 0
                      ? 0
                      : 2 * std::max(1, static_cast<int>(std::ceil(0.5 * dt / sim.dt_dem_max())));
  s += fmt::format("contact time     t_c = {:.4g} s (k = {} N/m{})\n", sim.contact_time(),
                   sc.contact.normal.k,
                   sc.contact.stiffness_reason.empty() ? "" : "; " + sc.contact.stiffness_reason);
  if (!sc.species.empty()) {
    const StiffnessChoice c = choose_contact_stiffness(sc);
    const double scale = std::sqrt(c.k / sc.contact.normal.k);  // overlaps at this scene's k
    s += fmt::format(
        "overlaps         expected largest {:.2g} d at impact ({:.3g} m/s), {:.2g} d under the "
        "sediment's weight (log.csv max_overlap_over_d; contact.max_overlap = {})\n",
        c.impact_overlap * scale, c.impact_speed, c.static_overlap * c.k / sc.contact.normal.k,
        sc.contact.max_overlap);
  }
  if (sc.watchdog.enabled) {  // (analysis/watchdog_warnings.hpp)
    const WatchdogWarnings w(sc);
    const bool fluid = std::isfinite(w.expected_density_error());
    const bool springs = std::isfinite(w.expected_overlap());
    s += fmt::format(
        "watchdog         stops the run past {}an overlap of {} d; warns once past {}{}, and "
        "for a safeguard biting {} steps in a row\n",
        fluid ? fmt::format("a density error of {:.2g} % (watchdog.density_error), ",
                            100 * sc.watchdog.density_error)
              : "",
        sc.watchdog.overlap,
        fluid ? fmt::format("{:.2g} % ({} x the expected)", 100 * w.density_warning(),
                            kDensityWarningMargin)
              : "",
        springs ? fmt::format("{}the expected overlap {:.2g} d", fluid ? ", " : "",
                              w.expected_overlap())
                : "",
        kPersistentSafeguardSteps);
  }
  const TangentialParams& tp = sc.contact.tangential;
  if (tp.model == TangentialParams::Model::kLinearHistory)
    s += fmt::format("friction         linear_history: k_t = {:.4g} N/m, mu = {}, {}\n",
                     tp.stiffness_ratio * sc.contact.normal.k, tp.friction,
                     tp.restitution > 0 ? fmt::format("e_t = {}", tp.restitution)
                                        : fmt::format("gamma_t = {} kg/s", tp.damping));
  if (sc.contact.rolling.model == RollingParams::Model::kEpsd)
    s += fmt::format("rolling          epsd: mu_r = {}, eta_r = {}\n", sc.contact.rolling.friction,
                     sc.contact.rolling.damping_ratio);
  // explicit, the fluid's drag exchange would bound the step (DemSubstepper::fluid_drag_time)
  const double drag_exchange = kExplicitDragLimit * sim.dem().fluid_drag_time();
  s += fmt::format(
      "time steps       dt_SPH = {:.4g} s (CFL {}{}), dt_DEM = {:.4g} s, {} DEM sub-steps per "
      "SPH step (more where the spheres' drag relaxes them faster: 0.1 m/(c eps) at run time)\n",
      dt, sc.time.cfl,
      drag_exchange < dt
          ? fmt::format("; the fluid's drag exchange with the spheres semi-implicit, explicit it "
                        "would need dt <= {:.3g} s (coupling/drag_exchange.hpp)",
                        drag_exchange)
          : "",
      sub > 0 ? dt / sub : 0.0, sub);
  s += fmt::format(
      "run              {} relaxation steps, then t = 0 .. {} s: about {:.0f} SPH steps\n",
      sc.startup.relax_steps, sc.time.end, sc.time.end / dt);
  const double mb = (bytes_of(sim.fluid()) + bytes_of(sim.spheres())) / 1048576.0;
  // One step builds what the run holds besides the arrays: neighbour and contact lists,
  // per-thread scratch, the contact history; the process's peak resident set then is
  // what the run needs (without the in-situ analysis, which ParaView adds).
  sim.step();
  const double mib_peak = peak_resident_mib();
  const StepTiming timing = time_steps(sim);
  const double relax_wall = setup_wall + sc.startup.relax_steps * timing.step;
  const SedimentForecast bed = forecast_sediment(sc, dt);
  const double steps_wall = forecast_wall(bed, timing.step, dt, sc.time.end);
  const double run_wall = relax_wall + steps_wall;
  if (bed.forms)
    s += fmt::format(
        "sediment         forms by about {:.3g} s (Kynch, the slowest spheres from eps {} to a "
        "bed at eps {}): dt_SPH then x {:.2f} (c0 / sqrt(eps) at its top), so {:.0f} SPH steps "
        "to t = {} s in all; the bed's contacts are not counted (run/sediment_forecast.hpp)\n",
        bed.settle_time, bed.suspension_voidage, kBedVoidage, bed.step_ratio,
        forecast_steps(bed, dt, sc.time.end), sc.time.end);
  s += fmt::format(
      "wall time        about {} on this machine, {} threads (a step takes {:.3g} s, one "
      "thread's {:.3g} s of CPU; set-up and relaxation {}){}\n",
      format_duration(run_wall), timing.threads, timing.step, timing.one_thread_cpu,
      format_duration(relax_wall),
      timing.cores_busy
          ? fmt::format(
                ": the cores were busy while check timed it ({} threads took {:.3g} s a step, "
                "longer than one thread's {:.3g} s of CPU), so the step is one thread's times "
                "{:.2g}, the share {} threads take on idle cores",
                timing.threads, timing.threads_wall, timing.one_thread_cpu,
                idle_thread_share(timing.threads), timing.threads)
          : "");
  if (!presets.empty()) s += describe_presets(sc, presets, run_wall);
  s += fmt::format(
      "memory           {:.0f} MiB for the scene: the growth of the peak resident set over "
      "the initial state and one step ({:.0f} -> {:.0f} MiB; particle arrays with their halo "
      "copies {:.1f} MiB, the rest lists and scratch; in-situ analysis not included)\n",
      mib_peak - resident_before, resident_before, mib_peak, mb);
  if (ranks > 1) {
    const RankForecast rf = forecast_ranks(sim, ranks);
    const double particles = static_cast<double>(sim.fluid().size() + sim.spheres().size());
    const double per_rank = static_cast<double>(rf.owned_max + rf.ghosts_max) / particles;
    s += fmt::format(
        "{:<17}the cuts by the counted work: the largest rank owns {} particles and "
        "holds {} halo copies ({:.2f} copies per owned particle over all ranks), and takes "
        "{:.1f} % of the work (max/mean {:.2f})\n"
        "                 memory about {:.0f} MiB per rank ({:.0f} MiB of the process, and the "
        "scene's {:.0f} MiB times its particles' share {:.3f}); {:.0f} MiB for all ranks\n"
        "                 wall time about {} with {} threads a rank ({} cores): the steps' "
        "time times the largest share; the exchanges between ranks are not counted (on one "
        "2-core machine 2 ranks x 1 thread took 1.3-1.5 x the time of 1 rank x 2 threads, "
        "bench/RESULTS.md)\n",
        fmt::format("on {} ranks", ranks), rf.owned_max, rf.ghosts_max, rf.ghosts_per_owned,
        100.0 * rf.largest_share, rf.largest_share * ranks,
        resident_before + (mib_peak - resident_before) * per_rank, resident_before,
        mib_peak - resident_before, per_rank,
        ranks * (resident_before + (mib_peak - resident_before) * per_rank),
        format_duration(setup_wall + (run_wall - setup_wall) * rf.largest_share), timing.threads,
        ranks * timing.threads);
  }
  return s;
}

}  // namespace sphdem
