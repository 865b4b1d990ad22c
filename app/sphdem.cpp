// sphdem: command-line front end of the solver library.
//   sphdem run [CASE.yaml] --out DIR [--set key.path=value ...]
//   sphdem resume DIR [--set time.end=T]
//   sphdem check CASE.yaml [--set ...]
//   sphdem figures DIR
//   sphdem docs [BLOCK] [--update FILE...]
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>

#include "analysis/contact_network.hpp"
#include "analysis/voidage_grid.hpp"
#include "analysis/watchdog.hpp"
#include "domain/rank_comm.hpp"
#include "io/checkpoint_file.hpp"
#include "launcher_ranks.hpp"
#include "propagator/simulation.hpp"
#include "run/checkpoints.hpp"
#include "run/runner.hpp"
#include "run/table_docs.hpp"
#include "scene/fidelity.hpp"
#include "scene/scene.hpp"
#include "scene/scene_limits.hpp"
#include "stop_signals.hpp"

#ifdef SPHDEM_HAVE_CATALYST
#include "insitu.hpp"
#include "vtk_snapshots.hpp"
#endif

namespace {

// The figures of a run directory (finished or interrupted), by pipelines/figures.py
// under Debian's python3 (which has numpy, matplotlib and h5py).
int make_figures(const std::string& dir) {
  const std::string cmd =
      fmt::format("/usr/bin/python3 '{}/figures.py' '{}'", SPHDEM_PIPELINES_DIR, dir);
  const int rc = std::system(cmd.c_str());
  return WIFEXITED(rc) ? WEXITSTATUS(rc) : 1;
}

// `sphdem docs`: a generated block to stdout, or the files' blocks rewritten in place.
int print_or_update_docs(const std::string& block, const std::vector<std::string>& files) {
  try {
    if (!block.empty()) std::cout << sphdem::generated_block(block);
    for (const std::string& f : files) {
      std::ifstream in(f);
      std::stringstream text;
      text << in.rdbuf();
      const std::string now = sphdem::with_generated_blocks(text.str());
      if (now == text.str()) continue;
      std::ofstream(f) << now;
      std::cerr << "sphdem: docs: rewrote " << f << "\n";
    }
    return 0;
  } catch (const std::invalid_argument& e) {
    std::cerr << "sphdem: error: " << e.what() << "\n";
    return 2;
  }
}

// A run with its in-situ analysis and VTK output, fresh or continued from a checkpoint;
// the figures at the end. Returns the exit code.
int run_with_analysis(const sphdem::Scene& scene, const std::string& out_dir, bool no_insitu,
                      const sphdem::CheckpointReader* resume) {
  const sphdem::RankComm comm;
  sphdem::RunOptions opt;
  opt.out_dir = out_dir;
  opt.progress = &std::cerr;
  opt.resume = resume;
  opt.stop_requested = sphdem::stop_signal;
  const double resume_time = resume ? resume->scalar<double>("run/time") : std::nan("");
  bool insitu_ran = false;
#ifdef SPHDEM_HAVE_CATALYST
  std::unique_ptr<sphdem::InSitu> insitu;
  std::unique_ptr<sphdem::VtkSnapshots> snapshots;
  const sphdem::GridSpec grid = sphdem::column_voidage_grid(
      scene.box.length(0), scene.box.length(1), scene.fill_height(), scene.insitu.grid_spacing);
  const sphdem::GridSpec piece = sphdem::rank_piece(grid, comm.rank(), comm.size());
  std::vector<double> voidage;
  if (scene.insitu.enabled && !no_insitu && !scene.insitu.pipelines.empty()) {
    sphdem::InSituOptions io;
    io.out_dir = out_dir;
    io.pipelines_dir = SPHDEM_PIPELINES_DIR;
    io.resume_time = resume_time;
    io.resume_step = resume ? static_cast<long>(resume->scalar<std::int64_t>("run/step")) : -1;
    std::filesystem::create_directories(out_dir);
    insitu = std::make_unique<sphdem::InSitu>(scene, io);
    sphdem::install_stop_signals();  // ParaView's logger installed its own for SIGINT, SIGTERM
    opt.hooks.push_back(
        {"in-situ analysis", scene.insitu.every, [&](const sphdem::Simulation& sim, long call) {
           voidage = voidage_on_grid(sim, grid);  // the whole grid, on every rank
           if (comm.parallel()) voidage = piece_values(voidage, grid, piece);
           const std::vector<int> contacts = contact_counts(sim.spheres(), sim.contact_list());
           sphdem::InSituFrame fr;
           fr.fluid = &sim.fluid();
           fr.spheres = &sim.spheres();
           fr.contact_count = &contacts;
           fr.grid = piece;
           fr.whole_extent = grid.extent;
           fr.voidage = &voidage;
           fr.time = sim.time();
           fr.step = sim.step_count();
           fr.analysis = call;
           insitu->execute(fr);
         }});
    insitu_ran = true;
  }
  if (scene.output.vtk_every > 0) {
    snapshots = std::make_unique<sphdem::VtkSnapshots>(
        (std::filesystem::path(out_dir) / "vtk").string(), comm.rank(), comm.size());
    if (resume) snapshots->resume(resume_time);
    opt.hooks.push_back(
        {"VTK snapshots", scene.output.vtk_every, [&](const sphdem::Simulation& sim, long) {
           snapshots->write(sim.fluid(), sim.spheres(), sim.time(), sim.step_count());
         }});
  }
#else
  (void)resume_time;
  if (scene.output.vtk_every > 0 || (scene.insitu.enabled && !no_insitu))
    std::cerr << "sphdem: note: built without ParaView (SPHDEM_WITH_PARAVIEW=OFF): no in-situ "
                 "analysis or VTK output\n";
#endif
  std::string failure;
  sphdem::RunSummary summary;
  try {
    summary = sphdem::run_scene(scene, opt);
  } catch (const sphdem::SceneError&) {
    throw;
  } catch (const sphdem::CheckpointError& e) {  // (on ranks: every rank throws it)
    failure = e.what();
  } catch (const sphdem::WatchdogError& e) {  // (on ranks: every rank throws it)
    failure = e.what();
  } catch (const std::exception& e) {
    failure = e.what();     // keep what was written so far, and still make the figures
    if (comm.parallel()) {  // one rank's failure: the others would wait for it
      std::cerr << fmt::format("sphdem: run failed on rank {}: {}\n", comm.rank(), failure);
      MPI_Abort(comm.comm(), 1);
    }
  }
#ifdef SPHDEM_HAVE_CATALYST
  insitu.reset();  // finalize Catalyst: pipelines flush their reduced data
#endif
  if (!failure.empty()) {
    if (comm.rank() != 0) return 1;
    if (insitu_ran) make_figures(out_dir);
    std::cerr << "sphdem: run failed: " << failure << "\n";
    const auto last = sphdem::CheckpointStore::list(out_dir);
    if (!last.empty())
      std::cerr << "sphdem: the last checkpoint is " << last.back()
                << "; continue with: sphdem resume " << out_dir << "\n";
    return 1;
  }
  if (summary.stopped_by) return 128 + summary.stopped_by;  // as a process ended by it
  if (insitu_ran && comm.rank() == 0) make_figures(out_dir);
  return 0;
}

// `sphdem resume DIR` may change only what does not alter the run's state.
void check_resume_overrides(const std::vector<std::string>& overrides) {
  for (const auto& o : overrides) {
    const std::string key = o.substr(0, o.find('='));
    if (key.rfind("time.", 0) == 0 || key.rfind("checkpoint.", 0) == 0 ||
        key.rfind("watchdog.", 0) == 0 || key == "output.progress_interval")
      continue;
    throw sphdem::SceneError(fmt::format(
        "--set '{}': a resumed run can change only time.* (end, cfl, dem_steps_per_contact, "
        "max_dt_sph), checkpoint.*, watchdog.* and output.progress_interval (the rest is the "
        "run's state; start a new run to change it)",
        o));
  }
}

}  // namespace

