// The extremes (issue 15): scenes past the sources' ranges either run stable and physical
// or are refused up front by scene/scene_limits.hpp with the key to change. A row that
// runs must keep every state finite, its density error under the weakly compressible
// limit (1 %), the voidage floor and the Omega clamp unused, the fluid at rest where the
// scene is at rest, and a settling sphere's slip within 5 % of its drag law's terminal
// speed, and a suspension's bulk its hindered speed (4.4) within 5 % (the rows that
// discriminate: stability alone holds for a wrong drag or a wrong buoyancy).
// `extremes_test` runs the short variants (ctest label `extremes`); `extremes_test --full`
// runs each row for its full time (validation/README.md).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <ostream>
#include <string>
#include <vector>

#include "../validation/closed_forms.hpp"
#include "analysis/diagnostics.hpp"
#include "coupling/drag_exchange.hpp"
#include "propagator/simulation.hpp"
#include "scene/contact_stiffness_rule.hpp"
#include "scene/scene.hpp"
#include "scene/scene_limits.hpp"

using namespace sphdem;

namespace {

bool g_full = false;  // --full: each row's full time

// One sphere of diameter d and density rho_p released at rest at height z0 in a column
// of fluid (rho_f, mu), fluid spacing dx, box w x w x H.
struct SphereScene {
  double d = 1e-4, rho_p = 2500, rho_f = 1000, mu = 8.9e-4, dx = 2e-4, w = 4e-3, H = 6e-3,
         z0 = 4.8e-3;
  const char* drag = "di_felice";
  std::string yaml() const {
    return fmt::format(R"(
name: extreme_sphere
domain: {{size: [{w}, {w}, {H}]}}
fluid: {{density: {rho_f}, viscosity: {mu}, spacing: {dx}}}
species: [{{name: s, diameter: {d}, density: {rho_p}}}]
particles: [{{type: single, species: s, position: [{c}, {c}, {z0}]}}]
drag: {{law: {drag}}}
startup: {{relax_steps: 100}}
)",
                       fmt::arg("w", w), fmt::arg("H", H), fmt::arg("rho_f", rho_f),
                       fmt::arg("mu", mu), fmt::arg("dx", dx), fmt::arg("d", d),
                       fmt::arg("rho_p", rho_p), fmt::arg("c", 0.5 * w), fmt::arg("z0", z0),
                       fmt::arg("drag", drag));
  }
};

// A random suspension or bed of spheres d in water over the lower part of a w x w x H column.
struct BedScene {
  double d = 1e-4, rho_p = 2500, dx = 2e-4, w = 1.6e-3, H = 3e-3, top = 2e-3, voidage = 0.9;
  std::string yaml() const {
    return fmt::format(R"(
name: extreme_bed
domain: {{size: [{w}, {w}, {H}]}}
fluid: {{density: 1000, viscosity: 1.0e-3, spacing: {dx}}}
species: [{{name: s, diameter: {d}, density: {rho_p}}}]
particles:
  - {{type: random, species: s, voidage: {eps}, min: [0, 0, 0], max: [{w}, {w}, {top}], seed: 1}}
drag: {{law: di_felice}}
startup: {{relax_steps: 100}}
)",
                       fmt::arg("w", w), fmt::arg("H", H), fmt::arg("dx", dx), fmt::arg("d", d),
                       fmt::arg("rho_p", rho_p), fmt::arg("eps", voidage), fmt::arg("top", top));
  }
};

// Clear water, no spheres, at rest in a w x w x H column.
std::string water_column(double w, double H, double dx) {
  return fmt::format(R"(
name: extreme_water
domain: {{size: [{w}, {w}, {H}]}}
fluid: {{density: 1000, viscosity: 1.0e-3, spacing: {dx}}}
startup: {{relax_steps: 100}}
)",
                     fmt::arg("w", w), fmt::arg("H", H), fmt::arg("dx", dx));
}

struct Row {
  std::string name, regime;
  std::string yaml;
  std::vector<std::string> sets;
  double end_short = 0, end_full = 0;  // simulated time (s)
  std::string refused_key;             // non-empty: check must refuse the scene on this key
  bool terminal = false;               // species 0's slip against its law's terminal speed
  bool at_rest = false;                // the fluid's kinetic energy must not grow
  bool overlap = false;        // the largest overlap within check's expected (impact, at rest)
  bool hindered = false;       // the suspension's bulk spheres against its hindered speed (4.4)
  bool implicit_drag = false;  // the step past what an explicit drag exchange would allow,
                               // and the bulk's superficial slip (not its fall) against (4.4)
};

