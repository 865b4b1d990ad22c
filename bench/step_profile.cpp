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
#include <omp.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "propagator/simulation.hpp"
#include "scene/scene.hpp"

using namespace sphdem;

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: step_profile SCENE.yaml [STEPS [WARMUP]] [key=value ...]\n");
    return 2;
  }
  int steps = 50, warmup = 10, sort_interval = 0;
  std::vector<std::string> overrides;
  int positional = 0;
  for (int i = 2; i < argc; ++i) {
    const std::string a = argv[i];
    if (a.rfind("sort=", 0) == 0)
      sort_interval = std::atoi(a.c_str() + 5);
    else if (a.find('=') != std::string::npos)
      overrides.push_back(a);
    else if (positional++ == 0)
      steps = std::atoi(argv[i]);
    else
      warmup = std::atoi(argv[i]);
  }
  const auto t0 = std::chrono::steady_clock::now();
  Simulation sim(load_scene(argv[1], overrides));
  const auto t1 = std::chrono::steady_clock::now();
  sim.relax();
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
      std::chrono::duration<double>(t1 - t0).count(), steps, sim.scene().startup.relax_steps,
      warmup, wall / steps);
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
  return 0;
}
