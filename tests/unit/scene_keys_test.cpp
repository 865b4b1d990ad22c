// The scene loader and writer against the scene key table (scene/scene_keys.hpp): every
// key the writer puts in case.yaml has a row, every row is written by some scene, each
// key left out reads back as its row's default, and a value outside a row's range is
// refused naming the key and the range. The loader cannot ask for a key without a row
// (MapReader throws std::logic_error), so together a key added to one and not the other
// fails here.
#include "scene/scene_keys.hpp"

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "scene/map_reader.hpp"
#include "scene/scene.hpp"

using namespace sphdem;

namespace {

constexpr const char* kFile = "keys.yaml";

// Scenes that between them hold every key: each condition of the table (a group's
// type, a size law, a contact part's model, the double smoothing) and each of the
// either-or keys (damping or restitution) is met by one.
const std::vector<std::string> kSamples = {
    "",
    R"(species:
  - {name: glass, diameter: 1.0e-4, density: 2500}
particles:
  - {type: single, species: glass, position: [0.002, 0.002, 0.0048]}
contact:
  restitution: 0.9
  tangential: {model: linear_history, friction: 0.5, restitution: 0.8}
  rolling: {model: epsd, friction: 0.1}
)",
    R"(species:
  - {name: big, diameter: 1.5e-4, density: 2500}
  - name: sieved
    density: 2500
    size_distribution: {law: list, diameters: [9.0e-5, 1.1e-4], fractions: [0.5, 0.5], basis: volume}
particles:
  - {type: random, species: [big, sieved], fractions: [0.5, 0.5], min: [0, 0, 0], max: [0.004, 0.004, 0.002], voidage: 0.95, seed: 3}
contact:
  tangential: {model: linear_history, friction: 0.5}
coupling: {voidage_smoothing: double}
)",
    R"(species:
  - {name: a, diameter: 1.0e-4, density: 2500}
  - {name: b, diameter: 1.2e-4, density: 2500}
  - name: u
    density: 2500
    size_distribution: {law: uniform, min: 9.0e-5, max: 1.1e-4}
  - name: n
    density: 2500
    size_distribution: {law: normal, mean: 1.0e-4, std: 1.0e-5, min: 8.0e-5, max: 1.2e-4}
  - name: l
    density: 2500
    size_distribution: {law: lognormal, median: 1.0e-4, sigma_ln: 0.1, min: 8.0e-5, max: 1.2e-4}
particles:
  - {type: lattice, species: [a, b], fractions: [0.5, 0.5], min: [0, 0, 0], max: [0.004, 0.004, 0.002], voidage: 0.9, seed: 1}
  - {type: random, species: [u, n, l], fractions: [0.4, 0.3, 0.3], min: [0, 0, 0.003], max: [0.004, 0.004, 0.004], voidage: 0.97}
)",
    R"(domain: {size: [0.004, 0.004, 0.004], periodic_z: true}
species:
  - {name: glass, diameter: 1.0e-4, density: 2500}
particles:
  - {type: random, species: glass, min: [0, 0, 0], max: [0.004, 0.004, 0.004], voidage: 0.9, seed: 1}
flow: {times: [0, 0.1], superficial_velocity: [0, 1.0e-4]}
)",
};

// A key path with list indices as N ("species.N.diameter").
std::string pattern(const std::string& path) {
  std::string out, part;
  std::stringstream ss(path);
  while (std::getline(ss, part, '.')) {
    const bool index = !part.empty() && part.find_first_not_of("0123456789") == std::string::npos;
    out += (out.empty() ? "" : ".") + (index ? std::string("N") : part);
  }
  return out;
}

// Every key of a YAML tree by its path (lists of maps descended, N for the index;
// a list of values is a value), with its node.
void collect(const YAML::Node& n, const std::string& path, std::map<std::string, YAML::Node>& out) {
  const auto join = [&](const std::string& k) { return path.empty() ? k : path + "." + k; };
  if (n.IsMap()) {
    for (const auto& kv : n) {
      const std::string p = join(kv.first.Scalar());
      out[p] = kv.second;
      collect(kv.second, p, out);
    }
  } else if (n.IsSequence() && n.size() > 0 && n[0].IsMap()) {
    for (std::size_t i = 0; i < n.size(); ++i) collect(n[i], join(std::to_string(i)), out);
  }
}

const SceneKey* row_of(const std::string& path) {
  for (const SceneKey& k : kSceneKeys)
    if (k.key == pattern(path)) return &k;
  return nullptr;
}

bool plain_default(const SceneKey& k) {
  return !k.is_required && k.default_note.empty() && k.type != KeyType::kMap &&
         k.type != KeyType::kList && k.type != KeyType::kNumbers && k.type != KeyType::kNames;
}

std::string number_yaml(double x) {
  std::ostringstream s;
  s.precision(17);
  s << x;
  return s.str();
}

}  // namespace

TEST(SceneKeys, EveryWrittenKeyHasARowAndEveryRowIsWritten) {
  std::set<std::string> written;
  for (const std::string& sample : kSamples) {
    SCOPED_TRACE(sample);
    const Scene sc = load_scene_text(sample, kFile);
    std::map<std::string, YAML::Node> keys;
    collect(YAML::Load(scene_to_yaml(sc)), "", keys);
    for (const auto& [path, node] : keys) {
      EXPECT_NE(row_of(path), nullptr) << "case.yaml writes '" << path << "', which has no row";
      written.insert(pattern(path));
    }
  }
  for (const SceneKey& k : kSceneKeys)
    EXPECT_TRUE(written.count(std::string(k.key)))
        << "no scene writes '" << k.key << "' to case.yaml (the writer, or a sample, misses it)";
}

