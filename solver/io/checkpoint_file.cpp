#include "io/checkpoint_file.hpp"

#include <fcntl.h>
#include <hdf5.h>
#include <unistd.h>
#include <zlib.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

#include "domain/rank_comm.hpp"

namespace sphdem {

namespace {

constexpr const char* kFormat = "sphdem-checkpoint 1";

hid_t native_type(EntryType t) {
  switch (t) {
    case EntryType::kF64:
      return H5T_NATIVE_DOUBLE;
    case EntryType::kI64:
      return H5T_NATIVE_INT64;
    case EntryType::kI32:
      return H5T_NATIVE_INT32;
    case EntryType::kU32:
      return H5T_NATIVE_UINT32;
    case EntryType::kU16:
      return H5T_NATIVE_UINT16;
    case EntryType::kU8:
      return H5T_NATIVE_UINT8;
  }
  return H5T_NATIVE_UINT8;
}

std::size_t type_size(EntryType t) {
  switch (t) {
    case EntryType::kF64:
    case EntryType::kI64:
      return 8;
    case EntryType::kI32:
    case EntryType::kU32:
      return 4;
    case EntryType::kU16:
      return 2;
    case EntryType::kU8:
      return 1;
  }
  return 1;
}

// The entry type of a dataset's stored type (nullopt-like false for any other type).
bool entry_type_of_stored(hid_t type, EntryType& out) {
  if (H5Tget_class(type) == H5T_FLOAT && H5Tget_size(type) == 8) {
    out = EntryType::kF64;
    return true;
  }
  if (H5Tget_class(type) != H5T_INTEGER) return false;
  const bool is_signed = H5Tget_sign(type) == H5T_SGN_2;
  switch (H5Tget_size(type)) {
    case 8:
      out = EntryType::kI64;
      return is_signed;
    case 4:
      out = is_signed ? EntryType::kI32 : EntryType::kU32;
      return true;
    case 2:
      out = EntryType::kU16;
      return !is_signed;
    case 1:
      out = EntryType::kU8;
      return !is_signed;
    default:
      return false;
  }
}

uLong crc_of_bytes(uLong c, const void* data, std::size_t bytes);
uLong entry_crc_head(const std::string& name, EntryType type);

std::uint32_t entry_crc(const std::string& name, EntryType type, const void* data,
                        std::size_t bytes) {
  return static_cast<std::uint32_t>(crc_of_bytes(entry_crc_head(name, type), data, bytes));
}

// The CRC-32 of bytes, in pieces of at most 1 GiB (crc32 takes an unsigned int), from c.
uLong crc_of_bytes(uLong c, const void* data, std::size_t bytes) {
  const auto* p = static_cast<const Bytef*>(data);
  while (bytes > 0) {
    const std::size_t chunk = std::min<std::size_t>(bytes, 1u << 30);
    c = crc32(c, p, static_cast<uInt>(chunk));
    p += chunk;
    bytes -= chunk;
  }
  return c;
}

// The CRC-32 of an entry's name and type: where its bytes' CRC starts.
uLong entry_crc_head(const std::string& name, EntryType type) {
  uLong c = crc32(0L, Z_NULL, 0);
  c = crc32(c, reinterpret_cast<const Bytef*>(name.data()), static_cast<uInt>(name.size()));
  const unsigned char t = static_cast<unsigned char>(type);
  return crc32(c, &t, 1);
}

std::uint32_t combined_crc(const std::map<std::string, std::uint32_t>& crcs) {
  uLong c = crc32(0L, Z_NULL, 0);
  for (const auto& [name, crc] : crcs) {  // std::map: name order
    c = crc32(c, reinterpret_cast<const Bytef*>(name.data()), static_cast<uInt>(name.size()));
    unsigned char b[4] = {static_cast<unsigned char>(crc), static_cast<unsigned char>(crc >> 8),
                          static_cast<unsigned char>(crc >> 16),
                          static_cast<unsigned char>(crc >> 24)};
    c = crc32(c, b, 4);
  }
  return static_cast<std::uint32_t>(c);
}

// The root's checksum and format attributes (collective in parallel HDF5: every rank
// writes the same).
herr_t write_root_attributes(hid_t file, std::uint32_t crc) {
  const hid_t scalar = H5Screate(H5S_SCALAR);
  const hid_t attr = H5Acreate2(file, "crc32", H5T_NATIVE_UINT32, scalar, H5P_DEFAULT, H5P_DEFAULT);
  herr_t status = attr < 0 ? -1 : H5Awrite(attr, H5T_NATIVE_UINT32, &crc);
  if (attr >= 0) H5Aclose(attr);
  const hid_t str = H5Tcopy(H5T_C_S1);
  H5Tset_size(str, std::strlen(kFormat));
  const hid_t fmt_attr = H5Acreate2(file, "format", str, scalar, H5P_DEFAULT, H5P_DEFAULT);
  if (status >= 0) status = fmt_attr < 0 ? -1 : H5Awrite(fmt_attr, str, kFormat);
  if (fmt_attr >= 0) H5Aclose(fmt_attr);
  H5Tclose(str);
  H5Sclose(scalar);
  return status;
}

// The innermost message of HDF5's error stack (for a failed write it carries the
// system's reason, e.g. "errno = 28, error message = 'No space left on device'").
std::string hdf5_reason() {
  std::string reason;
  H5Ewalk2(
      H5E_DEFAULT, H5E_WALK_UPWARD,
      [](unsigned n, const H5E_error2_t* e, void* out) -> herr_t {
        if (n == 0 && e->desc) *static_cast<std::string*>(out) = e->desc;
        return 0;
      },
      &reason);
  H5Eclear2(H5E_DEFAULT);
  return reason.empty() ? "HDF5 error" : reason;
}

std::string fmt_error(const char* what, const std::string& path, int err) {
  return std::string(what) + " " + path + ": " + std::strerror(err);
}

// HDF5 reports through our exceptions, not by printing its error stack.
void quiet_hdf5() {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
}

}  // namespace

// The file is built in memory (HDF5's core driver, no backing store) and written to the
// disk by finish() with plain write() and fsync(): a full disk or a file-size limit is
// then one clear error of ours, and HDF5 is never left holding a file it cannot flush
// (HDF5 1.10 crashes at exit flushing such a file again).
CheckpointWriter::CheckpointWriter(std::string path) : path_(std::move(path)) {
  open_in_memory();
}

void CheckpointWriter::open_in_memory() {
  quiet_hdf5();
  const int probe = ::open(path_.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  if (probe < 0) throw CheckpointError("cannot create " + path_ + ": " + std::strerror(errno));
  ::close(probe);
  const hid_t fapl = H5Pcreate(H5P_FILE_ACCESS);
  H5Pset_fapl_core(fapl, 64 << 20, /*backing_store=*/0);
  file_ = H5Fcreate(path_.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, fapl);
  H5Pclose(fapl);
  if (file_ < 0) throw CheckpointError("cannot create " + path_ + ": " + hdf5_reason());
}

// With several ranks: one file opened by all of them through MPI-IO (parallel HDF5).
CheckpointWriter::CheckpointWriter(std::string path, const RankComm& comm)
    : path_(std::move(path)) {
  if (!comm.parallel()) {
    open_in_memory();
    return;
  }
  quiet_hdf5();
  comm_ = &comm;
  const hid_t fapl = H5Pcreate(H5P_FILE_ACCESS);
  H5Pset_fapl_mpio(fapl, comm.comm(), MPI_INFO_NULL);
  file_ = H5Fcreate(path_.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, fapl);
  H5Pclose(fapl);
  const std::string reason = file_ < 0 ? hdf5_reason() : "";
  if (comm.max(file_ < 0 ? 1.0 : 0.0) > 0.0)
    throw CheckpointError("cannot create " + path_ + " on " + std::to_string(comm.size()) +
                          " ranks: " + (reason.empty() ? "failed on another rank" : reason));
}

CheckpointWriter::~CheckpointWriter() {
  if (file_ >= 0) H5Fclose(file_);
}

void CheckpointWriter::put(const std::string& name, EntryType type, const void* data, std::size_t n,
                           std::size_t size) {
  if (file_ < 0) throw CheckpointError(path_ + ": written after finish()");
  if (crcs_.count(name)) throw CheckpointError(path_ + ": entry '" + name + "' written twice");
  const hsize_t dims[1] = {n};
  const hid_t space = H5Screate_simple(1, dims, nullptr);
  const hid_t links = H5Pcreate(H5P_LINK_CREATE);
  H5Pset_create_intermediate_group(links, 1);
  const hid_t set =
      H5Dcreate2(file_, name.c_str(), native_type(type), space, links, H5P_DEFAULT, H5P_DEFAULT);
  H5Pclose(links);
  herr_t status = set < 0 ? -1 : 0;
  const bool writes = !comm_ || comm_->rank() == 0;  // ranks: the same data, rank 0 writes it
  if (set >= 0 && n > 0 && writes)
    status = H5Dwrite(set, native_type(type), H5S_ALL, H5S_ALL, H5P_DEFAULT, data);
  const std::string reason = status < 0 ? hdf5_reason() : "";
  if (set >= 0) H5Dclose(set);
  H5Sclose(space);
  if (comm_ && comm_->max(status < 0 ? 1.0 : 0.0) > 0.0 && status >= 0) status = -1;
  if (status < 0)
    throw CheckpointError("cannot write " + path_ + " ('" + name +
                          "'): " + (reason.empty() ? "failed on another rank" : reason));
  crcs_[name] = entry_crc(name, type, data, n * size);
}

void CheckpointWriter::put_slice(const std::string& name, EntryType type, const void* data,
                                 std::size_t n, std::size_t size) {
  if (!comm_) return put(name, type, data, n, size);
  if (file_ < 0) throw CheckpointError(path_ + ": written after finish()");
  if (crcs_.count(name)) throw CheckpointError(path_ + ": entry '" + name + "' written twice");
  const RankComm& comm = *comm_;
  const int R = comm.size(), me = comm.rank();
  std::vector<std::uint64_t> count(R, 0), crc(R, 0);
  count[me] = n;
  crc[me] = crc_of_bytes(crc32(0L, Z_NULL, 0), data, n * size);
  comm.sum(count);
  comm.sum(crc);
  std::uint64_t offset = 0, total = 0;
  for (int r = 0; r < R; ++r) {
    if (r < me) offset += count[r];
    total += count[r];
  }
  const hsize_t dims[1] = {total}, start[1] = {offset}, block[1] = {n},
                one[1] = {std::max<hsize_t>(n, 1)};
  const hid_t file_space = H5Screate_simple(1, dims, nullptr);
  const hid_t links = H5Pcreate(H5P_LINK_CREATE);
  H5Pset_create_intermediate_group(links, 1);
  const hid_t set = H5Dcreate2(file_, name.c_str(), native_type(type), file_space, links,
                               H5P_DEFAULT, H5P_DEFAULT);
  H5Pclose(links);
  const hid_t mem_space = H5Screate_simple(1, one, nullptr);
  if (n > 0) {
    H5Sselect_hyperslab(file_space, H5S_SELECT_SET, start, nullptr, block, nullptr);
  } else {
    H5Sselect_none(file_space);
    H5Sselect_none(mem_space);
  }
  const hid_t xfer = H5Pcreate(H5P_DATASET_XFER);
  H5Pset_dxpl_mpio(xfer, H5FD_MPIO_COLLECTIVE);
  herr_t status = set < 0 ? -1 : 0;
  if (set >= 0 && total > 0)
    status = H5Dwrite(set, native_type(type), mem_space, file_space, xfer, data);
  const std::string reason = status < 0 ? hdf5_reason() : "";
  H5Pclose(xfer);
  H5Sclose(mem_space);
  if (set >= 0) H5Dclose(set);
  H5Sclose(file_space);
  if (comm.max(status < 0 ? 1.0 : 0.0) > 0.0)
    throw CheckpointError("cannot write " + path_ + " ('" + name +
                          "'): " + (reason.empty() ? "failed on another rank" : reason));
  // the whole array's CRC: the slices' combined in rank order (as one rank's over all)
  uLong c = entry_crc_head(name, type);
  for (int r = 0; r < R; ++r)
    if (count[r] > 0) c = crc32_combine(c, static_cast<uLong>(crc[r]), count[r] * size);
  crcs_[name] = static_cast<std::uint32_t>(c);
}

void CheckpointWriter::text(const std::string& name, const std::string& s) {
  array(name, reinterpret_cast<const std::uint8_t*>(s.data()), s.size());
}

void CheckpointWriter::finish() {
  if (comm_) return finish_parallel();
  herr_t status = write_root_attributes(file_, combined_crc(crcs_));
  if (status >= 0) status = H5Fflush(file_, H5F_SCOPE_GLOBAL);
  std::vector<unsigned char> image;
  if (status >= 0) {
    const ssize_t size = H5Fget_file_image(file_, nullptr, 0);
    if (size > 0) {
      image.resize(static_cast<std::size_t>(size));
      status = H5Fget_file_image(file_, image.data(), image.size()) == size ? 0 : -1;
    } else {
      status = -1;
    }
  }
  const std::string reason = status < 0 ? hdf5_reason() : "";
  H5Fclose(file_);  // in memory: nothing to flush
  file_ = -1;
  if (status < 0) throw CheckpointError("cannot build " + path_ + " in memory: " + reason);
  // to the disk, then on the disk before the rename that commits it
  const int fd = ::open(path_.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  if (fd < 0) throw CheckpointError("cannot write " + path_ + ": " + std::strerror(errno));
  std::size_t done = 0;
  while (done < image.size()) {
    const ssize_t n = ::write(fd, image.data() + done, image.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      const int err = n < 0 ? errno : ENOSPC;
      ::close(fd);
      throw CheckpointError(fmt_error("cannot write", path_, err) + " after " +
                            std::to_string(done) + " of " + std::to_string(image.size()) +
                            " bytes");
    }
    done += static_cast<std::size_t>(n);
  }
  if (::fsync(fd) != 0 || ::close(fd) != 0)
    throw CheckpointError(fmt_error("cannot flush to the disk", path_, errno));
}

// Every rank writes the same attributes (collective in parallel HDF5); the data are on
// the disk once the file is flushed (MPI_File_sync) and closed.
void CheckpointWriter::finish_parallel() {
  herr_t status = write_root_attributes(file_, combined_crc(crcs_));
  if (status >= 0) status = H5Fflush(file_, H5F_SCOPE_GLOBAL);
  const std::string reason = status < 0 ? hdf5_reason() : "";
  if (H5Fclose(file_) < 0 && status >= 0) status = -1;
  file_ = -1;
  if (comm_->max(status < 0 ? 1.0 : 0.0) > 0.0)
    throw CheckpointError("cannot finish " + path_ + ": " +
                          (reason.empty() ? "failed on another rank" : reason));
}

CheckpointReader::CheckpointReader(const std::string& path) : path_(path) {
  quiet_hdf5();
  const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (file < 0)
    throw CheckpointError(
        path + ": cannot be opened as a checkpoint (cut short or not HDF5): " + hdf5_reason());
  struct Visit {
    CheckpointReader* self;
    hid_t file;
    std::string error;
  } visit{this, file, {}};
  const herr_t walked = H5Ovisit(
      file, H5_INDEX_NAME, H5_ITER_INC,
      [](hid_t root, const char* name, const H5O_info_t* info, void* arg) -> herr_t {
        auto* v = static_cast<Visit*>(arg);
        if (info->type != H5O_TYPE_DATASET) return 0;
        const hid_t set = H5Dopen2(root, name, H5P_DEFAULT);
        if (set < 0) {
          v->error = std::string("'") + name + "' cannot be opened";
          return -1;
        }
        const hid_t type = H5Dget_type(set);
        const hid_t space = H5Dget_space(set);
        const hssize_t n = H5Sget_simple_extent_npoints(space);
        Entry e{};
        herr_t status = 0;
        if (!entry_type_of_stored(type, e.type) || n < 0 ||
            H5Sget_simple_extent_ndims(space) != 1) {
          v->error = std::string("'") + name + "' is not a one-dimensional array of a known type";
          status = -1;
        } else {
          e.bytes.resize(static_cast<std::size_t>(n) * type_size(e.type));
          if (n > 0)
            status =
                H5Dread(set, native_type(e.type), H5S_ALL, H5S_ALL, H5P_DEFAULT, e.bytes.data());
          if (status < 0) v->error = std::string("'") + name + "' cannot be read: " + hdf5_reason();
        }
        H5Sclose(space);
        H5Tclose(type);
        H5Dclose(set);
        if (status < 0) return -1;
        v->self->entries_.emplace(name, std::move(e));
        return 0;
      },
      &visit);
  std::uint32_t stored = 0;
  herr_t crc_read = -1;
  if (walked >= 0 && H5Aexists(file, "crc32") > 0) {
    const hid_t attr = H5Aopen(file, "crc32", H5P_DEFAULT);
    crc_read = attr < 0 ? -1 : H5Aread(attr, H5T_NATIVE_UINT32, &stored);
    if (attr >= 0) H5Aclose(attr);
  }
  const std::string reason = walked < 0 && visit.error.empty() ? hdf5_reason() : visit.error;
  H5Fclose(file);
  if (walked < 0) throw CheckpointError(path + ": damaged: " + reason);
  if (crc_read < 0)
    throw CheckpointError(path + ": has no checksum (not finished, or not a sphdem checkpoint)");
  std::map<std::string, std::uint32_t> crcs;
  for (const auto& [name, e] : entries_)
    crcs[name] = entry_crc(name, e.type, e.bytes.data(), e.bytes.size());
  if (combined_crc(crcs) != stored)
    throw CheckpointError(path + ": checksum mismatch (the file is damaged)");
}

const CheckpointReader::Entry& CheckpointReader::entry(const std::string& name,
                                                       EntryType type) const {
  const auto it = entries_.find(name);
  if (it == entries_.end()) fail(name, "is missing");
  if (it->second.type != type) fail(name, "has another type than expected");
  return it->second;
}

void CheckpointReader::fail(const std::string& name, const std::string& what) const {
  throw CheckpointError(path_ + ": entry '" + name + "' " + what);
}

std::string CheckpointReader::text(const std::string& name) const {
  const std::vector<std::uint8_t> b = array<std::uint8_t>(name);
  return std::string(b.begin(), b.end());
}

std::vector<std::string> CheckpointReader::names(const std::string& group) const {
  std::vector<std::string> out;
  for (auto it = entries_.lower_bound(group); it != entries_.end(); ++it) {
    if (it->first.compare(0, group.size(), group) != 0) break;
    out.push_back(it->first.substr(group.size()));
  }
  return out;
}

}  // namespace sphdem
