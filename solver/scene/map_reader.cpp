#include "scene/map_reader.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "scene/did_you_mean.hpp"

namespace sphdem {

MapReader::MapReader(const YAML::Node& node, std::string path, SceneProblems& problems)
    : node_(node), path_(std::move(path)), problems_(problems), first_problem_(problems.count()) {
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

bool MapReader::in_range(const std::string& full_key, double v, double lo, double hi, bool lo_open,
                         bool hi_open) {
  if (!std::isfinite(v)) {
    fail(full_key, fmt::format("must be a finite number (got {})", v));
    return false;
  }
  if ((lo_open ? v <= lo : v < lo) || (hi_open ? v >= hi : v > hi)) {
    fail(full_key, fmt::format("must be in {}{}, {}{} (got {})", lo_open ? "(" : "[", lo, hi,
                               hi_open ? ")" : "]", v));
    return false;
  }
  return true;
}

double MapReader::number(const std::string& k, double def, double lo, double hi, bool lo_open,
                         bool hi_open) {
  double v = def;
  if (has(k) && !scalar(k, "a number", v)) return def;
  return in_range(key(k), v, lo, hi, lo_open, hi_open) ? v : def;
}

double MapReader::required(const std::string& k, double lo, double hi, bool lo_open) {
  if (!has(k)) {
    fail(key(k), fmt::format("is required: a number in {}{}, {}]", lo_open ? "(" : "[", lo, hi));
    return 0.0;
  }
  const std::size_t before = problems_.count();
  const double v = number(k, 0.0, lo, hi, lo_open);
  return problems_.count() == before ? v : 0.0;
}

std::optional<std::vector<double>> MapReader::numbers(const std::string& k, double lo, double hi,
                                                      bool lo_open) {
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
    ok = in_range(ki, v[i], lo, hi, lo_open) && ok;
  }
  return ok ? std::optional<std::vector<double>>(v) : std::nullopt;
}

std::int64_t MapReader::whole64(const std::string& k, std::int64_t def, std::int64_t lo,
                                std::int64_t hi) {
  std::int64_t v = def;
  if (has(k) && !scalar(k, "a whole number", v)) return def;
  if (v >= lo && v <= hi) return v;
  fail(key(k), fmt::format("must be a whole number in [{}, {}] (got {})", lo, hi, v));
  return def;
}

int MapReader::integer(const std::string& k, int def, int lo, int hi) {
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

std::string MapReader::text(const std::string& k, const std::string& def) {
  std::string v = def;
  return has(k) && scalar(k, "a string", v) ? v : def;
}

std::optional<std::string> MapReader::choice(const std::string& k, const std::string& def,
                                             const std::vector<std::string>& allowed) {
  std::string v = def;
  if (has(k) && !scalar(k, "a string", v)) return std::nullopt;
  if (std::find(allowed.begin(), allowed.end(), v) != allowed.end()) return v;
  fail(key(k), fmt::format("must be one of: {} (got '{}'){}", fmt::join(allowed, ", "), v,
                           did_you_mean(v, allowed)));
  return std::nullopt;
}

std::array<double, 3> MapReader::vec3(const std::string& k, std::array<double, 3> def) {
  if (!has(k)) return def;
  const YAML::Node n = child(k);
  if (!n.IsSequence() || n.size() != 3) {
    fail(key(k), "must be a list of 3 numbers [x, y, z]");
    return def;
  }
  std::array<double, 3> v{};
  for (std::size_t d = 0; d < 3; ++d) {
    try {
      v[d] = n[d].as<double>();
    } catch (const YAML::Exception&) {
      fail(key(k), "must be a list of 3 numbers [x, y, z]");
      return def;
    }
    if (!std::isfinite(v[d])) {
      fail(key(k), "must be finite numbers");
      return def;
    }
  }
  return v;
}

void MapReader::expect(std::initializer_list<const char*> keys) {
  for (const char* k : keys) allowed_.insert(k);
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
