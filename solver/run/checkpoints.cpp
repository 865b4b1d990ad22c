#include "run/checkpoints.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <system_error>

namespace sphdem {

namespace fs = std::filesystem;

namespace {
constexpr const char* kPrefix = "ckpt_";
constexpr const char* kSuffix = ".h5";

// The directory entry of a rename on the disk too (POSIX: fsync the directory).
void sync_directory(const std::string& dir) {
  const int fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY);
  if (fd < 0) return;
  ::fsync(fd);
  ::close(fd);
}
}  // namespace

std::string CheckpointStore::directory(const std::string& run_dir) {
  return (fs::path(run_dir) / "checkpoints").string();
}

CheckpointStore::CheckpointStore(std::string run_dir, int keep, const RankComm& comm)
    : dir_(directory(run_dir)), keep_(std::max(1, keep)), comm_(comm) {
  std::error_code ec;
  if (comm_.rank() == 0) fs::create_directories(dir_, ec);
  const std::string why = comm_.broadcast(ec ? ec.message() : std::string(), 0);
  if (!why.empty()) throw CheckpointError("cannot create " + dir_ + ": " + why);
  const auto existing = list(run_dir);
  if (!existing.empty()) last_ = existing.back();
}

std::vector<std::string> CheckpointStore::list(const std::string& run_dir) {
  std::vector<std::string> out;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(directory(run_dir), ec)) {
    const std::string name = e.path().filename().string();
    if (name.rfind(kPrefix, 0) == 0 && name.size() > std::string(kSuffix).size() &&
        name.compare(name.size() - 3, 3, kSuffix) == 0)
      out.push_back(e.path().string());
  }
  std::sort(out.begin(), out.end());  // ckpt_<12-digit step>: name order is step order
  return out;
}

std::string CheckpointStore::write(long step, const std::function<void(CheckpointWriter&)>& fill) {
  const std::string path =
      (fs::path(dir_) / fmt::format("{}{:012d}{}", kPrefix, step, kSuffix)).string();
  const std::string tmp = path + ".tmp";
  try {
    CheckpointWriter w(tmp, comm_);
    fill(w);
    w.finish();
  } catch (const CheckpointError& e) {
    std::error_code ec;
    if (comm_.rank() == 0) fs::remove(tmp, ec);
    throw CheckpointError(fmt::format("{}; {}", e.what(),
                                      last_.empty()
                                          ? std::string("no earlier checkpoint")
                                          : "the previous checkpoint " + last_ + " is whole"));
  }
  std::error_code ec;
  if (comm_.rank() == 0) {
    fs::rename(tmp, path, ec);
    if (ec) fs::remove(tmp, ec);
  }
  const std::string why = comm_.broadcast(ec ? ec.message() : std::string(), 0);
  if (!why.empty()) throw CheckpointError("cannot rename " + tmp + ": " + why);
  last_ = path;
  if (comm_.rank() != 0) return path;
  sync_directory(dir_);
  // the newest keep_ stay (and any stray temporary file of a killed run goes)
  auto all = list(fs::path(dir_).parent_path().string());
  for (std::size_t k = 0; k + keep_ < all.size(); ++k) fs::remove(all[k], ec);
  for (const auto& e : fs::directory_iterator(dir_, ec))
    if (e.path().extension() == ".tmp" && e.path().string() != tmp) fs::remove(e.path(), ec);
  return path;
}

CheckpointStore::Found CheckpointStore::newest_valid(const std::string& run_dir) {
  Found found;
  const auto all = list(run_dir);
  for (auto it = all.rbegin(); it != all.rend(); ++it) {
    try {
      found.reader = std::make_unique<CheckpointReader>(*it);
      return found;
    } catch (const CheckpointError& e) {
      found.skipped.push_back(e.what());
    }
  }
  std::string why = all.empty() ? "it holds no checkpoint" : "none reads back whole:";
  for (const auto& s : found.skipped) why += "\n  " + s;
  throw CheckpointError("cannot resume from " + directory(run_dir) + ": " + why);
}

}  // namespace sphdem
