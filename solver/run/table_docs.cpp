#include "run/table_docs.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>
#include <stdexcept>

#include "coupling/drag_law_table.hpp"
#include "run/log_columns.hpp"
#include "scene/fidelity.hpp"
#include "scene/insitu_pipelines.hpp"
#include "scene/map_reader.hpp"
#include "scene/scene_keys.hpp"

namespace sphdem {

namespace {

constexpr const char* kBegin = "sphdem docs:";
constexpr const char* kEnd = "end sphdem docs";

// A table cell: '|' escaped.
std::string cell(std::string_view s) {
  std::string out;
  for (char c : s) {
    if (c == '|') out += '\\';
    out += c;
  }
  return out;
}

// A number as a person writes it: 1000, 0.25, 8.9e-4.
std::string number_text(double x) {
  if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
  const double a = std::abs(x);
  if (a == 0 || (a >= 1e-3 && a < 1e4)) return fmt::format("{:g}", x);
  const int e = static_cast<int>(std::floor(std::log10(a)));
  return fmt::format("{:g}e{}", x / std::pow(10.0, e), e);
}

std::string range_of(const KeyRange& r) {
  return fmt::format("{}{}, {}{}", r.lo_open ? "(" : "[", number_text(r.lo), number_text(r.hi),
                     r.hi_open ? ")" : "]");
}

std::string choices_text(const SceneKey& k) {
  std::vector<std::string> quoted;
  for (const std::string& c : choices_of(k)) quoted.push_back("`" + c + "`");
  return fmt::format("{}", fmt::join(quoted, ", "));
}

std::string default_text(const SceneKey& k) {
  if (k.is_required) return "(required)";
  if (!k.default_note.empty()) return std::string(k.default_note);
  switch (k.type) {
    case KeyType::kNumber:
    case KeyType::kInteger:
    case KeyType::kWhole64:
      return number_text(k.number);
    case KeyType::kBoolean:
      return k.number != 0 ? "`true`" : "`false`";
    case KeyType::kText:
    case KeyType::kChoice:
      return fmt::format("`{}`", k.text.empty() ? "\"\"" : std::string(k.text));
    case KeyType::kVector3:
      return fmt::format("`[{}, {}, {}]`", number_text(k.vector[0]), number_text(k.vector[1]),
                         number_text(k.vector[2]));
    default:
      return "–";
  }
}

std::string allowed_text(const SceneKey& k) {
  std::string a;
  switch (k.type) {
    case KeyType::kMap:
      a = "a map";
      break;
    case KeyType::kList:
      a = "a list of maps";
      break;
    case KeyType::kNumber:
      a = range_of(k.range);
      break;
    case KeyType::kNumberOrAuto:
      a = range_of(k.range) + " or `auto`";
      break;
    case KeyType::kInteger:
      a = "whole number in " + range_of(k.range);
      break;
    case KeyType::kWhole64:
      a = "whole number ≥ 0";
      break;
    case KeyType::kBoolean:
      a = "`true`, `false`";
      break;
    case KeyType::kText:
      a = "a string";
      break;
    case KeyType::kChoice:
      a = choices_text(k);
      break;
    case KeyType::kVector3:
      a = std::isinf(k.range.lo) && std::isinf(k.range.hi)
              ? "3 numbers"
              : "3 numbers, each in " + range_of(k.range);
      break;
    case KeyType::kNumbers:
      a = "a list, each in " + range_of(k.range);
      break;
    case KeyType::kNames:
      a = k.choices ? "a list of " + choices_text(k) : "a list of species names";
      break;
  }
  if (!k.extra_limits.empty()) a += "; " + std::string(k.extra_limits);
  return a;
}

// "law=list|uniform" -> "(`law`: `list`, `uniform`) "
std::string condition_text(std::string_view c) {
  if (c.empty()) return "";
  const std::size_t eq = c.find('=');
  std::vector<std::string> v;
  std::stringstream ss{std::string(c.substr(eq + 1))};
  for (std::string x; std::getline(ss, x, '|');) v.push_back("`" + x + "`");
  return fmt::format("(`{}`: {}) ", c.substr(0, eq), fmt::join(v, ", "));
}

std::string keys_table(const std::vector<std::string>& sections) {
  std::string t = "| key | unit | default | allowed | meaning |\n|---|---|---|---|---|\n";
  auto listed = [&](std::string_view s) {
    return std::find(sections.begin(), sections.end(), std::string(s)) != sections.end();
  };
  for (const SceneKey& k : kSceneKeys) {
    // a map or a list heads its own section's table; any other key is in its section's
    const bool is_map = k.type == KeyType::kMap || k.type == KeyType::kList;
    if (!(is_map ? listed(k.key) : listed(k.section()))) continue;
    t += fmt::format("| `{}` | {} | {} | {} | {}{} |\n", k.key, cell(k.unit), cell(default_text(k)),
                     cell(allowed_text(k)), cell(condition_text(k.condition)), cell(k.doc));
  }
  return t;
}

std::string presets_table() {
  std::string t =
      "| preset | `fluid.resolution` | `fluid.sound_speed_factor` | `time.cfl` | "
      "`time.dem_steps_per_contact` | `contact.max_overlap` |\n|---|---|---|---|---|---|\n";
  for (const FidelityPreset& p : kFidelityPresets)
    t += fmt::format("| `{}` | {} | {} | {} | {} | {} |\n", p.name, number_text(p.resolution),
                     number_text(p.sound_speed_factor), number_text(p.cfl),
                     number_text(p.dem_steps_per_contact), number_text(p.max_overlap));
  return t;
}

std::string drag_laws_table() {
  std::string t =
      "| `drag.law` | law | equations | voidage function | valid to Re_p |\n"
      "|---|---|---|---|---|\n";
  for (const drag::DragLawInfo& l : drag::kDragLaws)
    t += fmt::format("| `{}` | {} | {} | {} | {} |\n", l.name, cell(l.description), l.equations,
                     l.voidage_function ? "yes" : "no",
                     std::isinf(l.reynolds_max) ? "any" : number_text(l.reynolds_max));
  return t;
}

std::string log_columns_table() {
  std::string t = "| column | unit | meaning |\n|---|---|---|\n";
  for (const LogColumn& c : log_columns())
    t += fmt::format("| `{}{}` | {} | {} |\n", c.name, c.per_species ? ":NAME" : "", cell(c.unit),
                     cell(c.meaning));
  return t;
}

std::string pipelines_table() {
  std::string t = "| pipeline | reads channel | writes (under `DIR/insitu/`) |\n|---|---|---|\n";
  for (const InSituPipeline& p : kInSituPipelines) {
    std::string reads(p.reads);
    for (std::size_t at = 0; (at = reads.find(", ", at)) != std::string::npos; at += 5)
      reads.replace(at, 2, "`, `");
    t += fmt::format("| `{}.py` | `{}` | {} |\n", p.name, reads, cell(p.writes));
  }
  return t;
}

std::string fuzz_dictionary() {
  std::set<std::string> words;
  for (const SceneKey& k : kSceneKeys) {
    words.emplace(k.name());
    for (const std::string& c : choices_of(k)) words.insert(c);
  }
  std::string t;
  for (const std::string& w : words) t += fmt::format("\"{}\"\n", w);
  return t;
}

}  // namespace

std::vector<std::string> scene_key_sections() {
  std::vector<std::string> out;
  for (const SceneKey& k : kSceneKeys) {
    const std::string s(k.section());
    if (std::find(out.begin(), out.end(), s) == out.end()) out.push_back(s);
  }
  return out;
}

std::string generated_block(const std::string& name) {
  std::stringstream ss(name);
  std::string word;
  ss >> word;
  if (word == "keys") {
    std::vector<std::string> sections;
    for (std::string s; ss >> s;) sections.push_back(s == "-" ? "" : s);
    if (sections.empty()) throw std::invalid_argument("'keys' needs the sections it shows");
    return keys_table(sections);
  }
  if (name == "fidelity presets") return presets_table();
  if (name == "drag laws") return drag_laws_table();
  if (name == "log columns") return log_columns_table();
  if (name == "pipelines") return pipelines_table();
  if (name == "fuzz dictionary") return fuzz_dictionary();
  throw std::invalid_argument("no generated block '" + name + "'");
}

std::string with_generated_blocks(const std::string& text) {
  std::stringstream in(text);
  std::string out, line;
  bool skipping = false;
  while (std::getline(in, line)) {
    if (skipping) {
      if (line.find(kEnd) == std::string::npos) continue;
      skipping = false;
    }
    out += line + "\n";
    const std::size_t at = line.find(kBegin);
    if (at == std::string::npos) continue;
    std::string name = line.substr(at + std::string(kBegin).size());
    const std::size_t end = name.find("-->");
    if (end != std::string::npos) name = name.substr(0, end);
    name.erase(0, name.find_first_not_of(' '));
    name.erase(name.find_last_not_of(' ') + 1);
    out += generated_block(name);
    skipping = true;
  }
  if (skipping) throw std::invalid_argument("a generated block without its 'end sphdem docs' line");
  return out;
}

}  // namespace sphdem
