#include "analysis/watchdog.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "propagator/simulation.hpp"
#include "scene/sound_speed_rule.hpp"

namespace sphdem {

namespace {

// DEM sub-steps per contact time below which the integration of a contact is in doubt
// (the default is 20; velocity Verlet loses a linear spring past ~3).
constexpr double kFewSubSteps = 8.0;
// The largest CFL number of the presets and the validation (scene/fidelity.hpp).
constexpr double kLargestTestedCfl = 0.3;

// The alarm of particle i of `particles` (an SPH particle or a sphere, `kind` its name).
template <class Particles>
WatchdogAlarm alarm_at(const Particles& p, std::size_t i, bool sphere, std::string kind,
                       const std::string& quantity, double value, double limit,
                       const std::string& cause) {
  return WatchdogAlarm{quantity, sphere, i,     p.id[i], std::move(kind), p.x[i], p.y[i],
                       p.z[i],   value,  limit, cause};
}

WatchdogAlarm fluid_alarm(const Simulation& sim, std::size_t a, const std::string& quantity,
                          double value, double limit, const std::string& cause) {
  const FluidParticles& f = sim.fluid();
  return alarm_at(f, a, false, f.kind[a] == kWall ? "wall" : "fluid", quantity, value, limit,
                  cause);
}

WatchdogAlarm sphere_alarm(const Simulation& sim, std::size_t j, const std::string& quantity,
                           double value, double limit, const std::string& cause) {
  const DemParticles& s = sim.spheres();
  return alarm_at(s, j, true, sim.scene().species[s.species[j]].name, quantity, value, limit,
                  cause);
}

// Past the periodic faces by more than half a box: positions are wrapped into the box
// only when the lists are rebuilt (a fraction of the skin out at most), so a particle
// that far out has moved more than a box since.
bool far_past_periodic_faces(const Box& box, double x, double y, double z) {
  const double p[3] = {x, y, z};
  for (int d = 0; d < 3; ++d)
    if (box.periodic[d] &&
        (p[d] < box.lo[d] - 0.5 * box.length(d) || p[d] > box.hi[d] + 0.5 * box.length(d)))
      return true;
  return false;
}

// Why a contact went wrong: too few sub-steps per contact, or a spring too soft.
std::string contact_cause(const Simulation& sim) {
  const double per_contact = sim.contact_time() / std::max(sim.dt_dem(), 1e-300);
  if (per_contact < kFewSubSteps)
    return fmt::format(
        "dt_DEM too large for this k ({:.3g} sub-steps per contact time t_c = {:.3g} s): raise "
        "time.dem_steps_per_contact",
        per_contact, sim.contact_time());
  return "the spring is too soft for the impact or the load: raise contact.stiffness (with "
         "stiffness: auto, lower contact.max_overlap)";
}

// A fluid particle among packed spheres, or a dense suspension's: its voidage below this
// (the first layer over a wall under a bed at 0.48 reads 0.67, its kernel half empty).
constexpr double kPackedVoidage = 0.7;

// Why the fluid went wrong, most likely first: a sound speed too low for the scene
// (its expected density error, scene/sound_speed_rule.hpp, past the weakly compressible
// 1 %); a CFL number above the tested range; the coupling, where the particle `at` (-1:
// none) sits among packed spheres; a flow faster than the scene's u_m (Mach^2 of the
// fastest fluid past 0.01); else an unstable SPH step.
std::optional<std::string> named_fluid_cause(const Simulation& sim, long at) {
  const FluidParticles& f = sim.fluid();
  const Scene& sc = sim.scene();
  const SoundSpeedReport c = sound_speed_report(sc);
  if (c.expected_density_error() > 0.01)
    return fmt::format(
        "the sound speed c0 = {:.3g} m/s is too low for this scene (expected density error "
        "{:.2g} %: Mach^2 {:.2g}, g H / c0^2 {:.2g}; the weakly compressible model needs 1 %): "
        "raise fluid.sound_speed",
        c.c0, 100 * c.expected_density_error(), c.flow, c.hydrostatic);
  if (sc.time.cfl > kLargestTestedCfl)
    return fmt::format(
        "the SPH step is unstable at CFL {} (dt = {:.3g} s; the presets use 0.2-0.3): lower "
        "time.cfl",
        sc.time.cfl, sim.dt_sph());
  if (at >= 0 && f.kind[at] == kFluid && f.eps[at] < kPackedVoidage) {
    if (sc.pressure_coupling == PressureCoupling::kInterpolated)
      return fmt::format(
          "the interpolated pressure coupling is linearly unstable over packed spheres (voidage "
          "{:.3g} here; packed_bed_stability_validation): coupling.pressure_coupling: "
          "variational (not with coupling.voidage_smoothing: double)",
          f.eps[at]);
    return fmt::format(
        "the fluid pushed through the packed spheres around it (voidage {:.3g}): its Darcy "
        "pressure grows as (1 - eps)^2 / (eps^3 d^2), which the automatic c0 does not count, "
        "and the error falls as 1/c0 to 1/c0^2: {}",
        f.eps[at], twice_the_sound_speed(sc));
  }
  double v2 = 0.0;
  for (std::size_t a = 0; a < f.n_owned; ++a)
    if (f.kind[a] == kFluid && std::isfinite(f.vx[a] + f.vy[a] + f.vz[a]))
      v2 = std::max(v2, f.vx[a] * f.vx[a] + f.vy[a] * f.vy[a] + f.vz[a] * f.vz[a]);
  const double mach2 = v2 / (c.c0 * c.c0);
  if (mach2 > 0.01)
    return fmt::format(
        "the fluid moves faster than the sound speed allows (Mach^2 = {:.2g} at {:.3g} m/s; the "
        "scene's u_m = {:.3g} m/s): raise fluid.sound_speed or fluid.expected_speed",
        mach2, std::sqrt(v2), sc.fluid.expected_speed);
  return std::nullopt;
}

std::string fluid_cause(const Simulation& sim, long at = -1) {
  if (auto named = named_fluid_cause(sim, at)) return *named;
  return fmt::format("the SPH step is unstable (c0 = {:.3g} m/s, dt = {:.3g} s): lower time.cfl",
                     sim.scene().fluid.sound_speed, sim.dt_sph());
}

// A density error past its bound with every state finite: unless a named cause applies,
// the flow's pressure is larger than c0's rule expects (a suspension's voidage fluctuating
// with no free surface to relieve it: in a periodic column it grows to a plateau several
// times the rule's figure, falling as 1/c0 to 1/c0^2, bench/TRADEOFF.md), not an unstable
// step (which leaves the bound by far within a few steps and then the state non-finite).
std::string density_cause(const Simulation& sim, long at) {
  if (auto named = named_fluid_cause(sim, at)) return *named;
  return fmt::format(
      "the flow's pressure is larger than c0 = {:.3g} m/s leads to expect (the spheres' voidage "
      "fluctuating, no free surface to relieve it), and the error falls as 1/c0 to 1/c0^2: {}",
      sim.scene().fluid.sound_speed, twice_the_sound_speed(sim.scene()));
}

// Why a particle went wrong (non-finite, through the wall, out of the box): the contacts'
// integration, else the fluid's (a step past the tested CFL takes the spheres with it),
// else `otherwise` (a spring too soft, a box with no room for the motion).
std::string instability_cause(const Simulation& sim, const std::string& otherwise) {
  const double per_contact = sim.contact_time() / std::max(sim.dt_dem(), 1e-300);
  if (sim.spheres().n_owned > 0 && per_contact < kFewSubSteps) return contact_cause(sim);
  if (sim.fluid_count() > 0)
    if (auto named = named_fluid_cause(sim, -1)) return *named;
  return otherwise;
}

}  // namespace

std::optional<WatchdogAlarm> watchdog_check(const Simulation& sim, const WatchdogSpec& limits,
                                            WatchdogReading* reading) {
  if (!limits.enabled) return std::nullopt;
  const FluidParticles& f = sim.fluid();
  const DemParticles& s = sim.spheres();
  const Scene& sc = sim.scene();
  const Box& box = sim.params().box;
  const long nf = static_cast<long>(f.n_owned), ns = static_cast<long>(s.n_owned);
  // Non-finite values, and every other breach with its worst particle, in one pass each.
  long bad_fluid = nf, bad_sphere = ns;
  long out_fluid = nf, out_sphere = ns;
  double worst_density = 0.0, worst_overlap = 0.0;
  long worst_density_at = -1, worst_overlap_at = -1;
  const double rho0 = sim.eos().rho0;
  const double floor_z = box.lo[2] - (sc.fluid.wall_layers + 1) * sc.fluid.spacing;
  const double top_z = box.hi[2];
  // The free surface sits at the box's top in a full column: a surface particle may bob a
  // kernel support 2h above it (the cell list keeps it in the top cell, its neighbours all
  // below); one past that has no neighbour left and has left the fluid.
  const double fluid_top_z = top_z + kernel::kSupport * sc.fluid.lattice_h();
  const bool walled = !box.periodic[2];  // a column periodic in z has no floor or top
  for (long a = 0; a < nf; ++a) {
    if (!std::isfinite(f.x[a] + f.y[a] + f.z[a] + f.vx[a] + f.vy[a] + f.vz[a] + f.rho[a])) {
      bad_fluid = std::min(bad_fluid, a);
      continue;
    }
    const bool outside = (walled && (f.z[a] < floor_z || f.z[a] > fluid_top_z)) ||
                         far_past_periodic_faces(box, f.x[a], f.y[a], f.z[a]);
    if (outside) out_fluid = std::min(out_fluid, a);
    if (f.kind[a] != kFluid) continue;
    const double e = std::abs(f.rho[a] / (f.eps[a] * rho0) - 1.0);
    if (e > worst_density) {
      worst_density = e;
      worst_density_at = a;
    }
  }
  for (long j = 0; j < ns; ++j) {
    if (!std::isfinite(s.x[j] + s.y[j] + s.z[j] + s.vx[j] + s.vy[j] + s.vz[j] + s.wx[j] + s.wy[j] +
                       s.wz[j])) {
      bad_sphere = std::min(bad_sphere, j);
      continue;
    }
    const bool outside = (walled && (s.z[j] < box.lo[2] || s.z[j] > top_z)) ||
                         far_past_periodic_faces(box, s.x[j], s.y[j], s.z[j]);
    if (outside) out_sphere = std::min(out_sphere, j);
    const double o = s.overlap_max[j] / (2.0 * s.radius[j]);
    if (o > worst_overlap) {
      worst_overlap = o;
      worst_overlap_at = j;
    }
  }
  if (reading) *reading = WatchdogReading{worst_density, worst_overlap};
  const double inf = HUGE_VAL;
  if (bad_sphere < ns)
    return sphere_alarm(sim, bad_sphere, "non-finite position or velocity", NAN, inf,
                        instability_cause(sim, contact_cause(sim)));
  if (bad_fluid < nf)
    return fluid_alarm(sim, bad_fluid, "non-finite position, velocity or density", NAN, inf,
                       fluid_cause(sim));
  if (out_sphere < ns) {
    const bool below = walled && s.z[out_sphere] < box.lo[2];
    return sphere_alarm(
        sim, out_sphere, below ? "left the domain through the bottom wall" : "left the domain",
        s.z[out_sphere], below ? box.lo[2] : top_z,
        below ? instability_cause(sim, contact_cause(sim))
              : instability_cause(sim,
                                  "thrown past the top of the box: give it room above the "
                                  "column (domain.size), or find what threw it"));
  }
  if (out_fluid < nf) {
    const bool below = walled && f.z[out_fluid] < floor_z;
    return fluid_alarm(
        sim, out_fluid, below ? "passed through the bottom wall" : "left the domain",
        f.z[out_fluid], below ? floor_z : fluid_top_z,
        below ? fluid_cause(sim)
              : instability_cause(sim, "thrown past the top of the box: " + fluid_cause(sim) +
                                           " (or give the column room above it: "
                                           "domain.size)"));
  }
  if (worst_overlap > limits.overlap)
    return sphere_alarm(sim, worst_overlap_at, "overlap / d", worst_overlap, limits.overlap,
                        contact_cause(sim));
  if (worst_density > limits.density_error)
    return fluid_alarm(sim, worst_density_at, "density error |rho/(eps rho0) - 1|", worst_density,
                       limits.density_error, density_cause(sim, worst_density_at));
  const double fluid_count = static_cast<double>(std::max<std::size_t>(sim.fluid_count(), 1));
  const double floor_share = sim.voidage_clamped() / fluid_count;
  const double clamp_share = sim.omega_bounded() / fluid_count;
  if (floor_share > limits.safeguard_share || clamp_share > limits.safeguard_share) {
    // the particle: the lowest voidage (floor), or the first whose Omega is at a bound
    const bool floor = floor_share > limits.safeguard_share;
    long at = -1;
    for (long a = 0; a < nf; ++a) {
      if (f.kind[a] != kFluid) continue;
      if (floor ? (at < 0 || f.eps[a] < f.eps[at]) : (f.omega[a] == 0.5 || f.omega[a] == 2.0)) {
        at = a;
        if (!floor) break;
      }
    }
    at = std::max(at, 0L);
    if (floor)
      return fluid_alarm(
          sim, at, "share of the fluid held at the voidage floor", floor_share,
          limits.safeguard_share,
          fmt::format("the spheres pack closer than the fluid resolves: the voidage floor {} "
                      "replaces the model on {:.2g} % of the fluid (coupling.voidage_floor; a "
                      "finer fluid.spacing, or spheres smaller than it)",
                      sc.voidage_floor, 100 * floor_share));
    return fluid_alarm(
        sim, at, "share of the fluid with its Omega term clamped to [0.5, 2]", clamp_share,
        limits.safeguard_share,
        "h varies faster than the kernel resolves (a jump of the voidage or of the density "
        "across one kernel): " +
            fluid_cause(sim));
  }
  return std::nullopt;
}

std::string describe_alarm(const WatchdogAlarm& w, long step, double time) {
  const std::string what =
      w.sphere ? fmt::format("sphere id {} (species {})", w.id, w.kind)
               : fmt::format("{} particle id {}", w.kind == "wall" ? "wall" : "fluid", w.id);
  const std::string value = std::isnan(w.value)
                                ? std::string()
                                : fmt::format(": {:.4g} (bound {:.4g})", w.value, w.limit);
  return fmt::format(
      "watchdog at step {} (t = {:.6g} s): {} at ({:.6g}, {:.6g}, {:.6g}) m: {}{}; likely cause: "
      "{}",
      step, time, what, w.x, w.y, w.z, w.quantity, value, w.cause);
}

}  // namespace sphdem