void PrintTo(const Row& row, std::ostream* os) {
  *os << row.name;
}

// The law's terminal speed in clear fluid: Stokes (2.73) or Di Felice's single sphere
// (the block formula of closed_forms.hpp at eps = 1).
double terminal_speed(const Scene& sc) {
  const SpeciesSpec& sp = sc.species.at(0);
  const double g = std::abs(sc.gravity[2]);
  if (std::holds_alternative<drag::Stokes>(sc.drag))
    return theory::StokesSettling(sp.diameter, sp.density, sc.fluid.density, sc.fluid.viscosity, g)
        .v_terminal;
  return theory::di_felice_block_slip(sp.diameter, sp.density, sc.fluid.density, sc.fluid.viscosity,
                                      g, 1.0);
}

std::vector<Row> rows() {
  std::vector<Row> r;
  auto sphere = [](SphereScene s) { return s.yaml(); };
  // density ratio, one 100 um sphere in a 2 mm wide column (Stokes time rho_p d^2 / 18 mu;
  // 6 of them short, 10 full); 2.5 is the thesis sphere, Re_t 0.86
  for (double ratio : {1.05, 1.2, 2.5, 10.0}) {
    SphereScene s;
    s.rho_p = 1000 * ratio, s.w = 2e-3;
    const double tau = s.rho_p * s.d * s.d / (18 * s.mu);
    r.push_back({fmt::format("density_ratio_{}_sphere", ratio),
                 fmt::format("rho_p/rho_f = {}, one 100 um sphere (Di Felice)", ratio),
                 sphere(s),
                 {},
                 6 * tau,
                 10 * tau,
                 "",
                 true});
  }
  {
    SphereScene s;
    s.rho_p = 10000, s.w = 2e-3, s.drag = "stokes";
    r.push_back({"density_ratio_10_sphere_stokes",
                 "rho_p/rho_f = 10 with Stokes' law (Re_t 6)",
                 sphere(s),
                 {},
                 0,
                 0,
                 "drag.law"});
  }
  // density ratio, a suspension at eps 0.9: its bulk settles at the hindered speed
  for (double ratio : {1.05, 1.2, 2.5, 10.0}) {
    BedScene b;
    b.rho_p = 1000 * ratio;
    Row row{fmt::format("density_ratio_{}_suspension", ratio),
            fmt::format("rho_p/rho_f = {}, a suspension at eps 0.9", ratio),
            b.yaml(),
            {},
            ratio > 5 ? 0.02 : 0.01,
            0.05,
            ""};
    row.hindered = true;
    r.push_back(row);
  }
  // particle Reynolds number, each with Di Felice's law (creeping flow to 1e4); dx = 1.5 d
  {
    SphereScene s;  // 1 mm glass in a glycerol-like liquid: Re_t 9e-4
    s.d = 1e-3, s.rho_f = 1260, s.mu = 1.0, s.dx = 1.5e-3, s.w = 1.2e-2, s.H = 2.1e-2,
    s.z0 = 1.5e-2;
    r.push_back({"reynolds_1e-3",
                 "Re_t = 9e-4: 1 mm glass, mu = 1 Pa s",
                 sphere(s),
                 {},
                 2e-3,
                 4e-3,
                 "",
                 true});
  }
  {
    SphereScene s;  // 1 mm glass in water: Re_t 134
    s.d = 1e-3, s.mu = 1e-3, s.dx = 1.5e-3, s.w = 1.2e-2, s.H = 6e-2, s.z0 = 5e-2;
    r.push_back(
        {"reynolds_100", "Re_t = 134: 1 mm glass in water", sphere(s), {}, 0.1, 0.2, "", true});
  }
  {
    SphereScene s;  // 3 mm glass in water: Re_t 924
    s.d = 3e-3, s.mu = 1e-3, s.dx = 4.5e-3, s.w = 3.6e-2, s.H = 0.1485, s.z0 = 0.12;
    r.push_back(
        {"reynolds_1000", "Re_t = 924: 3 mm glass in water", sphere(s), {}, 0.25, 0.35, "", true});
  }
  // voidage from a packed bed to a suspension (the single sphere is above)
  // (a bed starts in contact: random at eps 0.42, placed by collective rearrangement with
  // its pairs 1e-3 d apart, scene/collective_rearrangement.hpp; an fcc lattice at that
  // voidage would leave gaps of 6-7 % of d)
  {
    BedScene b;
    b.voidage = 0.42, b.top = 1e-3;
    r.push_back({"voidage_0.42_bed",
                 "a random bed at eps 0.42 in contact under water",
                 b.yaml(),
                 {},
                 0.01,
                 0.05,
                 ""});
  }
  {
    BedScene b;
    b.voidage = 0.7;
    Row row{"voidage_0.7", "a suspension at eps 0.7", b.yaml(), {}, 0.01, 0.05, ""};
    row.hindered = true;
    r.push_back(row);
  }
  // fine particles: 20 um in a packed bed, where an explicit drag exchange would bind the step
  {
    BedScene b;
    b.d = 2e-5, b.rho_p = 2650, b.dx = 4e-5, b.w = 4e-4, b.H = 8e-4, b.top = 3e-4;
    b.voidage = 0.42;
    r.push_back({"fine_20um_bed",
                 "20 um silt in a random bed at eps 0.42 in contact",
                 b.yaml(),
                 {},
                 5e-4,
                 2e-3,
                 ""});
  }
  // ... and in a dense suspension in a viscous liquid, where the drag exchange is
  // semi-implicit (coupling/drag_exchange.hpp): the bulk's slip against (4.4)
  {
    BedScene b;
    b.d = 2e-5, b.rho_p = 2650, b.dx = 4e-5, b.w = 4e-4, b.H = 8e-4, b.top = 6e-4;
    b.voidage = 0.7;
    Row row{"fine_20um_suspension",
            "20 um silt in a suspension at eps 0.7, mu = 8 mPa s",
            b.yaml(),
            {"fluid.viscosity=8e-3"},
            1e-2,
            1e-2,
            ""};
    row.hindered = true;
    row.implicit_drag = true;
    r.push_back(row);
  }
  // contact stiffness over six decades (the automatic spring: 0.24 N/m), a suspension at
  // eps 0.7 reaching the floor; its largest overlap within check's expected one
  for (double k : {1e-3, 1e-2, 1e-1, 1.0, 10.0, 100.0, 1000.0}) {
    BedScene b;
    b.top = 1e-3, b.voidage = 0.7;
    Row row{fmt::format("stiffness_{}", k),
            fmt::format("k = {} N/m, a suspension at eps 0.7 reaching the floor", k),
            b.yaml(),
            {fmt::format("contact.stiffness={}", k)},
            0.01,
            0.05,
            ""};
    if (k < 0.05) row.refused_key = "contact.stiffness";
    row.overlap = true;
    r.push_back(row);
  }
  // h/d from 1 to 8 (h = 1.5 dx, dx = 200 um): one sphere of d = h / ratio, 1500 kg/m^3
  // (Re_t <= 1.2), Stokes' law
  for (double ratio : {1.0, 2.0, 3.0, 4.0, 8.0}) {
    SphereScene s;
    s.drag = "stokes", s.rho_p = 1500, s.w = 2e-3, s.d = 1.5 * s.dx / ratio;
    const double tau = s.rho_p * s.d * s.d / (18 * s.mu);
    Row row{fmt::format("h_over_d_{}", ratio),
            fmt::format("h/d = {}: one {:.3g} um sphere (Stokes)", ratio, 1e6 * s.d),
            sphere(s),
            {},
            std::max(6 * tau, 2e-3),
            std::max(10 * tau, 4e-3),
            "",
            true};
    if (ratio < 2.5) row.refused_key = "fluid.spacing";
    r.push_back(row);
  }
  // no spheres; a column one kernel wide; a 2 m column
  r.push_back({"no_spheres",
               "clear water at rest, 6 mm",
               water_column(2e-3, 6e-3, 2e-4),
               {},
               0.01,
               0.05,
               "",
               false,
               true});
  {
    SphereScene s;  // 2 h = 0.6 mm wide
    s.w = 6e-4, s.drag = "stokes";
    r.push_back({"one_kernel_wide",
                 "a column 2 h wide with one sphere",
                 sphere(s),
                 {},
                 0,
                 0,
                 "domain.size"});
  }
  {
    SphereScene s;  // a 2.8 mm sand grain in 2 m of water: Re_t 870, c0 63 m/s
    s.d = 2.8e-3, s.rho_p = 2650, s.mu = 1e-3, s.dx = 0.02, s.w = 0.16, s.H = 2.0, s.z0 = 1.9;
    r.push_back(
        {"column_2m", "a 2.8 mm sand grain in a 2 m column", sphere(s), {}, 0.2, 0.5, "", true});
  }
  return r;
}

