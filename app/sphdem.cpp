// sphdem: command-line front end of the solver library.
//   sphdem run [CASE.yaml] --out DIR [--set key.path=value ...]
//   sphdem check CASE.yaml [--set ...]
#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <iostream>

#include "run/runner.hpp"
#include "run/scene.hpp"

int main(int argc, char** argv) {
  CLI::App app{"sphdem: coupled SPH-DEM simulator of fluid-particle flows"};
  app.require_subcommand(1);

  std::string case_file = SPHDEM_DEFAULT_CASE, out_dir = "out";
  std::vector<std::string> overrides;
  auto* run = app.add_subcommand("run", "run a scene (default: the monodisperse block)");
  run->add_option("case", case_file, "scene file (YAML)")->check(CLI::ExistingFile);
  run->add_option("--out,-o", out_dir, "output directory")->capture_default_str();
  run->add_option("--set", overrides, "override a scene key, e.g. --set time.end=0.01")->allow_extra_args(false);

  auto* check = app.add_subcommand("check", "validate a scene and print its derived numbers");
  check->add_option("case", case_file, "scene file (YAML)")->required()->check(CLI::ExistingFile);
  check->add_option("--set", overrides, "override a scene key")->allow_extra_args(false);

  CLI11_PARSE(app, argc, argv);
  try {
    const sphdem::Scene scene = sphdem::load_scene(case_file, overrides);
    if (*check) {
      std::cout << sphdem::describe_scene(scene);
      return 0;
    }
    sphdem::RunOptions opt;
    opt.out_dir = out_dir;
    opt.progress = &std::cerr;
    sphdem::run_scene(scene, opt);
  } catch (const sphdem::SceneError& e) {
    std::cerr << "sphdem: error: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "sphdem: run failed: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
