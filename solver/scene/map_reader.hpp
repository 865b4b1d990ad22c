#pragma once
// Reads one YAML map of a scene file through the scene key table (scene/scene_keys.hpp):
// each key's type, default and allowed range come from its row, so a reader names only
// the key (and, where the default or range depends on other keys, that value). It
// remembers which keys were asked for, so any other key is reported as unknown (with the
// keys allowed there). A bad value is recorded in the scene's SceneProblems and the
// key's default returned, so reading goes on and a file's every problem is reported at
// once (scene/scene_problems.hpp). Asking for a key that has no row is a programming
// error (std::logic_error).
#include <yaml-cpp/yaml.h>

#include <array>
#include <cstdint>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "scene/scene_key.hpp"
#include "scene/scene_problems.hpp"

namespace sphdem {

class MapReader {
 public:
  // `path` is the map's dotted key ("" for the top level, "species.2" in a list). A node
  // that is not a map is a problem, and reads as an empty map (every key at its default).
  MapReader(const YAML::Node& node, std::string path, SceneProblems& problems);

  std::string key(const std::string& k) const { return path_.empty() ? k : path_ + "." + k; }
  // The table's row of key k of this map.
  const SceneKey& row(const std::string& k) const;
  // Records a problem at a full key ("" is the top level).
  void fail(const std::string& full_key, const std::string& what) { problems_.add(full_key, what); }
  // True while no problem was recorded since this reader was made (its own, those of
  // readers nested in it, and any other): checks across keys run only on clean values.
  bool clean() const { return problems_.count() == first_problem_; }

  bool has(const std::string& k);
  YAML::Node child(const std::string& k);  // an undefined node when absent

  // A number in the row's range; the row's default (or `def`) when absent or bad.
  double number(const std::string& k) { return number(k, row(k).number); }
  double number(const std::string& k, double def);
  // The same in a narrower range [lo, hi] that other keys set (within the row's).
  double number_within(const std::string& k, double def, double lo, double hi);
  // A number the file must give; 0 when absent or bad.
  double required(const std::string& k);
  // A non-empty list of numbers, each in the row's range (an entry in error is named
  // 'key.i'); nothing when the list or an entry is bad.
  std::optional<std::vector<double>> numbers(const std::string& k);
  std::int64_t whole64(const std::string& k);
  int integer(const std::string& k) { return integer(k, static_cast<int>(row(k).number)); }
  int integer(const std::string& k, int def, int lo_from_other_keys = 0);
  bool boolean(const std::string& k) { return boolean(k, row(k).number != 0); }
  bool boolean(const std::string& k, bool def);
  std::string text(const std::string& k);
  // One of the row's choices (a misspelling gets a did-you-mean); nothing when the file
  // gave another value. `def` where the default depends on other keys.
  std::optional<std::string> choice(const std::string& k) {
    return choice(k, std::string(row(k).text));
  }
  std::optional<std::string> choice(const std::string& k, const std::string& def);
  // `auto` (true; also when absent) or a number in the row's range (into v).
  bool number_or_auto(const std::string& k, double& v);
  std::array<double, 3> vec3(const std::string& k) { return vec3(k, row(k).vector); }
  std::array<double, 3> vec3(const std::string& k, std::array<double, 3> def);

  // Declares the keys the table has here and reports any other key at once (the top
  // level, so that a misspelt section is named before the problems its absence causes).
  void expect_table_keys();
  // Reports keys that were never asked for (report_unknown false: where a bad choice
  // leaves it unknown which keys apply) and declares the keys asked for.
  void finish(bool report_unknown = true);

 private:
  template <class T>
  bool scalar(const std::string& k, const char* what, T& out);
  bool in_range(const std::string& full_key, double v, const KeyRange& r);
  YAML::Node node_;
  std::string path_, pattern_;  // pattern_: path_ with list indices as N
  SceneProblems& problems_;
  std::size_t first_problem_;
  std::set<std::string> allowed_, reported_;
};

// A range as the messages and documents write it: "(0, inf]".
std::string range_text(const KeyRange& r);
// The allowed values of a row's choices, in order.
std::vector<std::string> choices_of(const SceneKey& row);

}  // namespace sphdem