class Extremes : public ::testing::TestWithParam<Row> {};

TEST_P(Extremes, StableAndPhysicalOrRefused) {
  const Row& row = GetParam();
  RecordProperty("regime", row.regime);
  Scene sc;
  try {
    sc = load_scene_text(row.yaml, row.name, row.sets);
  } catch (const SceneError& e) {  // the loader's own limits (a box narrower than the kernel)
    const bool named =
        !row.refused_key.empty() &&
        std::string(e.what()).find("key '" + row.refused_key + "'") != std::string::npos;
    EXPECT_TRUE(named) << e.what();
    std::printf("%s: refused (%s)\n", row.name.c_str(), e.what());
    RecordProperty("outcome", "refused: " + row.refused_key);
    RecordProperty("measured", e.what());
    return;
  }
  const std::vector<LimitBreach> breaches = scene_limit_breaches(sc);
  if (!row.refused_key.empty()) {
    bool named = false;
    for (const LimitBreach& b : breaches) named = named || b.key == row.refused_key;
    EXPECT_TRUE(named) << "expected a refusal on " << row.refused_key << "; got:\n"
                       << describe_breaches(sc, breaches);
    std::printf("%s: refused (%s)\n", row.name.c_str(), describe_breaches(sc, breaches).c_str());
    RecordProperty("outcome", "refused: " + row.refused_key);
    RecordProperty("measured", describe_breaches(sc, breaches));
    return;
  }
  ASSERT_TRUE(breaches.empty()) << describe_breaches(sc, breaches);
  const double end = g_full ? row.end_full : row.end_short;
  Simulation sim(sc);
  sim.relax();
  double max_density_error = 0, max_overlap = 0, ke_first_half = 0, ke_second_half = 0;
  long floor_hits = 0, clamp_hits = 0;
  // hindered: the mean fall speed of the spheres in the suspension's bulk, 2h clear of the
  // interface (falling at u) and of the sediment (rising at u (1 - eps0)/(eps0 - 0.5),
  // Kynch), over the second half of the run
  const double eps0 = row.hindered ? sc.particles.at(0).voidage : 1.0;
  const double top0 = row.hindered ? sc.particles.at(0).hi[2] : 0.0;
  const double u_hindered =
      row.hindered ? theory::di_felice_block_slip(sc.species.at(0).diameter,
                                                  sc.species.at(0).density, sc.fluid.density,
                                                  sc.fluid.viscosity, sc.gravity_magnitude(), eps0)
                   : 0.0;
  const double support = kernel::kSupport * sc.fluid.lattice_h();
  double bulk_fall_sum = 0, bulk_slip_sum = 0;
  long bulk_count = 0;
  const double log_every = end / 50;
  double next_log = 0;
  try {
    while (sim.time() < end) {
      sim.step();
      floor_hits += sim.voidage_clamped();
      clamp_hits += sim.omega_bounded();
      if (sim.time() < next_log && sim.time() < end) continue;
      next_log += log_every;
      const Diagnostics d = diagnostics(sim);
      max_density_error = std::max(max_density_error, d.max_density_error);
      max_overlap = std::max(max_overlap, d.max_overlap_over_d);
      double& ke = sim.time() < 0.5 * end ? ke_first_half : ke_second_half;
      ke = std::max(ke, d.kinetic_energy_fluid);
      if (row.hindered && sim.time() >= 0.5 * end) {
        const double t = sim.time();
        const double lo = support + u_hindered * t * (1 - eps0) / (eps0 - 0.5);
        const double hi = top0 - u_hindered * t - support;
        const DemParticles& s = sim.spheres();
        for (std::size_t j = 0; j < s.n_owned; ++j)
          if (s.z[j] > lo && s.z[j] < hi) {
            bulk_fall_sum -= s.vz[j];
            bulk_slip_sum += s.eps[j] * (s.ufz[j] - s.vz[j]);
            ++bulk_count;
          }
      }
    }
  } catch (const std::exception& e) {
    FAIL() << row.name << " failed at t = " << sim.time() << " s: " << e.what();
  }
  const Diagnostics d = diagnostics(sim);
  std::string measured = fmt::format("density error {:.2g} %, floor {} / clamp {} particle-steps",
                                     100 * max_density_error, floor_hits, clamp_hits);
  EXPECT_LT(max_density_error, 0.01);
  EXPECT_EQ(floor_hits, 0);
  EXPECT_EQ(clamp_hits, 0);
  if (sim.spheres().n_owned > 0)
    measured += fmt::format(", overlap {:.2g} d", d.max_overlap_over_d);
  if (row.at_rest) {
    // at rest: no growth from the first half of the run to the second, beyond round-off
    // against the column's potential energy scale M g H
    const double scale = d.fluid_mass * std::abs(sc.gravity[2]) * sc.fill_height();
    measured += fmt::format(", kinetic energy {:.2g} -> {:.2g} M g H", ke_first_half / scale,
                            ke_second_half / scale);
    EXPECT_LT(ke_second_half, std::max(2.0 * ke_first_half, 1e-12 * scale));
  }
  if (row.overlap) {
    const StiffnessChoice c = choose_contact_stiffness(sc);
    const double k = sc.contact.normal.k;
    const double expected =
        std::max(c.impact_overlap * std::sqrt(c.k / k), c.static_overlap * c.k / k);
    measured +=
        fmt::format(", largest overlap {:.3g} d against {:.3g} d expected", max_overlap, expected);
    EXPECT_LE(max_overlap, expected);
  }
  if (row.terminal) {
    const double v_t = terminal_speed(sc), slip = d.slip_z_mean.at(0);
    measured += fmt::format(", slip {:.4g} m/s against {:.4g} ({:+.2f} %)", slip, v_t,
                            100 * (slip / v_t - 1));
    EXPECT_NEAR(slip / v_t, 1.0, 0.05);
  }
  if (row.hindered) {
    ASSERT_GT(bulk_count, 0) << "no sphere in the bulk";
    const double u = bulk_fall_sum / bulk_count;
    // the slip is what the drag sees; the fall speed also carries the fluid's convection
    // where the spheres gather (validation/README.md)
    const double slip = bulk_slip_sum / bulk_count;
    measured += fmt::format(
        ", bulk fall speed {:.4g} m/s against {:.4g} (4.4) ({:+.2f} %), superficial slip {:+.2f} %",
        u, u_hindered, 100 * (u / u_hindered - 1), 100 * (slip / u_hindered - 1));
    // (a fine silt's fall over 10 ms carries the fluid's own transient: the slip is held)
    EXPECT_NEAR((row.implicit_drag ? slip : u) / u_hindered, 1.0, 0.05);
  }
  if (row.implicit_drag) {
    const double explicit_dt = kExplicitDragLimit * sim.dem().fluid_drag_time();
    measured += fmt::format(", dt_SPH {:.3g} s, {:.3g} times an explicit exchange's", sim.dt_sph(),
                            sim.dt_sph() / explicit_dt);
    EXPECT_GT(sim.dt_sph(), 2 * explicit_dt);
  }
  std::printf("%s (t = %.3g s, %ld steps): %s\n", row.name.c_str(), sim.time(),
              static_cast<long>(sim.step_count()), measured.c_str());
  RecordProperty("outcome", "runs");
  RecordProperty("measured", measured);
}

INSTANTIATE_TEST_SUITE_P(Matrix, Extremes, ::testing::ValuesIn(rows()),
                         [](const ::testing::TestParamInfo<Row>& info) {
                           std::string n = info.param.name;
                           for (char& c : n)
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           return n;
                         });

}  // namespace

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  for (int k = 1; k < argc; ++k) g_full = g_full || std::strcmp(argv[k], "--full") == 0;
  return RUN_ALL_TESTS();
}
