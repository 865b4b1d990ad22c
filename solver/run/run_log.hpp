#pragma once
// DIR/log.csv: one row per log interval, flushed at once so that a run that fails
// keeps every row it reached.
#include <fstream>
#include <string>
#include <vector>

#include "analysis/diagnostics.hpp"
#include "scene/scene.hpp"

namespace sphdem {

class RunLog {
 public:
  RunLog(const std::string& path, const std::vector<SpeciesSpec>& species);
  // A resumed run's log: the file's header and its rows up to `step` are kept (rows
  // written after the checkpoint are cut first), new rows follow. Throws if the file's
  // columns are not this scene's.
  RunLog(const std::string& path, const std::vector<SpeciesSpec>& species, long keep_through_step);
  void write(const Diagnostics& d);
  static std::vector<std::string> columns(const std::vector<SpeciesSpec>& species);

 private:
  std::ofstream out_;
};

}  // namespace sphdem
