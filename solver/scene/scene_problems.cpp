#include "scene/scene_problems.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>

#include "scene/did_you_mean.hpp"
#include "scene/scene.hpp"

namespace sphdem {

namespace {

std::string join(const std::string& section, const std::string& key) {
  return section.empty() ? key : section + "." + key;
}

// A section with its list indices as N ('species.2' -> 'species.N'): the hint names the
// kind of section, not one entry of a list.
std::string generic(const std::string& section) {
  std::string out, part;
  for (std::size_t i = 0; i <= section.size(); ++i) {
    if (i < section.size() && section[i] != '.') {
      part += section[i];
      continue;
    }
    const bool index = !part.empty() && std::all_of(part.begin(), part.end(), [](char c) {
      return std::isdigit(static_cast<unsigned char>(c));
    });
    out += (out.empty() ? "" : ".") + (index ? std::string("N") : part);
    part.clear();
  }
  return out;
}

}  // namespace

void SceneProblems::add(const std::string& key, const std::string& what) {
  entries_.push_back(
      {fmt::format("{}: key '{}'{}: {}", file_, key.empty() ? "<top>" : key, origin(key), what),
       "",
       "",
       {}});
}

void SceneProblems::add_line(const std::string& line) {
  entries_.push_back({line, "", "", {}});
}

void SceneProblems::unknown(const std::string& section, const std::string& key,
                            const std::set<std::string>& allowed) {
  entries_.push_back({"", section, key, {allowed.begin(), allowed.end()}});
}

void SceneProblems::declare(const std::string& section, const std::set<std::string>& keys) {
  sections_.emplace_back(section, keys);
}

void SceneProblems::override_applied(const std::string& path, const std::string& assignment) {
  overrides_.emplace_back(path, assignment);
}

std::string SceneProblems::origin(const std::string& key) const {
  for (auto it = overrides_.rbegin(); it != overrides_.rend(); ++it) {  // the last one wins
    const std::string& p = it->first;
    if (key == p || key.rfind(p + ".", 0) == 0 || p.rfind(key + ".", 0) == 0)
      return fmt::format(" (from --set '{}')", it->second);
  }
  return "";
}

// The hint: the closest key of its own section; else the same key in other sections;
// else the closest key of other sections. `known` is every (section, key) declared, with
// the sections' list indices as N, each once.
std::string SceneProblems::unknown_line(
    const Entry& e, const std::vector<std::pair<std::string, std::string>>& known) const {
  std::string hint = closest_name(e.key, e.allowed);
  if (hint.empty()) {
    const std::string own = generic(e.section);
    std::vector<std::string> same, keys, full;
    for (const auto& [section, k] : known) {
      if (section == own) continue;
      if (k == e.key && same.size() < 3) same.push_back(join(section, k));
      keys.push_back(k);
      full.push_back(join(section, k));
    }
    if (!same.empty()) {
      hint = fmt::format("{}", fmt::join(same, "' or '"));
    } else {
      const std::string best = closest_name(e.key, keys);
      for (std::size_t i = 0; i < keys.size() && !best.empty(); ++i)
        if (keys[i] == best) {
          hint = full[i];
          break;
        }
    }
  }
  const std::string key = join(e.section, e.key);
  return fmt::format("{}: key '{}'{}: unknown key; {}allowed here: {}", file_, key, origin(key),
                     hint.empty() ? "" : fmt::format("did you mean '{}'? ", hint),
                     fmt::join(e.allowed, ", "));
}

void SceneProblems::throw_if_any() const {
  if (entries_.empty()) return;
  std::vector<std::pair<std::string, std::string>> known;
  std::set<std::pair<std::string, std::string>> seen;
  for (const auto& [section, keys] : sections_) {
    const std::string g = generic(section);
    for (const std::string& k : keys)
      if (seen.emplace(g, k).second) known.emplace_back(g, k);
  }
  std::string text;
  for (const Entry& e : entries_) {
    if (!text.empty()) text += "\n";
    text += e.line.empty() ? unknown_line(e, known) : e.line;
  }
  throw SceneError(text);
}

void SceneProblems::stop(const std::string& key, const std::string& what) {
  add(key, what);
  throw_if_any();
  throw SceneError(file_);  // not reached: there is one problem at least
}

}  // namespace sphdem
