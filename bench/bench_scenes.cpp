// Throughput of whole SPH-DEM steps on the scenes users run, in particle-steps per
// second (Google Benchmark counters). Run: build/bench/bench_scenes
//   block:  cases/block_monodisperse.yaml (12000 fluid + 1200 wall SPH, 5819 spheres)
//   column: the peers' `sph` scene (shared/peers/README.md): the same 4x4x6 mm water
//           column, 13200 SPH particles (walls counted, as the peers count them),
//           c0 = 1 m/s, no spheres; compare with LIGGGHTS' 0.421 M p-s/s (1 rank).
//   dem_settle, dem_bed: the peers' dry DEM scenes (bench/dem_settle.yaml, bench/dem_bed.yaml).
//   bed:    contact-dominated: 14400 free 100 um spheres on a simple-cubic lattice at
//           voidage 0.4765 (layers 0.02 % of d apart, the bottom one just above the wall),
//           stiffness 100 N/m (54 DEM sub-steps per SPH step), in a 2 mm water column: the
//           bed lands on the wall and stays packed, and the DEM sub-steps dominate a step.
//           BM_BedStep: normal contacts only; BM_BedStepFriction: the same bed with
//           tangential friction (linear_history) and rolling resistance (epsd).
#include <benchmark/benchmark.h>

#include <memory>

#include "propagator/simulation.hpp"
#include "scene/scene.hpp"

using namespace sphdem;

namespace {

void run_steps(benchmark::State& state, const Scene& sc, int warmup) {
  Simulation sim(sc);
  sim.relax();
  for (int k = 0; k < warmup; ++k) sim.step();
  double sph = 0, dem = 0;
  for (auto _ : state) {
    sim.step();
    sph += static_cast<double>(sim.fluid().n_owned);
    dem += static_cast<double>(sim.spheres().n_owned) * sim.dem_substeps();
  }
  state.counters["sph_particle_steps_per_s"] = benchmark::Counter(sph, benchmark::Counter::kIsRate);
  if (dem > 0)
    state.counters["dem_particle_steps_per_s"] =
        benchmark::Counter(dem, benchmark::Counter::kIsRate);
  state.counters["dem_substeps"] = sim.dem_substeps();
}

void BM_BlockStep(benchmark::State& state) {
  run_steps(state,
            load_scene(SPHDEM_CASES_DIR "/block_monodisperse.yaml", {"startup.relax_steps=20"}),
            20);
}
BENCHMARK(BM_BlockStep)->Unit(benchmark::kMillisecond)->Iterations(200)->UseRealTime();

void BM_FluidColumnStep(benchmark::State& state) {
  const Scene sc = load_scene_text(R"(
name: peers_sph_column
domain: {size: [0.004, 0.004, 0.006]}
fluid: {spacing: 2.0e-4, sound_speed: 1.0, wall_layers: 3}
startup: {relax_steps: 0}
)",
                                   "peers_sph_column");
  run_steps(state, sc, 200);
}
BENCHMARK(BM_FluidColumnStep)->Unit(benchmark::kMillisecond)->Iterations(1400)->UseRealTime();

// The peers' dem_settle window (shared/peers/README.md): 500 warm-up and 39 500 timed
// DEM steps at dt = t_c/20, here 13 and 988 outer steps of 40 sub-steps (520 and 39 520).
// Compare dem_particle_steps_per_s with LAMMPS 18.99 M/s and LIGGGHTS 13.60 M/s (1 rank),
// 36.28 and 25.32 M/s (2 ranks); run the peers in the same session for a ratio.
void BM_DemSettle(benchmark::State& state) {
  run_steps(state, load_scene(SPHDEM_BENCH_DIR "/dem_settle.yaml"), 13);
}
BENCHMARK(BM_DemSettle)->Unit(benchmark::kMillisecond)->Iterations(988)->UseRealTime();

// The peers' dem_bed window (shared/peers/README.md): 1 000 warm-up and 10 000 timed DEM
// steps at dt = t_c/20 in a dense fcc bed (bench/dem_bed.yaml), here 25 and 250 outer
// steps of 40 sub-steps.
void BM_DemBed(benchmark::State& state) {
  run_steps(state, load_scene(SPHDEM_BENCH_DIR "/dem_bed.yaml"), 25);
}
BENCHMARK(BM_DemBed)->Unit(benchmark::kMillisecond)->Iterations(250)->UseRealTime();

const char* const kBed = R"(
name: bench_bed
domain: {size: [0.004, 0.004, 0.002]}
species: [{name: glass, diameter: 1.0e-4, density: 2500}]
particles:
  - {type: lattice, species: glass, min: [0, 0, 0], max: [0.004, 0.004, 0.0009002], voidage: 0.4765}
contact: {stiffness: 100, restitution: 0.5}
startup: {relax_steps: 5}
)";

void BM_BedStep(benchmark::State& state) {
  run_steps(state, load_scene_text(kBed, "bench_bed"), 20);
}
BENCHMARK(BM_BedStep)->Unit(benchmark::kMillisecond)->Iterations(60)->UseRealTime();

void BM_BedStepFriction(benchmark::State& state) {
  run_steps(state,
            load_scene_text(
                kBed, "bench_bed",
                {"contact.tangential={model: linear_history, friction: 0.5, restitution: 0.5}",
                 "contact.rolling={model: epsd, friction: 0.1}"}),
            20);
}
BENCHMARK(BM_BedStepFriction)->Unit(benchmark::kMillisecond)->Iterations(60)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
