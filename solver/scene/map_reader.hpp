#pragma once
// Reads one YAML map of a scene file, remembering which keys were asked for so that any
// other key is reported as unknown (with the keys allowed there). A bad value is recorded
// in the scene's SceneProblems and the key's default returned, so reading goes on and a
// file's every problem is reported at once (scene/scene_problems.hpp).
#include <yaml-cpp/yaml.h>

#include <array>
#include <cstdint>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "scene/scene_problems.hpp"

namespace sphdem {

class MapReader {
 public:
  // `path` is the map's dotted key ("" for the top level). A node that is not a map is
  // a problem, and reads as an empty map (every key at its default).
  MapReader(const YAML::Node& node, std::string path, SceneProblems& problems);

  std::string key(const std::string& k) const { return path_.empty() ? k : path_ + "." + k; }
  // Records a problem at a full key ("" is the top level).
  void fail(const std::string& full_key, const std::string& what) { problems_.add(full_key, what); }
  // True while no problem was recorded since this reader was made (its own, those of
  // readers nested in it, and any other): checks across keys run only on clean values.
  bool clean() const { return problems_.count() == first_problem_; }

  bool has(const std::string& k);
  YAML::Node child(const std::string& k);  // an undefined node when absent

  // A number in [lo, hi] (open ends when lo_open/hi_open); def when absent or bad.
  double number(const std::string& k, double def, double lo, double hi, bool lo_open = false,
                bool hi_open = false);
  // A number the file must give; 0 when absent or bad.
  double required(const std::string& k, double lo, double hi, bool lo_open = false);
  bool in_range(const std::string& full_key, double v, double lo, double hi, bool lo_open = false,
                bool hi_open = false);
  // A non-empty list of numbers, each in [lo, hi] (an entry in error is named 'key.i');
  // nothing when the list or an entry is bad.
  std::optional<std::vector<double>> numbers(const std::string& k, double lo, double hi,
                                             bool lo_open = false);
  std::int64_t whole64(const std::string& k, std::int64_t def, std::int64_t lo, std::int64_t hi);
  int integer(const std::string& k, int def, int lo, int hi);
  bool boolean(const std::string& k, bool def);
  std::string text(const std::string& k, const std::string& def);
  // One of `allowed` (a misspelling gets a did-you-mean); nothing when the file gave
  // another value.
  std::optional<std::string> choice(const std::string& k, const std::string& def,
                                    const std::vector<std::string>& allowed);
  std::array<double, 3> vec3(const std::string& k, std::array<double, 3> def);

  // Declares the keys allowed here and reports any other key at once (the top level, so
  // that a misspelt section is named before the problems its absence causes).
  void expect(std::initializer_list<const char*> keys);
  // Reports keys that were never asked for (report_unknown false: where a bad choice
  // leaves it unknown which keys apply) and declares the keys asked for.
  void finish(bool report_unknown = true);

 private:
  template <class T>
  bool scalar(const std::string& k, const char* what, T& out);
  YAML::Node node_;
  std::string path_;
  SceneProblems& problems_;
  std::size_t first_problem_;
  std::set<std::string> allowed_, reported_;
};

}  // namespace sphdem