TEST(SceneKeys, AKeyLeftOutReadsAsItsDefault) {
  std::size_t checked = 0;
  for (const std::string& sample : kSamples) {
    SCOPED_TRACE(sample);
    std::map<std::string, YAML::Node> given, written;
    collect(YAML::Load(sample.empty() ? "{}" : sample), "", given);
    collect(YAML::Load(scene_to_yaml(load_scene_text(sample, kFile))), "", written);
    for (const auto& [path, node] : written) {
      const SceneKey* k = row_of(path);
      if (!k || !plain_default(*k) || given.count(path)) continue;
      ++checked;
      switch (k->type) {
        case KeyType::kNumber:
        case KeyType::kInteger:
        case KeyType::kWhole64:
          EXPECT_EQ(node.as<double>(), k->number) << path;
          break;
        case KeyType::kBoolean:
          EXPECT_EQ(node.as<bool>(), k->number != 0) << path;
          break;
        case KeyType::kText:
        case KeyType::kChoice:
          EXPECT_EQ(node.as<std::string>(), k->text) << path;
          break;
        case KeyType::kVector3:
          for (int d = 0; d < 3; ++d) EXPECT_EQ(node[d].as<double>(), k->vector[d]) << path;
          break;
        default:
          break;
      }
    }
  }
  EXPECT_GT(checked, 60u);
}

// A value just outside a row's range (at an open bound, or a little beyond a closed one)
// is refused naming the key; where no other key narrows the range, naming the range too.
TEST(SceneKeys, AValueOutsideItsRangeIsRefused) {
  std::set<std::string> tried;
  for (const std::string& sample : kSamples) {
    std::map<std::string, YAML::Node> written;
    collect(YAML::Load(scene_to_yaml(load_scene_text(sample, kFile))), "", written);
    for (const auto& [path, node] : written) {
      const SceneKey* k = row_of(path);
      if (!k || tried.count(std::string(k->key))) continue;
      const bool numeric = k->type == KeyType::kNumber || k->type == KeyType::kInteger ||
                           k->type == KeyType::kWhole64 || k->type == KeyType::kNumberOrAuto ||
                           k->type == KeyType::kVector3 || k->type == KeyType::kNumbers;
      if (!numeric) continue;
      tried.insert(std::string(k->key));
      const bool whole = k->type == KeyType::kInteger || k->type == KeyType::kWhole64;
      std::vector<double> bad;
      if (std::isfinite(k->range.lo))
        bad.push_back(k->range.lo_open ? k->range.lo
                      : whole          ? k->range.lo - 1
                                       : k->range.lo - 1e-3 * std::max(1.0, std::abs(k->range.lo)));
      if (std::isfinite(k->range.hi))
        bad.push_back(k->range.hi_open ? k->range.hi
                      : whole          ? k->range.hi + 1
                                       : k->range.hi + 1e-3 * std::max(1.0, std::abs(k->range.hi)));
      for (const double v : bad) {
        const std::string text = k->type == KeyType::kVector3
                                     ? "[" + number_yaml(v) + ", " +
                                           number_yaml(node[1].as<double>()) + ", " +
                                           number_yaml(node[2].as<double>()) + "]"
                                 : k->type == KeyType::kNumbers ? "[" + number_yaml(v) + "]"
                                                                : number_yaml(v);
        SCOPED_TRACE(path + "=" + text);
        try {
          load_scene_text(sample, kFile, {path + "=" + text});
          ADD_FAILURE() << "loaded with " << path << " = " << text;
        } catch (const SceneError& e) {
          const std::string msg = e.what();
          EXPECT_NE(msg.find("key '" + path), std::string::npos) << msg;
          if (k->extra_limits.empty() && !whole) {
            EXPECT_NE(msg.find(range_text(k->range)), std::string::npos) << msg;
          }
        }
      }
    }
  }
  std::size_t numeric_rows = 0;
  for (const SceneKey& k : kSceneKeys)
    numeric_rows += k.type == KeyType::kNumber || k.type == KeyType::kInteger ||
                    k.type == KeyType::kWhole64 || k.type == KeyType::kNumberOrAuto ||
                    k.type == KeyType::kVector3 || k.type == KeyType::kNumbers;
  EXPECT_EQ(tried.size(), numeric_rows);
}

// The table itself: unique keys, each in a section that has a row (a map or a list),
// choices where a choice needs them, defaults inside their ranges.
TEST(SceneKeys, TheTableIsWellFormed) {
  std::set<std::string_view> keys;
  for (const SceneKey& k : kSceneKeys) {
    EXPECT_TRUE(keys.insert(k.key).second) << k.key << " twice";
    const std::string_view s = k.section();
    if (!s.empty()) {
      const std::string_view owner =
          s.size() > 2 && s.substr(s.size() - 2) == ".N" ? s.substr(0, s.size() - 2) : s;
      EXPECT_TRUE(keys.count(owner))
          << k.key << ": its section '" << owner << "' has no row before it";
    }
    if (k.type == KeyType::kChoice) {
      ASSERT_NE(k.choices, nullptr) << k.key;
      if (!k.is_required) {
        const std::vector<std::string> c = choices_of(k);
        EXPECT_NE(std::find(c.begin(), c.end(), std::string(k.text)), c.end()) << k.key;
      }
    }
    if ((k.type == KeyType::kNumber || k.type == KeyType::kInteger) && plain_default(k)) {
      const KeyRange& r = k.range;
      EXPECT_TRUE((r.lo_open ? k.number > r.lo : k.number >= r.lo) &&
                  (r.hi_open ? k.number < r.hi : k.number <= r.hi))
          << k.key << ": default outside its range";
    }
  }
}
