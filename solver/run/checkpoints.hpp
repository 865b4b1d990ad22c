#pragma once
// DIR/checkpoints/: a run's checkpoints, ckpt_<step>.h5 (io/checkpoint_file.hpp). Each is
// written under a temporary name, flushed to the disk and renamed, so a checkpoint that
// exists under its name is whole; then all but the newest `keep` are removed. Resuming
// takes the newest that reads back whole (its checksum), warning about newer ones that
// do not, so a damaged or cut newest file costs one interval, never the run.
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "domain/rank_comm.hpp"
#include "io/checkpoint_file.hpp"

namespace sphdem {

class CheckpointStore {
 public:
  // On ranks every rank writes its slices into one file (collective); rank 0 renames it
  // and removes the old ones.
  CheckpointStore(std::string run_dir, int keep, const RankComm& comm = RankComm(MPI_COMM_NULL));

  // Writes the checkpoint of `step` with `fill`. On failure (a full disk, a file-size
  // limit) removes the partial file and throws CheckpointError naming the file, the
  // reason and the previous checkpoint, which is left whole.
  std::string write(long step, const std::function<void(CheckpointWriter&)>& fill);
  // The newest checkpoint written by this store ("" before the first).
  const std::string& last() const { return last_; }

  struct Found {
    std::unique_ptr<CheckpointReader> reader;
    std::vector<std::string> skipped;  // newer files that did not read back, with why
  };
  // The newest checkpoint of a run directory that reads back whole; throws
  // CheckpointError (naming the directory and each file's fault) when there is none.
  static Found newest_valid(const std::string& run_dir);
  // Checkpoint files of a run directory, oldest first (temporary files left out).
  static std::vector<std::string> list(const std::string& run_dir);
  static std::string directory(const std::string& run_dir);

 private:
  std::string dir_;
  int keep_;
  RankComm comm_;
  std::string last_;
};

}  // namespace sphdem
