#pragma once
// One checkpoint file (HDF5): named one-dimensional arrays and scalars, with a CRC-32
// over every entry, so that a file cut short or damaged is refused when it is read.
//
// Layout for the MPI decomposition: each particle field is one global dataset (the
// ranks' owned particles one after the other, in rank order). On one rank the file is
// built in memory and written by write() and fsync(); on several (a writer made with a
// parallel RankComm) every rank writes its slice of each `distributed` entry into the same
// file with parallel HDF5 (MPI-IO, collective), and the entry's CRC-32 is the ranks'
// slices' CRCs combined in rank order (zlib's crc32_combine): the same checksum, and the
// same datasets, as one rank writing the whole array. One file per checkpoint keeps the
// commit one rename, and a run can be resumed on any number of ranks: each reads a slice
// and the decomposition moves particles to their owners.
//
// Entry names are paths ("fluid/x", "run/time"); a scalar is an array of one. Text
// (the resolved scene) is an array of bytes. The checksum is the CRC-32 of every
// entry's name, type and bytes in name order, kept as the root attribute "crc32".
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace sphdem {

class RankComm;

// A checkpoint that cannot be written or read back (the message names the file and
// the cause: the disk, a checksum, a missing entry).
struct CheckpointError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

enum class EntryType : std::uint8_t { kF64, kI64, kI32, kU32, kU16, kU8 };

template <class T>
constexpr EntryType entry_type_of();
template <>
constexpr EntryType entry_type_of<double>() {
  return EntryType::kF64;
}
template <>
constexpr EntryType entry_type_of<std::int64_t>() {
  return EntryType::kI64;
}
template <>
constexpr EntryType entry_type_of<std::int32_t>() {
  return EntryType::kI32;
}
template <>
constexpr EntryType entry_type_of<std::uint32_t>() {
  return EntryType::kU32;
}
template <>
constexpr EntryType entry_type_of<std::uint16_t>() {
  return EntryType::kU16;
}
template <>
constexpr EntryType entry_type_of<std::uint8_t>() {
  return EntryType::kU8;
}

// Writes a new file at `path` (the caller's temporary name; see checkpoints.hpp for
// the rename). Every write throws CheckpointError on failure (a full disk, a file-size
// limit), naming the file and the system's reason.
class CheckpointWriter {
 public:
  explicit CheckpointWriter(std::string path);
  // Every rank of `comm` makes the same calls in the same order (collective); with one
  // rank it is the writer above.
  CheckpointWriter(std::string path, const RankComm& comm);
  ~CheckpointWriter();  // closes a file not finished (it stays incomplete, unverified)
  CheckpointWriter(const CheckpointWriter&) = delete;
  CheckpointWriter& operator=(const CheckpointWriter&) = delete;

  template <class T>
  void array(const std::string& name, const T* data, std::size_t n) {
    put(name, entry_type_of<T>(), data, n, sizeof(T));
  }
  template <class T>
  void array(const std::string& name, const std::vector<T>& v) {
    array(name, v.data(), v.size());
  }
  template <class T>
  void scalar(const std::string& name, T value) {
    array(name, &value, 1);
  }
  void text(const std::string& name, const std::string& s);
  // One global array of which this rank holds the slice `data` of n values; the slices
  // follow one another in rank order. (`array` and `scalar`: the same on every rank.)
  template <class T>
  void distributed(const std::string& name, const T* data, std::size_t n) {
    put_slice(name, entry_type_of<T>(), data, n, sizeof(T));
  }
  template <class T>
  void distributed(const std::string& name, const std::vector<T>& v, std::size_t n) {
    distributed(name, v.data(), n);
  }
  // Writes the checksum, closes the file and flushes it to the disk (fsync).
  void finish();

 private:
  void open_in_memory();  // one rank: the file built in memory, written by finish()
  void put(const std::string& name, EntryType type, const void* data, std::size_t n,
           std::size_t size);
  void put_slice(const std::string& name, EntryType type, const void* data, std::size_t n,
                 std::size_t size);
  void finish_parallel();
  const RankComm* comm_ = nullptr;  // set with several ranks: the file is written by all
  std::string path_;
  std::int64_t file_ = -1;
  std::map<std::string, std::uint32_t> crcs_;  // per entry, combined in name order
};

// Reads a whole file and checks its checksum; throws CheckpointError (naming the file)
// when it cannot be opened, is cut short, or its checksum does not match.
class CheckpointReader {
 public:
  explicit CheckpointReader(const std::string& path);

  const std::string& path() const { return path_; }
  bool has(const std::string& name) const { return entries_.count(name) > 0; }
  template <class T>
  std::vector<T> array(const std::string& name) const {
    const Entry& e = entry(name, entry_type_of<T>());
    std::vector<T> v(e.bytes.size() / sizeof(T));
    if (!v.empty()) std::memcpy(v.data(), e.bytes.data(), e.bytes.size());
    return v;
  }
  template <class T>
  T scalar(const std::string& name) const {
    const std::vector<T> v = array<T>(name);
    if (v.size() != 1) fail(name, "is not a scalar");
    return v[0];
  }
  std::string text(const std::string& name) const;
  // Names of the entries under a group ("fluid/"), without the prefix.
  std::vector<std::string> names(const std::string& group) const;

 private:
  struct Entry {
    EntryType type;
    std::vector<unsigned char> bytes;
  };
  const Entry& entry(const std::string& name, EntryType type) const;
  [[noreturn]] void fail(const std::string& name, const std::string& what) const;
  std::string path_;
  std::map<std::string, Entry> entries_;
};

}  // namespace sphdem
