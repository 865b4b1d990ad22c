// A water column at rest (thesis §4.2 geometry, narrowed) keeps its hydrostatic
// pressure, height and density (and no excess pore pressure at its base, Zhao et al.
// 2014); a held sphere in it feels the buoyancy V rho_f g; a neutral layer of spheres
// on the wall adds nothing to the fluid's excess load on it.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include "analysis/diagnostics.hpp"
#include "analysis/pore_pressure.hpp"
#include "propagator/simulation.hpp"
#include "scene/scene.hpp"
#include "scene/sound_speed_rule.hpp"

using namespace sphdem;

namespace {
const char* kColumn = R"(
name: column
domain: {size: [0.0016, 0.0016, 0.006]}
fluid: {density: 1000, viscosity: 8.9e-4, spacing: 2.0e-4}
startup: {relax_steps: 0}
time: {end: 0.01}
)";
}

TEST(Hydrostatic, ColumnAtRestKeepsPressureHeightAndDensity) {
  const Scene sc = load_scene_text(kColumn, "column.yaml");
  Simulation sim(sc);
  const double H = sc.fill_height(), g = 9.81, rho_f = sc.fluid.density, dx = sc.fluid.spacing;
  double top0 = 0;
  for (std::size_t a = 0; a < sim.fluid().n_owned; ++a) top0 = std::max(top0, sim.fluid().z[a]);
  // one acoustic period 4H/c0 and more, with no damping
  const double period = 4.0 * H / sc.fluid.sound_speed;
  while (sim.time() < 1.5 * period) sim.step();
  const FluidParticles& f = sim.fluid();
  // layer means (layers are the initial lattice rows, by id)
  std::map<long, std::pair<double, int>> pz, zz;
  double top = 0, vmax = 0;
  for (std::size_t a = 0; a < f.n_owned; ++a) {
    if (f.kind[a] != kFluid) continue;
    const long layer = std::lround(f.z[a] / dx - 0.5);
    pz[layer].first += f.P[a];
    ++pz[layer].second;
    top = std::max(top, f.z[a]);
    vmax = std::max(vmax, std::sqrt(f.vx[a] * f.vx[a] + f.vy[a] * f.vy[a] + f.vz[a] * f.vz[a]));
  }
  double worst = 0;
  for (const auto& [layer, acc] : pz) {
    const double depth = H - (layer + 0.5) * dx;
    if (depth < 3 * dx) continue;  // the relative error of a near-zero pressure is meaningless
    const double p = acc.first / acc.second, p_ref = rho_f * g * depth;
    worst = std::max(worst, std::abs(p / p_ref - 1.0));
  }
  const Diagnostics d = diagnostics(sim);
  std::printf(
      "after %ld steps (%.3g s): worst layer pressure error %.3f %%, top moved %.3f %% of H, "
      "max |rho/rho_0 - 1| %.3f %%, max |u| %.3g m/s\n",
      sim.step_count(), sim.time(), 100 * worst, 100 * (top - top0) / H, 100 * d.max_density_error,
      vmax);
  EXPECT_LT(worst, 0.02);                     // issue #2: within 2 %
  EXPECT_LT(std::abs(top - top0) / H, 0.01);  // physics.md §1: height within 1 %
  EXPECT_LT(d.max_density_error, 0.01);       // and density within 1 % (c0 = 10 sqrt(2 g H))
  EXPECT_LT(vmax, 1e-3);                      // at rest: far below any settling speed
  // check's estimate of the density error (scene/sound_speed_rule.hpp): at rest it is the
  // base's compression under the column, g H / c0^2 (the Tait law's curvature and the
  // kernel's sampling of the deepest layer give the rest).
  const double expected = sound_speed_report(sc).expected_density_error();
  std::printf("expected density error %.3f %% (g H/c0^2), measured %.3f %%\n", 100 * expected,
              100 * d.max_density_error);
  EXPECT_NEAR(d.max_density_error / expected, 1.0, 0.1);  // measured when written: -2.8 %
}

