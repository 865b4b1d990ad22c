// libFuzzer target over the scene loader and the --set parser (issue 16). An input is a
// scene file, then, after a line "#--set" (a YAML comment), one --set assignment a line.
// The loader must load the scene or throw SceneError: a crash, a hang, a sanitizer report
// or any other exception is a bug. A scene that loads must pass the limits check of
// `sphdem check` (scene/scene_limits.hpp) and write a case.yaml that loads.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <sstream>
#include <string>
#include <vector>

#include "scene/scene.hpp"
#include "scene/scene_limits.hpp"

namespace {

[[noreturn]] void bug(const char* what, const std::string& detail) {
  std::fprintf(stderr, "scene_fuzz: %s: %s\n", what, detail.c_str());
  std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string input(reinterpret_cast<const char*>(data), size);
  const std::string marker = "#--set\n";
  std::string yaml = input;
  std::vector<std::string> sets;
  const auto at = input.rfind(marker, 0) == 0 ? 0 : input.find("\n" + marker);
  if (at != std::string::npos) {
    yaml = input.substr(0, at);
    std::istringstream lines(input.substr(at + (at == 0 ? 0 : 1) + marker.size()));
    for (std::string line; std::getline(lines, line);) sets.push_back(line);
  }
  sphdem::Scene scene;
  try {
    scene = sphdem::load_scene_text(yaml, "fuzz.yaml", sets);
  } catch (const sphdem::SceneError&) {
    return 0;  // a bad scene, reported as one
  } catch (const std::exception& e) {
    bug("an exception that is not a SceneError", e.what());
  } catch (...) {
    bug("an exception that is not a std::exception", "");
  }
  std::string written;
  try {
    sphdem::scene_limit_breaches(scene);
    written = sphdem::scene_to_yaml(scene);
    sphdem::load_scene_text(written, "case.yaml");
  } catch (const std::exception& e) {
    bug("the case.yaml of a scene that loaded does not load",
        std::string(e.what()) + "\n" + written);
  }
  return 0;
}