// MPI around a run on ranks: initialised only under a launcher, finalised at the end.
struct MpiSession {
  bool on;
  MpiSession(bool start, int& argc, char**& argv) : on(start) {
    if (on) MPI_Init(&argc, &argv);
  }
  ~MpiSession() {
    if (on) MPI_Finalize();
  }
};

int main(int argc, char** argv) {
  CLI::App app{"sphdem: coupled SPH-DEM simulator of fluid-particle flows"};
  app.require_subcommand(1);

  std::string case_file = SPHDEM_DEFAULT_CASE, out_dir = "out";
  std::vector<std::string> overrides;
  bool no_insitu = false;
  auto* run = app.add_subcommand(
      "run", "run a scene (default: cases/sedimentation.yaml, a suspension settling to rest)");
  run->add_option("case", case_file, "scene file (YAML)")->check(CLI::ExistingFile);
  run->add_option("--out,-o", out_dir, "output directory")->capture_default_str();
  run->add_option("--set", overrides, "override a scene key, e.g. --set time.end=0.01")
      ->allow_extra_args(false);
  run->add_flag("--no-insitu", no_insitu, "skip the in-situ analysis and figures");
  std::string fidelity;
  std::vector<std::string> presets;
  for (const auto& p : sphdem::kFidelityPresets) presets.push_back(p.name);
  run->add_option("--fidelity", fidelity,
                  "preset for the keys the scene leaves unset (scene key fidelity)")
      ->check(CLI::IsMember(presets));

  std::string resume_dir;
  auto* resume = app.add_subcommand(
      "resume", "continue the run in DIR from its newest checkpoint that reads back whole");
  resume->add_option("dir", resume_dir, "run directory")->required()->check(CLI::ExistingDirectory);
  resume
      ->add_option("--set", overrides,
                   "change time.* (time.end extends a finished run; time.cfl, "
                   "time.dem_steps_per_contact after a watchdog stop), checkpoint.*, "
                   "watchdog.* or output.progress_interval")
      ->allow_extra_args(false);
  resume->add_flag("--no-insitu", no_insitu, "skip the in-situ analysis and figures");

  auto* check = app.add_subcommand("check", "validate a scene and print its derived numbers");
  check->add_option("case", case_file, "scene file (YAML)")->required()->check(CLI::ExistingFile);
  check->add_option("--set", overrides, "override a scene key")->allow_extra_args(false);
  int check_ranks = 1;
  check
      ->add_option("--ranks", check_ranks,
                   "also the memory per rank and the wall time on this many MPI ranks")
      ->check(CLI::Range(1, 1 << 20));
  check->add_option("--fidelity", fidelity, "preset for the keys the scene leaves unset")
      ->check(CLI::IsMember(presets));

  std::string fig_dir;
  auto* figures = app.add_subcommand("figures", "(re)make the figures of a run directory");
  figures->add_option("dir", fig_dir, "run directory")->required()->check(CLI::ExistingDirectory);

  std::string doc_block;
  std::vector<std::string> doc_files;
  auto* docs = app.add_subcommand(
      "docs",
      "print a table of the documents from the solver's own tables, or rewrite those tables in "
      "FILEs (run/table_docs.hpp)");
  docs->add_option("block", doc_block,
                   "what to print: 'keys SECTION...' (- for the top level), 'fidelity presets', "
                   "'drag laws', 'log columns', 'pipelines', 'fuzz dictionary'");
  docs->add_option("--update", doc_files, "rewrite every generated block of these files")
      ->check(CLI::ExistingFile);

  CLI11_PARSE(app, argc, argv);
  if (*docs) return print_or_update_docs(doc_block, doc_files);
  // Under mpirun: run and resume share the scene over the ranks (MPI initialised for them
  // only), figures are made by rank 0; check is refused.
  const auto ranks =
      sphdem::launcher_ranks([](const char* v) -> const char* { return std::getenv(v); });
  const bool speaks = ranks.rank == 0;  // messages common to every rank: rank 0's
  if (*figures) return speaks ? make_figures(fig_dir) : 0;
  if (ranks.size > 1 && !*run && !*resume) {
    if (speaks) std::cerr << sphdem::one_process_message(ranks, "check");
    return 2;
  }
  const MpiSession mpi(ranks.size > 1, argc, argv);
  if (!fidelity.empty()) overrides.insert(overrides.begin(), "fidelity=" + fidelity);
  sphdem::install_stop_signals();
  try {
    if (*resume) {
      check_resume_overrides(overrides);
      sphdem::CheckpointStore::Found found = sphdem::CheckpointStore::newest_valid(resume_dir);
      for (const auto& why : found.skipped)
        if (speaks)
          std::cerr << "sphdem: warning: skipped a checkpoint that does not read back whole: "
                    << why << "\n";
      const sphdem::CheckpointReader& ckpt = *found.reader;
      const sphdem::Scene scene =
          sphdem::load_scene_text(ckpt.text("scene/yaml"), ckpt.path() + " (its scene)", overrides);
      if (ckpt.scalar<double>("run/time") >= scene.time.end * (1.0 - 1e-12)) {
        if (speaks)
          std::cerr << fmt::format(
              "sphdem: the run in {} is complete (t = {:.6g} s = time.end); to extend it: sphdem "
              "resume {} --set time.end=T\n",
              resume_dir, ckpt.scalar<double>("run/time"), resume_dir);
        return 0;
      }
      return run_with_analysis(scene, resume_dir, no_insitu, &ckpt);
    }
    const sphdem::Scene scene = sphdem::load_scene(case_file, overrides);
    if (*check) {  // every breach of the model's limits, then the derived numbers
      const auto breaches = sphdem::scene_limit_breaches(scene);
      for (const auto& b : breaches)
        std::cerr << "sphdem: refused: " << case_file << ": key '" << b.key << "': " << b.message
                  << "\n";
      std::vector<sphdem::Scene> presets;  // the same file at each fidelity
      for (const auto& p : sphdem::kFidelityPresets) {
        std::vector<std::string> sets = overrides;
        sets.push_back(std::string("fidelity=") + p.name);
        presets.push_back(sphdem::load_scene(case_file, sets));
      }
      std::cout << sphdem::describe_scene(scene, presets, check_ranks);
      if (!breaches.empty())
        std::cerr << fmt::format("sphdem: {} limit(s) broken: `sphdem run` refuses this scene\n",
                                 breaches.size());
      return breaches.empty() ? 0 : 2;
    }
    return run_with_analysis(scene, out_dir, no_insitu, nullptr);
  } catch (const sphdem::SceneError& e) {  // every problem of the scene, one a line
    std::istringstream problems(e.what());
    for (std::string line; std::getline(problems, line);)
      if (speaks) std::cerr << "sphdem: error: " << line << "\n";
    return 2;
  } catch (const sphdem::CheckpointError& e) {
    if (speaks) std::cerr << "sphdem: error: " << e.what() << "\n";
    return 1;
  } catch (const std::exception& e) {
    if (speaks) std::cerr << "sphdem: run failed: " << e.what() << "\n";
    return 1;
  }
}
