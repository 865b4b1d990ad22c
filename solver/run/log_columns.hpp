#pragma once
// The one table of log.csv's columns (name, unit, meaning, and how a row prints it);
// RunLog writes them in this order and cases/README.md's table of them is rendered from it
// (run/table_docs.hpp). Adding a column: its field in Diagnostics and a row here.
#include <cstddef>
#include <string>
#include <vector>

#include "analysis/diagnostics.hpp"

namespace sphdem {

struct LogColumn {
  const char* name;  // per species: the prefix of NAME:<species>
  const char* unit;
  const char* meaning;
  bool per_species;
  // Appends the value (for species s where per_species) to a row, without a separator.
  void (*append)(std::string& row, const Diagnostics& d, std::size_t s);
};

// The columns in their order; a per-species column stands for one column per species, in
// the order of `species` (every vz_mean:S, then every slip_z_mean:S, ...).
const std::vector<LogColumn>& log_columns();

}  // namespace sphdem
