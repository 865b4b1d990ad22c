#include "scene/map_reader.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "scene/did_you_mean.hpp"
#include "scene/scene_keys.hpp"

namespace sphdem {

std::string range_text(const KeyRange& r) {
  return fmt::format("{}{}, {}{}", r.lo_open ? "(" : "[", r.lo, r.hi, r.hi_open ? ")" : "]");
}

MapReader::MapReader(const YAML::Node& node, std::string path, SceneProblems& problems)
    : node_(node), path_(std::move(path)), problems_(problems), first_problem_(problems.count()) {
  for (std::size_t i = 0; i < path_.size();) {  // "species.2.size_distribution" -> "species.N..."
    std::size_t end = path_.find('.', i);
    if (end == std::string::npos) end = path_.size();
    const std::string part = path_.substr(i, end - i);
    const bool index = !part.empty() && part.find_first_not_of("0123456789") == std::string::npos;
    pattern_ += (pattern_.empty() ? "" : ".") + (index ? std::string("N") : part);
    i = end + 1;
  }
  if (node_ && node_.IsNull()) node_ = YAML::Node(YAML::NodeType::Undefined);  // "section:" alone
  if (node_ && !node_.IsMap()) {
    fail(path_, "must be a map of keys");
    node_ = YAML::Node(YAML::NodeType::Undefined);
  }
  std::set<std::string> seen;
  for (const auto& kv : node_) {  // yaml-cpp keeps the first of duplicate keys silently
    if (!kv.first.IsScalar()) {
      fail(path_, "every key must be a plain name");
      continue;
    }
    const std::string k = kv.first.Scalar();
    if (!seen.insert(k).second) fail(key(k), "given twice");
  }
}

bool MapReader::has(const std::string& k) {
  row(k);  // every key asked for has its row
  allowed_.insert(k);
  const YAML::Node& n = node_;  // const lookup: never inserts the key
  return n && n[k];
}

YAML::Node MapReader::child(const std::string& k) {
  return has(k) ? static_cast<const YAML::Node&>(node_)[k] : YAML::Node(YAML::NodeType::Undefined);
}

template <class T>
bool MapReader::scalar(const std::string& k, const char* what, T& out) {
  const YAML::Node n = child(k);
  if (!n.IsScalar()) {
    fail(key(k), fmt::format("must be {}", what));
    return false;
  }
  try {
    out = n.as<T>();
    return true;
  } catch (const YAML::Exception&) {
    fail(key(k), fmt::format("must be {} (got '{}')", what, n.Scalar()));
    return false;
  }
}

const SceneKey& MapReader::row(const std::string& k) const {
  const std::string path = pattern_.empty() ? k : pattern_ + "." + k;
  for (const SceneKey& r : kSceneKeys)
    if (r.key == path) return r;
  throw std::logic_error("scene key '" + path + "' has no row in scene/scene_keys.hpp");
}

bool MapReader::in_range(const std::string& full_key, double v, const KeyRange& r) {
  if (!std::isfinite(v)) {
    fail(full_key, fmt::format("must be a finite number (got {})", v));
    return false;
  }
  if ((r.lo_open ? v <= r.lo : v < r.lo) || (r.hi_open ? v >= r.hi : v > r.hi)) {
    fail(full_key, fmt::format("must be in {} (got {})", range_text(r), v));
    return false;
  }
  return true;
}

double MapReader::number(const std::string& k, double def) {
  const KeyRange& r = row(k).range;
  return number_within(k, def, r.lo, r.hi);
}

double MapReader::number_within(const std::string& k, double def, double lo, double hi) {
  KeyRange r = row(k).range;
  if (lo < r.lo || hi > r.hi)
    throw std::logic_error("scene key '" + key(k) + "': a range beyond its row's");
  r.lo = lo;
  r.hi = hi;
  double v = def;
  if (has(k) && !scalar(k, "a number", v)) return def;
  return in_range(key(k), v, r) ? v : def;
}

double MapReader::required(const std::string& k) {
  if (!has(k)) {
    fail(key(k), fmt::format("is required: a number in {}", range_text(row(k).range)));
    return 0.0;
  }
  const std::size_t before = problems_.count();
  const double v = number(k, 0.0);
  return problems_.count() == before ? v : 0.0;
}

std::optional<std::vector<double>> MapReader::numbers(const std::string& k) {
  const KeyRange& r = row(k).range;
  const YAML::Node n = child(k);
  if (!n.IsSequence() || n.size() == 0) {
    fail(key(k), "must be a non-empty list of numbers");
    return std::nullopt;
  }
  std::vector<double> v(n.size());
  bool ok = true;
  for (std::size_t i = 0; i < n.size(); ++i) {
    const std::string ki = fmt::format("{}.{}", key(k), i);
    if (!n[i].IsScalar()) {
      fail(ki, "must be a number");
      ok = false;
      continue;
    }
    try {
      v[i] = n[i].as<double>();
    } catch (const YAML::Exception&) {
      fail(ki, fmt::format("must be a number (got '{}')", n[i].Scalar()));
      ok = false;
      continue;
    }
    ok = in_range(ki, v[i], r) && ok;
  }
  return ok ? std::optional<std::vector<double>>(v) : std::nullopt;
}

std::int64_t MapReader::whole64(const std::string& k) {
  const SceneKey& rw = row(k);
  const auto lo = static_cast<std::int64_t>(rw.range.lo);
  const std::int64_t hi = std::isinf(rw.range.hi) ? std::numeric_limits<std::int64_t>::max()
                                                  : static_cast<std::int64_t>(rw.range.hi);
  const auto def = static_cast<std::int64_t>(rw.number);
  std::int64_t v = def;
  if (has(k) && !scalar(k, "a whole number", v)) return def;
  if (v >= lo && v <= hi) return v;
  fail(key(k), fmt::format("must be a whole number in [{}, {}] (got {})", lo, hi, v));
  return def;
}

int MapReader::integer(const std::string& k, int def, int lo_from_other_keys) {
  const KeyRange& r = row(k).range;
  const int lo = std::max(static_cast<int>(r.lo), lo_from_other_keys);
  const int hi = static_cast<int>(r.hi);
  int v = def;
  if (has(k) && !scalar(k, "a whole number", v)) return def;
  if (v >= lo && v <= hi) return v;
  fail(key(k), fmt::format("must be a whole number in [{}, {}] (got {})", lo, hi, v));
  return def;
}

bool MapReader::boolean(const std::string& k, bool def) {
  bool v = def;
  return has(k) && scalar(k, "true or false", v) ? v : def;
}

std::string MapReader::text(const std::string& k) {
  std::string v(row(k).text);
  return has(k) && scalar(k, "a string", v) ? v : std::string(row(k).text);
}

std::vector<std::string> choices_of(const SceneKey& row) {
  std::vector<std::string> out;
  for (const char* const* c = row.choices; c && *c; ++c) out.emplace_back(*c);
  return out;
}

std::optional<std::string> MapReader::choice(const std::string& k, const std::string& def) {
  const std::vector<std::string> allowed = choices_of(row(k));
  std::string v = def;
  if (has(k) && !scalar(k, "a string", v)) return std::nullopt;
  if (std::find(allowed.begin(), allowed.end(), v) != allowed.end()) return v;
  fail(key(k), fmt::format("must be one of: {} (got '{}'){}", fmt::join(allowed, ", "), v,
                           did_you_mean(v, allowed)));
  return std::nullopt;
}

bool MapReader::number_or_auto(const std::string& k, double& v) {
  if (!has(k) || (child(k).IsScalar() && child(k).Scalar() == "auto")) return true;
  v = number(k, v);
  return false;
}

std::array<double, 3> MapReader::vec3(const std::string& k, std::array<double, 3> def) {
  if (!has(k)) return def;
  const KeyRange& r = row(k).range;
  const YAML::Node n = child(k);
  const std::string what =
      std::isinf(r.lo) && std::isinf(r.hi)
          ? std::string("must be a list of 3 numbers [x, y, z]")
          : fmt::format("must be a list of 3 numbers [x, y, z], each in {}", range_text(r));
  if (!n.IsSequence() || n.size() != 3) {
    fail(key(k), what);
    return def;
  }
  std::array<double, 3> v{};
  for (std::size_t d = 0; d < 3; ++d) {
    try {
      v[d] = n[d].as<double>();
    } catch (const YAML::Exception&) {
      fail(key(k), what);
      return def;
    }
    if (!std::isfinite(v[d])) {
      fail(key(k), "must be finite numbers");
      return def;
    }
    if ((r.lo_open ? v[d] <= r.lo : v[d] < r.lo) || (r.hi_open ? v[d] >= r.hi : v[d] > r.hi)) {
      fail(key(k),
           fmt::format("{} (got [{}, {}, {}])", what, n[0].Scalar(), n[1].Scalar(), n[2].Scalar()));
      return def;
    }
  }
  return v;
}

void MapReader::expect_table_keys() {
  for (const SceneKey& r : kSceneKeys)
    if (r.section() == pattern_) allowed_.insert(std::string(r.name()));
  finish();
}

void MapReader::finish(bool report_unknown) {
  problems_.declare(path_, allowed_);
  if (!report_unknown) return;
  for (const auto& kv : node_) {
    if (!kv.first.IsScalar()) continue;  // reported when the reader was made
    const std::string k = kv.first.Scalar();
    if (!allowed_.count(k) && reported_.insert(k).second) problems_.unknown(path_, k, allowed_);
  }
}

}  // namespace sphdem
