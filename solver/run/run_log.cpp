#include "run/run_log.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "run/log_columns.hpp"

namespace sphdem {

std::vector<std::string> RunLog::columns(const std::vector<SpeciesSpec>& species) {
  std::vector<std::string> c;
  for (const LogColumn& col : log_columns()) {
    if (!col.per_species) c.push_back(col.name);
    for (std::size_t s = 0; col.per_species && s < species.size(); ++s)
      c.push_back(fmt::format("{}:{}", col.name, species[s].name));
  }
  return c;
}

RunLog::RunLog(const std::string& path, const std::vector<SpeciesSpec>& species) : out_(path) {
  if (!out_) throw std::runtime_error("cannot write " + path);
  out_ << fmt::format("{}\n", fmt::join(columns(species), ","));
  out_.flush();
}

RunLog::RunLog(const std::string& path, const std::vector<SpeciesSpec>& species,
               long keep_through_step) {
  const std::vector<std::string> cols = columns(species);
  const std::string header = fmt::format("{}", fmt::join(cols, ","));
  std::string kept = header + "\n";
  {
    std::ifstream in(path);
    std::string line;
    if (in && std::getline(in, line) && line != header)
      throw std::runtime_error(path + ": its columns are not this scene's; cannot continue it");
    while (std::getline(in, line)) {
      const auto comma = line.find(',');
      if (static_cast<std::size_t>(std::count(line.begin(), line.end(), ',')) + 1 != cols.size())
        break;  // a row cut short by a kill
      char* end = nullptr;
      const long step = std::strtol(line.c_str() + comma + 1, &end, 10);
      if (*end != ',' || step > keep_through_step) break;
      kept += line + "\n";
    }
  }
  {
    std::ofstream tmp(path + ".tmp");
    tmp << kept;
    if (!tmp.flush()) throw std::runtime_error("cannot write " + path + ".tmp");
  }
  std::filesystem::rename(path + ".tmp", path);
  out_.open(path, std::ios::app);
  if (!out_) throw std::runtime_error("cannot write " + path);
}

void RunLog::write(const Diagnostics& d) {
  std::string row;
  for (const LogColumn& col : log_columns()) {
    const std::size_t n = col.per_species ? d.com_z.size() : 1;
    for (std::size_t s = 0; s < n; ++s) {
      if (!row.empty()) row += ',';
      col.append(row, d, s);
    }
  }
  out_ << row << '\n';
  out_.flush();
}

}  // namespace sphdem