// With each pressure coupling (interpolated; variational; variational with the
// hydrostatic split, where the buoyancy is analytic and the pairs carry P - P_h; and
// variational with the spheres' kernel twice the fluid's, coupling.sphere_kernel_scale).
TEST(Hydrostatic, HeldSphereFeelsBuoyancy) {
  const std::vector<std::vector<std::string>> couplings = {
      {"coupling.pressure_coupling=interpolated"},
      {"coupling.pressure_coupling=variational", "coupling.hydrostatic_split=false"},
      {"coupling.pressure_coupling=variational", "coupling.hydrostatic_split=true"},
      {"coupling.pressure_coupling=variational", "coupling.hydrostatic_split=false",
       "coupling.sphere_kernel_scale=2"}};
  for (const auto& sets : couplings) {
    std::vector<std::string> all = sets;
    all.push_back("startup.relax_steps=200");
    const Scene sc = load_scene_text(std::string(kColumn) + R"(
species: [{name: glass, diameter: 1.0e-4, density: 2500}]
particles: [{type: single, species: glass, position: [0.0008, 0.0008, 0.003]}]
)",
                                     "column_sphere.yaml", all);
    Simulation sim(sc);
    sim.relax();
    const DemParticles& s = sim.spheres();
    const double buoyancy = s.volume(0) * sc.fluid.density * 9.81;
    std::string name = "interpolated";
    for (const std::string& set : sets)
      name = set.substr(set.find('.') + 1) + (name == "interpolated" ? "" : ", " + name);
    std::printf("%s: fluid force on the held sphere: (%.3g, %.3g, %.5g) N; V rho_f g = %.5g N\n",
                name.c_str(), s.fx[0], s.fy[0], s.fz[0], buoyancy);
    // (2.68) at rest: V (-grad P) with grad P = rho_f g (the reaction keeps it so)
    EXPECT_NEAR(s.fz[0] / buoyancy, 1.0, 0.02);
    EXPECT_LT(std::hypot(s.fx[0], s.fy[0]) / buoyancy, 0.01);
  }
}

// The variational coupling switches each sphere's force of the last sub-step from the
// pressure gradient it felt to the new one (DemSubstepper::switch_pressure_force), so
// that what the sphere receives is what the fluid got. The g it felt is the one the last
// step left; the interpolation of the next evaluation overwrites s.g, so it must be kept
// before that (keeping it after made the switch add V (g_new - g_interpolated)).
TEST(VariationalCoupling, SwitchStartsFromTheGradientTheSpheresFelt) {
  const Scene sc = load_scene_text(
      std::string(kColumn) + R"(
species: [{name: glass, diameter: 1.0e-4, density: 2500}]
particles:
  - {type: single, species: glass, position: [0.0008, 0.0008, 0.003]}
  - {type: single, species: glass, position: [0.0004, 0.0011, 0.002]}
)",
      "column_spheres.yaml", {"coupling.pressure_coupling=variational", "startup.relax_steps=20"});
  Simulation sim(sc);
  sim.relax();
  const DemParticles& s = sim.spheres();
  for (int k = 0; k < 5; ++k) {
    const std::vector<double> gx = s.gx, gy = s.gy, gz = s.gz;  // what the spheres feel now
    sim.step();
    for (std::size_t j = 0; j < s.n_owned; ++j) {
      EXPECT_EQ(sim.dem().kept_pressure_gradient(0)[j], gx[j]) << "step " << k << " sphere " << j;
      EXPECT_EQ(sim.dem().kept_pressure_gradient(1)[j], gy[j]) << "step " << k << " sphere " << j;
      EXPECT_EQ(sim.dem().kept_pressure_gradient(2)[j], gz[j]) << "step " << k << " sphere " << j;
    }
  }
}

