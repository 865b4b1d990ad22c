// Where a coupled step's time goes, pass by pass, with the pairs each pass visits: the
// profile of issue 35 (bench/RESULTS.md). Loads a scene, relaxes it, takes `warm-up`
// steps, then times `steps` steps with the propagator's pass timers and prints, per pass,
// the wall time per step, its share, and for the pair passes the pairs per second per
// thread (OMP_NUM_THREADS threads):
//   voidage         the fluid-sphere Verlet entries (each gets a distance and kernel values)
//   interpolation   the fluid-sphere pairs within the spheres' kernel (each adds the
//                   variational pairs and, with its drag weight, the Shepard sums' block)
//   reaction        the same pairs; "drag entries" counts those with a drag weight > 0
//   density_rate, momentum   the fluid pairs (half list, with its skin)
// Run: OMP_NUM_THREADS=2 build/bench/step_profile cases/sand_column.yaml [STEPS [WARMUP]]
//      [key=value ...] [sort=STEPS: re-sort every STEPS steps after the warm-up]
//      [resume=RUN_DIR: from the run's newest checkpoint (its scene, the overrides on top),
//      without relaxation: the step as a run has it later, a sediment in it]
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

#include "io/checkpoint_file.hpp"
#include "propagator/simulation.hpp"
#include "run/checkpoints.hpp"
#include "scene/scene.hpp"

using namespace sphdem;

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: step_profile SCENE.yaml [STEPS [WARMUP]] [key=value ...]\n");
    return 2;
  }
  int steps = 50, warmup = 10, sort_interval = 0;
  std::vector<std::string> overrides;
  std::string resume_dir;
  int positional = 0;
  for (int i = 2; i < argc; ++i) {
    const std::string a = argv[i];
    if (a.rfind("sort=", 0) == 0)
      sort_interval = std::atoi(a.c_str() + 5);
    else if (a.rfind("resume=", 0) == 0)
      resume_dir = a.substr(7);
    else if (a.find('=') != std::string::npos)
      overrides.push_back(a);
    else if (positional++ == 0)
      steps = std::atoi(argv[i]);
    else
      warmup = std::atoi(argv[i]);
  }
  const auto t0 = std::chrono::steady_clock::now();
  std::unique_ptr<Simulation> made;
  if (resume_dir.empty()) {
    made = std::make_unique<Simulation>(load_scene(argv[1], overrides));
  } else {
    const CheckpointStore::Found found = CheckpointStore::newest_valid(resume_dir);
    const CheckpointReader& ckpt = *found.reader;
    made = std::make_unique<Simulation>(
        load_scene_text(ckpt.text("scene/yaml"), ckpt.path(), overrides), ckpt);
    std::printf("# from %s: t = %.6g s, step %ld\n", ckpt.path().c_str(), made->time(),
                static_cast<long>(made->step_count()));
  }
  Simulation& sim = *made;
  const auto t1 = std::chrono::steady_clock::now();
  if (resume_dir.empty()) sim.relax();
  for (int k = 0; k < warmup; ++k) sim.step();
  if (sort_interval > 0) sim.set_sort_interval(sort_interval);  // after the first sorts
  const PassTimers before = sim.timers();
  const long dem_builds = sim.dem().list_builds(), fluid_builds = sim.neighbour_builds();
  double fluid_sphere = 0, within = 0, drag = 0, fluid_pairs = 0;
  double wall = 0;  // in the steps alone (the counts below are one thread's loops)
  for (int k = 0; k < steps; ++k) {
    const auto t2 = std::chrono::steady_clock::now();
    sim.step();
    wall += std::chrono::duration<double>(std::chrono::steady_clock::now() - t2).count();
    const FluidSpherePairs& p = sim.sphere_pairs();
    for (std::size_t a = 0; a < sim.fluid().n_owned; ++a) {
      within += p.end(a) - p.begin(a);
      for (std::uint32_t e = p.begin(a); e < p.end(a); ++e) drag += p.drag_w()[e] > 0.0;
    }
    fluid_sphere += static_cast<double>(p.list.neighbour.size());
    fluid_pairs += static_cast<double>(sim.fluid_pairs().neighbour.size());
  }
  const int threads = omp_get_max_threads();
  std::printf(
      "# %s: %zu fluid (owned SPH), %zu spheres, %d threads; setup %.2f s; %d steps "
      "after %d relaxation and %d warm-up steps: %.4f s per step\n",
      argv[1], sim.fluid().n_owned, sim.spheres().n_owned, threads,
      std::chrono::duration<double>(t1 - t0).count(), steps,
      resume_dir.empty() ? sim.scene().startup.relax_steps : 0, warmup, wall / steps);
  std::printf(
      "# per step: %.3g fluid-sphere list entries, %.3g within the kernel, %.3g drag "
      "entries, %.3g fluid pair entries\n",
      fluid_sphere / steps, within / steps, drag / steps, fluid_pairs / steps);
  std::printf(
      "# list builds over the steps: %ld fluid (all lists), %ld sphere halo and contact "
      "list (each renews the fluid-sphere pairs)\n",
      sim.neighbour_builds() - fluid_builds, sim.dem().list_builds() - dem_builds);
  std::printf("%-16s %12s %7s %22s\n", "pass", "ms/step", "share", "pairs/s/thread");
  const auto& names = PassTimers::kNames;
  for (int k = 0; k < PassTimers::kCount; ++k) {
    const double s = sim.timers().seconds[k] - before.seconds[k];
    const std::string pass = names[k];
    double pairs = 0;
    if (pass == "voidage") pairs = fluid_sphere;
    if (pass == "interpolation") pairs = within;
    if (pass == "reaction") pairs = within;
    if (pass == "density_rate" || pass == "momentum") pairs = fluid_pairs;
    std::printf("%-16s %12.3f %6.1f%% ", names[k], 1e3 * s / steps, 100.0 * s / wall);
    if (pairs > 0)
      std::printf("%22.3g\n", pairs / (s * threads));
    else
      std::printf("%22s\n", "-");
  }
  // what bounds the step: the particle with the smallest CFL bound (3.5) and the clear
  // liquid's and the suspension's smoothing lengths
  const FluidParticles& f = sim.fluid();
  std::size_t worst = 0;
  double h_clear = 0, n_clear = 0, h_mix = 0, n_mix = 0, cs_max = 0;
  for (std::size_t a = 0; a < f.n_owned; ++a) {
    if (f.kind[a] != kFluid) continue;
    if (f.dt_limit[a] < f.dt_limit[worst]) worst = a;
    cs_max = std::max(cs_max, f.cs[a]);
    if (f.eps[a] > 0.999)
      h_clear += f.h[a], ++n_clear;
    else
      h_mix += f.h[a], ++n_mix;
  }
  const double cfl = sim.scene().time.cfl;
  std::printf(
      "# dt_SPH %.4g s; smallest CFL bound %.4g s at z = %.4g m: h %.4g m, eps %.3f, cs %.4g "
      "m/s, v_sig %.4g m/s; largest cs %.4g; mean h: clear liquid %.4g m (%g), with spheres "
      "%.4g m (%g)\n",
      sim.dt_sph(), f.dt_limit[worst], f.z[worst], f.h[worst], f.eps[worst], f.cs[worst],
      cfl * f.h[worst] / f.dt_limit[worst], cs_max, h_clear / std::max(n_clear, 1.0), n_clear,
      h_mix / std::max(n_mix, 1.0), n_mix);
  return 0;
}
