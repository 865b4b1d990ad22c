#pragma once
// One row of the scene key table (scene/scene_keys.hpp): what a key of a scene file is,
// its unit, default, allowed range and one line of meaning. The loader reads every key
// through its row (scene/map_reader.hpp), so a value's type, default and range come from
// here; the documents (cases/README.md), the fuzz dictionary and the tests follow from
// the rows. Rows are built with the constexpr helpers below (number, integer, ...), and
// a few modifiers (required, note, when, limits).
#include <array>
#include <cstddef>
#include <limits>
#include <string_view>

namespace sphdem {

enum class KeyType {
  kMap,           // a section: its keys are rows of their own
  kList,          // a list of maps (species, particles): rows "list.N.key"
  kNumber,        // a finite real
  kNumberOrAuto,  // a real, or `auto` (the loader resolves it)
  kInteger,       // a whole number (int)
  kWhole64,       // a whole number (64-bit: seeds)
  kBoolean,
  kText,
  kChoice,   // one of `choices`
  kVector3,  // [x, y, z]
  kNumbers,  // a non-empty list of reals, each in range
  kNames,    // a non-empty list of names (of `choices` where given)
};

inline constexpr double kInf = std::numeric_limits<double>::infinity();

struct KeyRange {
  double lo = -kInf, hi = kInf;
  bool lo_open = false, hi_open = false;
};
constexpr KeyRange closed(double lo, double hi) {
  return {lo, hi, false, false};
}
constexpr KeyRange above(double lo) {
  return {lo, kInf, true, false};
}  // (lo, inf]
constexpr KeyRange at_least(double lo) {
  return {lo, kInf, false, false};
}
constexpr KeyRange half_open(double lo, double hi) {
  return {lo, hi, false, true};
}  // [lo, hi)
constexpr KeyRange left_open(double lo, double hi) {
  return {lo, hi, true, false};
}  // (lo, hi]
constexpr KeyRange any_finite() {
  return {};
}

struct SceneKey {
  std::string_view key;  // full path; list entries as N ("species.N.diameter")
  KeyType type = KeyType::kMap;
  std::string_view unit = "–";
  double number = 0;                      // default of a number, integer or boolean (0/1)
  std::array<double, 3> vector{0, 0, 0};  // default of a vector
  std::string_view text;                  // default of a text or a choice
  KeyRange range;                         // numbers, integers, vectors and lists: each entry
  const char* const* choices = nullptr;   // kChoice, kNames: null-terminated
  std::string_view doc;                   // one line: the meaning and the equations it feeds
  bool is_required = false;
  std::string_view default_note;  // the default in words where a value does not say it
  std::string_view condition;     // "KEY=v1|v2": only where the map's KEY has one of these
  std::string_view extra_limits;  // limits across keys, in words (the loader checks them)

  constexpr SceneKey required() const {
    SceneKey k = *this;
    k.is_required = true;
    return k;
  }
  constexpr SceneKey note(std::string_view n) const {
    SceneKey k = *this;
    k.default_note = n;
    return k;
  }
  constexpr SceneKey when(std::string_view c) const {
    SceneKey k = *this;
    k.condition = c;
    return k;
  }
  constexpr SceneKey limits(std::string_view l) const {
    SceneKey k = *this;
    k.extra_limits = l;
    return k;
  }
  // the key's last part ("diameter" of "species.N.diameter")
  constexpr std::string_view name() const { return key.substr(key.rfind('.') + 1); }
  // the map it lies in ("species.N"; "" at the top level)
  constexpr std::string_view section() const {
    const std::size_t dot = key.rfind('.');
    return dot == std::string_view::npos ? std::string_view() : key.substr(0, dot);
  }
};

namespace key_rows {
constexpr SceneKey map(std::string_view key, std::string_view doc) {
  SceneKey k;
  k.key = key;
  k.type = KeyType::kMap;
  k.doc = doc;
  return k;
}
constexpr SceneKey list(std::string_view key, std::string_view doc) {
  SceneKey k = map(key, doc);
  k.type = KeyType::kList;
  return k;
}
constexpr SceneKey number(std::string_view key, std::string_view unit, double def, KeyRange range,
                          std::string_view doc) {
  SceneKey k = map(key, doc);
  k.type = KeyType::kNumber;
  k.unit = unit;
  k.number = def;
  k.range = range;
  return k;
}
constexpr SceneKey number_or_auto(std::string_view key, std::string_view unit, KeyRange range,
                                  std::string_view doc) {
  SceneKey k = number(key, unit, 0, range, doc);
  k.type = KeyType::kNumberOrAuto;
  k.text = "auto";
  return k;
}
constexpr SceneKey integer(std::string_view key, std::string_view unit, int def, KeyRange range,
                           std::string_view doc) {
  SceneKey k = number(key, unit, def, range, doc);
  k.type = KeyType::kInteger;
  return k;
}
constexpr SceneKey whole64(std::string_view key, double def, std::string_view doc) {
  SceneKey k = number(key, "–", def, at_least(0), doc);
  k.type = KeyType::kWhole64;
  return k;
}
constexpr SceneKey boolean(std::string_view key, bool def, std::string_view doc) {
  SceneKey k = map(key, doc);
  k.type = KeyType::kBoolean;
  k.number = def ? 1 : 0;
  return k;
}
constexpr SceneKey text(std::string_view key, std::string_view def, std::string_view doc) {
  SceneKey k = map(key, doc);
  k.type = KeyType::kText;
  k.text = def;
  return k;
}
constexpr SceneKey choice(std::string_view key, const char* const* choices, std::string_view def,
                          std::string_view doc) {
  SceneKey k = text(key, def, doc);
  k.type = KeyType::kChoice;
  k.choices = choices;
  return k;
}
constexpr SceneKey vector3(std::string_view key, std::string_view unit, std::array<double, 3> def,
                           KeyRange range, std::string_view doc) {
  SceneKey k = number(key, unit, 0, range, doc);
  k.type = KeyType::kVector3;
  k.vector = def;
  return k;
}
constexpr SceneKey numbers(std::string_view key, std::string_view unit, KeyRange each,
                           std::string_view doc) {
  SceneKey k = number(key, unit, 0, each, doc);
  k.type = KeyType::kNumbers;
  return k;
}
constexpr SceneKey names(std::string_view key, const char* const* choices, std::string_view doc) {
  SceneKey k = map(key, doc);
  k.type = KeyType::kNames;
  k.choices = choices;
  return k;
}
}  // namespace key_rows

}  // namespace sphdem