TEST(ExcessPorePressure, WaterAtRestHasNone) {
  const Scene sc = load_scene_text(kColumn, "column.yaml");
  Simulation sim(sc);
  // the hydrostatic start is P = rho_f g (H - z) exactly
  EXPECT_LT(std::abs(diagnostics(sim).excess_pore_pressure_base), 1e-12);
  const double period = 4.0 * sc.fill_height() / sc.fluid.sound_speed;
  double worst = 0;
  while (sim.time() < 1.5 * period) {
    sim.step();
    worst = std::max(worst, std::abs(diagnostics(sim).excess_pore_pressure_base));
  }
  std::printf("water at rest over 1.5 acoustic periods: max |u_base| / (rho_f g H) = %.2e\n",
              worst);
  EXPECT_LT(worst, 0.01);  // physics.md §1: the column at rest keeps its pressure within 1 %
}

// The fluid's load on the wall (analysis/pore_pressure.hpp: fluid_load_base) with a rigid
// layer of neutrally buoyant spheres (epsilon 0.9) near the wall, within reach of the
// wall particles' kernel (it stays where it is, so no inertia enters the balance). At
// rest the fluid carries its own weight and, by action-reaction, the buoyancy it gives
// the spheres, rho_f g V: both are the clear column's load, so the excess is 0. With the
// variational coupling part of the buoyancy comes from the wall particles' pairs straight onto the
// spheres (near the wall the pairs carry the absolute pressure: 3.1 times the buoyancy up
// from the wall, 2.1 times down from the fluid above); the load must count that path.
namespace {
bool absolute_pairs_of(const std::vector<std::string>& sets) {
  return sets.size() == 2 && sets[1] == "coupling.hydrostatic_split=false";
}
}  // namespace

TEST(FluidLoadOnTheWall, NeutralLayerNearTheWallAddsNoExcess) {
  const std::vector<std::vector<std::string>> couplings = {
      {"coupling.pressure_coupling=interpolated"},
      {"coupling.pressure_coupling=variational", "coupling.hydrostatic_split=false"},
      {"coupling.pressure_coupling=variational", "coupling.hydrostatic_split=true"}};
  for (auto sets : couplings) {
    const std::string name = sets.size() == 1          ? sets[0].substr(sets[0].find('=') + 1)
                             : absolute_pairs_of(sets) ? "variational"
                                                       : "variational, split";
    const bool absolute_pairs = absolute_pairs_of(sets);
    sets.push_back("startup.relax_steps=200");
    const Scene sc = load_scene_text(std::string(kColumn) + R"(
species: [{name: neutral, diameter: 1.0e-4, density: 1000}]
particles: [{type: lattice, species: neutral, voidage: 0.9, min: [0, 0, 1.0e-4], max: [0.0016, 0.0016, 5.0e-4],
             rigid: true}]
)",
                                     "column_sphere.yaml", sets);
    Simulation sim(sc);
    sim.relax();
    const FluidParticles& f = sim.fluid();
    const DemParticles& s = sim.spheres();
    const double g = 9.81, area = sc.box.length(0) * sc.box.length(1), H = sc.fill_height();
    const BasePorePressure base{sc.fluid.density, g, H, sc.fluid.spacing};
    // the spheres' buoyancy in the load's unit, and one acoustic period's mean of the load
    double volume = 0;
    for (std::size_t j = 0; j < s.n_owned; ++j) volume += s.volume(j);
    const double buoyancy = volume / (area * H);
    const double period = 4.0 * H / sc.fluid.sound_speed, t0 = sim.time();
    double load = 0, without_wall_pairs = 0, dur = 0;
    while (sim.time() < t0 + period) {
      const double dt = sim.dt_sph();
      load += diagnostics(sim).fluid_load_base * dt;
      without_wall_pairs += fluid_load_base(f, s, 0.0, sim.hydrostatic_split(), area, base) * dt;
      dur += dt;
      sim.step();
    }
    load /= dur;
    without_wall_pairs /= dur;
    std::printf(
        "%s, %zu spheres: fluid's load on the wall %.3g of their buoyancy; without the wall "
        "particles' "
        "pairs with the spheres %.3g\n",
        name.c_str(), s.n_owned, load / buoyancy, without_wall_pairs / buoyancy);
    // Measured: 0.0014 (interpolated), 0.0002 (variational; without the wall pairs -3.14),
    // -0.0015 (variational, split).
    EXPECT_LT(std::abs(load / buoyancy), 0.01);
    // With the variational pairs on the absolute pressure the wall pairs carry a share the
    // test can see (with the split, on P - P_h: -0.010; the split's analytic force is in
    // the load instead, and leaving it out would be the whole column's weight)
    if (absolute_pairs) {
      EXPECT_GT(std::abs(without_wall_pairs - load) / buoyancy, 0.1);
    }
  }
}

