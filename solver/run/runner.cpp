#include "run/runner.hpp"

#include <fmt/format.h>
#include <sys/resource.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>

#include "analysis/diagnostics.hpp"
#include "analysis/sediment_output.hpp"
#include "propagator/simulation.hpp"
#include "run/run_log.hpp"
#include "run/safeguard_tally.hpp"
#include "scene/contact_stiffness_rule.hpp"
#include "scene/scene_limits.hpp"
#include "scene/sound_speed_rule.hpp"

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

RunSummary run_scene(const Scene& scene, RunOptions opt) {
  namespace fs = std::filesystem;
  refuse_scene_past_limits(scene);
  fs::create_directories(opt.out_dir);
  {
    std::ofstream cy(fs::path(opt.out_dir) / "case.yaml");
    cy << scene_to_yaml(scene);
  }
  std::ostream* out = opt.progress;
  const auto t_start = Clock::now();
  Simulation sim(scene);
  if (out)
    *out << fmt::format("sphdem: {} fluid + {} wall SPH particles, {} spheres; relaxing {} steps\n",
                        sim.fluid_count(), sim.wall_count(), sim.spheres().n_owned,
                        scene.startup.relax_steps)
         << std::flush;
  sim.relax();
  RunLog log((fs::path(opt.out_dir) / "log.csv").string(), scene.species);
  log.write(diagnostics(sim));
  std::vector<double> next_hook(opt.hooks.size(), 0.0), last_run(opt.hooks.size(), -1.0);
  auto run_hooks = [&](bool last) {  // each hook at t = 0, every interval, and at the end
    for (std::size_t k = 0; k < opt.hooks.size(); ++k) {
      PeriodicHook& hk = opt.hooks[k];
      const bool due = sim.time() >= next_hook[k] * (1.0 - 1e-9);
      if (!due && !(last && last_run[k] != sim.time())) continue;
      last_run[k] = sim.time();
      const auto t0 = Clock::now();
      hk.action(sim);
      hk.seconds += since(t0);
      while (next_hook[k] <= sim.time() * (1.0 + 1e-9)) next_hook[k] += hk.interval;
    }
  };
  run_hooks(false);
  double step_seconds = 0;

  const auto t_loop = Clock::now();
  auto t_progress = t_loop;
  double next_log = scene.output.log_interval;
  double dem_sphere_steps = 0;
  const double end = scene.time.end;
  RunSummary r;
  double largest_overlap = 0, largest_density_error = 0;  // over the logged steps
  while (sim.time() < end * (1.0 - 1e-12)) {
    const auto t_step = Clock::now();
    sim.step();
    step_seconds += since(t_step);
    r.safeguards.add(sim.voidage_clamped(), sim.omega_bounded());
    dem_sphere_steps += static_cast<double>(sim.dem_substeps()) * sim.spheres().n_owned;
    const bool last = sim.time() >= end * (1.0 - 1e-12);
    if (sim.time() >= next_log * (1.0 - 1e-9) || last) {
      const Diagnostics d = diagnostics(sim);
      largest_overlap = std::max(largest_overlap, d.max_overlap_over_d);
      largest_density_error = std::max(largest_density_error, d.max_density_error);
      log.write(d);
      while (next_log <= sim.time() * (1.0 + 1e-9)) next_log += scene.output.log_interval;
    }
    run_hooks(last);
    if (out && since(t_progress) >= scene.output.progress_interval) {
      t_progress = Clock::now();
      const double wall = since(t_loop);
      const double rate = sim.step_count() / wall;
      const double eta = wall * (end - sim.time()) / std::max(sim.time(), 1e-30);
      *out << fmt::format(
                  "  t = {:.4e} / {:.4e} s ({:4.1f} %)  step {}  {:.1f} steps/s  dt = {:.3e} s  "
                  "ETA {}\n",
                  sim.time(), end, 100.0 * sim.time() / end, sim.step_count(), rate, sim.dt_sph(),
                  format_duration(eta))
           << std::flush;
    }
  }
  write_sediment_output(sim, opt.out_dir);
  r.steps = sim.step_count();
  r.step_seconds = step_seconds;
  r.hooks = opt.hooks;
  r.simulated_time = sim.time();
  r.wall_seconds = since(t_start);
  const double loop = since(t_loop);
  r.fluid_particle_steps_per_second = static_cast<double>(sim.fluid().n_owned) * r.steps / loop;
  r.sphere_particle_steps_per_second = dem_sphere_steps / loop;
  if (out) {
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
  }
  if (out) *out << "sphdem: " << r.safeguards.describe(sim.fluid().n_owned) << "\n";
  r.largest_overlap = largest_overlap;
  r.largest_density_error = largest_density_error;
  if (out && sim.fluid().n_owned > 0)
    *out << fmt::format(
        "sphdem: largest density error over the logged steps {:.2g} % (expected {:.2g} % from c0; "
        "limit 1 %{})\n",
        100 * largest_density_error, 100 * sound_speed_report(scene).expected_density_error(),
        largest_density_error > 0.01 ? ": raise fluid.sound_speed" : "");
  if (out && sim.spheres().n_owned > 0)
    *out << fmt::format("sphdem: largest overlap over the logged steps {:.3g} d{}\n",
                        largest_overlap,
                        largest_overlap > scene.contact.max_overlap
                            ? fmt::format(" -- above contact.max_overlap = {}: a stiffer spring "
                                          "(contact.stiffness) or a slower impact",
                                          scene.contact.max_overlap)
                            : fmt::format(" (contact.max_overlap {})", scene.contact.max_overlap));
  if (out)
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
  return sc.time.cfl * sc.fluid.smoothing_factor * sc.fluid.spacing / sc.fluid.sound_speed;
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

std::string describe_scene(const Scene& sc, const std::vector<Scene>& presets) {
  const double resident_before = peak_resident_mib();
  Simulation sim(sc);
  std::string s;
  s += fmt::format("scene            {} ({})\n", sc.name, sc.source);
  s += fmt::format(
      "domain           {} x {} x {} m, periodic in x and y, wall at z = 0, fluid to z = {} m\n",
      sc.box.length(0), sc.box.length(1), sc.box.length(2), sc.fill_height());
  s += fmt::format(
      "SPH particles    {} fluid + {} wall ({} layers), spacing dx = {} m, h = {:.4g} m\n",
      sim.fluid_count(), sim.wall_count(), sc.fluid.wall_layers, sc.fluid.spacing,
      sc.fluid.smoothing_factor * sc.fluid.spacing);
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
        "max_density_error)\n",
        c.c0, c.mach, 100 * c.expected_density_error(), 100 * c.flow, 100 * c.hydrostatic);
  }
  s += fmt::format("drag law         {}\n", drag::drag_law_name(sc.drag));
  s += fmt::format(
      "coupling         {}{}, spheres' kernel H = {} h, the drag's {} h{}\n",
      sc.pressure_coupling == PressureCoupling::kVariational ? "variational" : "interpolated",
      sc.hydrostatic_split ? " with the hydrostatic split" : "", sc.sphere_kernel_scale,
      sc.drag_kernel_scale,
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
  const TangentialParams& tp = sc.contact.tangential;
  if (tp.model == TangentialParams::Model::kLinearHistory)
    s += fmt::format("friction         linear_history: k_t = {:.4g} N/m, mu = {}, {}\n",
                     tp.stiffness_ratio * sc.contact.normal.k, tp.friction,
                     tp.restitution > 0 ? fmt::format("e_t = {}", tp.restitution)
                                        : fmt::format("gamma_t = {} kg/s", tp.damping));
  if (sc.contact.rolling.model == RollingParams::Model::kEpsd)
    s += fmt::format("rolling          epsd: mu_r = {}, eta_r = {}\n", sc.contact.rolling.friction,
                     sc.contact.rolling.damping_ratio);
  const double drag_exchange = sim.fluid_drag_fraction() * sim.dem().fluid_drag_time();
  s += fmt::format(
      "time steps       dt_SPH = {:.4g} s (CFL {}{}), dt_DEM = {:.4g} s, {} DEM sub-steps per "
      "SPH step (more where the spheres' drag relaxes them faster: 0.1 m/(c eps) at run time)\n",
      dt, sc.time.cfl,
      drag_exchange <= dt * (1 + 1e-12)
          ? "; bound by the fluid's drag exchange with the spheres, " +
                fmt::format("{} ln(1 + 1/r) m/(c eps) at r = (1 - eps) rho_p / (eps rho_f)",
                            sim.fluid_drag_fraction())
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
  double step_wall = HUGE_VAL;  // the quickest of three more steps: lists in place, as in a run
  for (int k = 0; k < 3; ++k) {
    const auto t_step = Clock::now();
    sim.step();
    step_wall = std::min(step_wall, since(t_step));
  }
  const double run_wall = step_wall * sc.time.end / std::max(sim.dt_sph(), 1e-300);
  s += fmt::format("wall time        about {} on this machine (a step takes {:.3g} s)\n",
                   format_duration(run_wall), step_wall);
  if (!presets.empty()) s += describe_presets(sc, presets, run_wall);
  s += fmt::format(
      "memory           {:.0f} MiB for the scene: the growth of the peak resident set over "
      "the initial state and one step ({:.0f} -> {:.0f} MiB; particle arrays with their halo "
      "copies {:.1f} MiB, the rest lists and scratch; in-situ analysis not included)\n",
      peak_resident_mib() - resident_before, resident_before, peak_resident_mib(), mb);
  return s;
}

}  // namespace sphdem