// The hydrostatic split keeps gravity at the free surface (sph/hydrostatic_pressure.hpp):
// a drop, one top-layer particle lifted out of its neighbours' reach (3 h), falls freely,
// g t^2 / 2, as with the split off. With P_h the depth to the top all the way up, -grad P_h
// cancelled the drop's gravity and nothing else acted on it: it hung where it was, and a
// surface particle lifted by a wave floated off (the clear liquid over the 1 m sand
// column's bed rose 4-7 mm/s until the run stopped; the reduced column's rose 1 mm/s).
TEST(Hydrostatic, LiftedDropFallsWithTheSplit) {
  for (const char* split : {"false", "true"}) {
    const Scene sc = load_scene_text(kColumn, "column.yaml",
                                     {"coupling.pressure_coupling=variational",
                                      std::string("coupling.hydrostatic_split=") + split});
    Simulation sim(sc);
    FluidParticles& f = sim.fluid();
    std::size_t top = 0;
    for (std::size_t a = 0; a < f.n_owned; ++a)
      if (f.kind[a] == kFluid && f.z[a] > f.z[top]) top = a;
    const auto id = f.id[top];
    const double lift = 3.0 * f.h[top], z0 = f.z[top] + lift, t_fall = 0.01;
    f.z[top] = z0;
    while (sim.time() < t_fall) sim.step();
    double z = 0;
    for (std::size_t a = 0; a < f.n_owned; ++a)  // the list builds reorder the particles
      if (f.id[a] == id) z = f.z[a];
    const double fall = z0 - z, free_fall = 0.5 * 9.81 * sim.time() * sim.time();
    std::printf(
        "split %s: a drop lifted %.3g mm above the top layer fell %.4g mm in %.3g s "
        "(free fall %.4g mm)\n",
        split, 1e3 * lift, 1e3 * fall, sim.time(), 1e3 * free_fall);
    EXPECT_NEAR(fall / free_fall, 1.0, 0.02) << "split " << split;
  }
}

// The split the solver runs (compile_step_params): P_h the depth below the fill height
// times rho_f g, with its gradient rho_f g, and zero from the fill height up. Session 28
// documented a taper over the top (2 sigma + 1/2) dx that no run had; this reads what the
// step is given, not a split the test builds itself.
TEST(Hydrostatic, SolversSplitIsTheDepthBelowTheFillHeight) {
  const Scene sc =
      load_scene_text(kColumn, "column.yaml", {"coupling.pressure_coupling=variational"});
  ASSERT_TRUE(sc.hydrostatic_split);
  const HydrostaticPressure ph = Simulation(sc).hydrostatic_split();  // a copy: the step goes
  const double H = sc.fill_height(), dx = sc.fluid.spacing, rho_g = sc.fluid.density * 9.81;
  for (const double depth : {0.5 * dx, 3.0 * dx, 0.5 * H, H}) {  // the top layer to the base
    EXPECT_NEAR(ph(H - depth), rho_g * depth, 1e-9 * rho_g * depth) << depth / dx << " dx";
    EXPECT_NEAR(ph.gradient_z(H - depth), -rho_g, 1e-9 * rho_g) << depth / dx << " dx";
  }
  for (const double above : {0.0, 0.5 * dx, 3.0 * dx}) {
    EXPECT_EQ(ph(H + above), 0.0) << above / dx << " dx above";
    EXPECT_EQ(ph.gradient_z(H + above), 0.0) << above / dx << " dx above";
  }
  const Scene off = load_scene_text(
      kColumn, "column.yaml",
      {"coupling.pressure_coupling=variational", "coupling.hydrostatic_split=false"});
  EXPECT_EQ(Simulation(off).hydrostatic_split()(0.0), 0.0);  // no split: P_h is zero
}
