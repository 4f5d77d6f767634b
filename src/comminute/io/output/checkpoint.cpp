#include "comminute/io/output/checkpoint.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <hdf5.h>

#include <map>
#include <vector>

#include "comminute/core/atomic_file.hpp"
#include "comminute/core/error.hpp"

namespace comminute::io {

namespace {

// FNV-1a, 64 bit (Fowler–Noll–Vo): detects corrupted entry bytes.
std::uint64_t fnv1a64(const std::vector<std::uint8_t>& b) {
  std::uint64_t h = 0xcbf29ce484222325ull;
  for (std::uint8_t c : b) h = (h ^ c) * 0x100000001b3ull;
  return h;
}

// Owns an HDF5 identifier and closes it with the matching function.
class Handle {
 public:
  Handle(hid_t id, herr_t (*close)(hid_t)) : id_(id), close_(close) {}
  ~Handle() {
    if (id_ >= 0) close_(id_);
  }
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  operator hid_t() const { return id_; }
  bool ok() const { return id_ >= 0; }

 private:
  hid_t id_;
  herr_t (*close_)(hid_t);
};

// Silences HDF5's own error printing while we turn failures into Errors.
class QuietHdf5 {
 public:
  QuietHdf5() {
    H5Eget_auto2(H5E_DEFAULT, &func_, &data_);
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  }
  ~QuietHdf5() { H5Eset_auto2(H5E_DEFAULT, func_, data_); }

 private:
  H5E_auto2_t func_ = nullptr;
  void* data_ = nullptr;
};

struct Io {
  std::filesystem::path path;
  [[noreturn]] void fail(const std::string& what) const {
    throw Error(fmt::format("checkpoint '{}': {}", path.string(), what));
  }
  void check(herr_t status, const std::string& what) const {
    if (status < 0) fail(what + " failed");
  }
};

void write_attribute(const Io& io, hid_t obj, const char* name, hid_t type, const void* value) {
  Handle space(H5Screate(H5S_SCALAR), H5Sclose);
  Handle attr(H5Acreate2(obj, name, type, space, H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
  if (!attr.ok()) io.fail(fmt::format("cannot create attribute '{}'", name));
  io.check(H5Awrite(attr, type, value), fmt::format("writing attribute '{}'", name));
}

void write_string_attribute(const Io& io, hid_t obj, const char* name, const std::string& s) {
  Handle type(H5Tcopy(H5T_C_S1), H5Tclose);
  io.check(H5Tset_size(type, s.size() + 1), "string type");
  io.check(H5Tset_strpad(type, H5T_STR_NULLTERM), "string type");
  write_attribute(io, obj, name, type, s.c_str());
}

void read_attribute(const Io& io, hid_t obj, const char* name, hid_t type, void* value) {
  Handle attr(H5Aopen(obj, name, H5P_DEFAULT), H5Aclose);
  if (!attr.ok())
    io.fail(fmt::format("attribute '{}' is missing (not a comminute checkpoint?)", name));
  io.check(H5Aread(attr, type, value), fmt::format("reading attribute '{}'", name));
}

std::string read_string_attribute(const Io& io, hid_t obj, const char* name) {
  Handle attr(H5Aopen(obj, name, H5P_DEFAULT), H5Aclose);
  if (!attr.ok()) io.fail(fmt::format("attribute '{}' is missing", name));
  Handle type(H5Aget_type(attr), H5Tclose);
  if (!type.ok() || H5Tget_class(type) != H5T_STRING || H5Tis_variable_str(type) != 0)
    io.fail(fmt::format("attribute '{}' is not a fixed-length string", name));
  std::vector<char> buf(H5Tget_size(type) + 1, '\0');
  io.check(H5Aread(attr, type, buf.data()), fmt::format("reading attribute '{}'", name));
  return std::string(buf.data());
}

void write_entry(const Io& io, hid_t group, std::size_t k, const std::string& name,
                 const std::vector<std::uint8_t>& bytes) {
  const std::string ds_name = fmt::format("{:06d}", k);
  const hsize_t n = bytes.size();
  Handle space(H5Screate_simple(1, &n, nullptr), H5Sclose);
  Handle dcpl(H5Pcreate(H5P_DATASET_CREATE), H5Pclose);
  io.check(H5Pset_obj_track_times(dcpl, false), "dataset properties");  // reproducible bytes
  Handle ds(
      H5Dcreate2(group, ds_name.c_str(), H5T_NATIVE_UINT8, space, H5P_DEFAULT, dcpl, H5P_DEFAULT),
      H5Dclose);
  if (!ds.ok()) io.fail(fmt::format("cannot create the dataset of entry '{}'", name));
  if (n > 0)
    io.check(H5Dwrite(ds, H5T_NATIVE_UINT8, H5S_ALL, H5S_ALL, H5P_DEFAULT, bytes.data()),
             fmt::format("writing entry '{}'", name));
  write_string_attribute(io, ds, "name", name);
  const std::uint64_t sum = fnv1a64(bytes);
  write_attribute(io, ds, "fnv1a64", H5T_NATIVE_UINT64, &sum);
}

CheckpointInfo read_info(const Io& io, hid_t file) {
  CheckpointInfo info;
  read_attribute(io, file, "format_version", H5T_NATIVE_INT, &info.format_version);
  if (info.format_version != checkpoint_format_version)
    io.fail(fmt::format("format version {} is not the supported version {}", info.format_version,
                        checkpoint_format_version));
  info.comminute_version = read_string_attribute(io, file, "comminute_version");
  read_attribute(io, file, "time", H5T_NATIVE_DOUBLE, &info.time);
  read_attribute(io, file, "step", H5T_NATIVE_UINT64, &info.step);
  read_attribute(io, file, "threads", H5T_NATIVE_INT, &info.threads);
  return info;
}

// Opens the file read-only, or throws an Error that says why not.
hid_t open_for_reading(const Io& io) {
  if (!std::filesystem::exists(io.path)) io.fail("no such file");
  const hid_t file = H5Fopen(io.path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (file < 0) io.fail("not a readable HDF5 file (truncated or corrupt?)");
  return file;
}

}  // namespace

void write_checkpoint(const std::filesystem::path& path, const Archive& a, CheckpointInfo info) {
  const QuietHdf5 quiet;
  info.format_version = checkpoint_format_version;
  info.comminute_version = COMMINUTE_VERSION;
  if (path.has_parent_path()) std::filesystem::create_directories(path.parent_path());
  const std::filesystem::path tmp = path.string() + ".part";
  const Io io{tmp};
  try {
    {
      // strong close: closing the file closes every object still open in it, on every path
      Handle fapl(H5Pcreate(H5P_FILE_ACCESS), H5Pclose);
      io.check(H5Pset_fclose_degree(fapl, H5F_CLOSE_STRONG), "file properties");
      Handle file(H5Fcreate(tmp.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, fapl), H5Fclose);
      if (!file.ok()) io.fail("cannot create the file");
      write_attribute(io, file, "format_version", H5T_NATIVE_INT, &info.format_version);
      write_string_attribute(io, file, "comminute_version", info.comminute_version);
      write_attribute(io, file, "time", H5T_NATIVE_DOUBLE, &info.time);
      write_attribute(io, file, "step", H5T_NATIVE_UINT64, &info.step);
      write_attribute(io, file, "threads", H5T_NATIVE_INT, &info.threads);
      const std::uint64_t count = a.entries().size();
      write_attribute(io, file, "entries", H5T_NATIVE_UINT64, &count);
      Handle gcpl(H5Pcreate(H5P_GROUP_CREATE), H5Pclose);
      io.check(H5Pset_obj_track_times(gcpl, false), "group properties");
      Handle group(H5Gcreate2(file, "entries", H5P_DEFAULT, gcpl, H5P_DEFAULT), H5Gclose);
      if (!group.ok()) io.fail("cannot create group 'entries'");
      std::size_t k = 0;
      for (const auto& [name, bytes] : a.entries()) write_entry(io, group, k++, name, bytes);
      io.check(H5Fflush(file, H5F_SCOPE_GLOBAL), "flush");
    }
    durable_rename(tmp, path);  // fsync of file and folder: the previous checkpoint stays
  } catch (...) {
    std::error_code ec;
    std::filesystem::remove(tmp, ec);
    throw;
  }
}

CheckpointInfo read_checkpoint_info(const std::filesystem::path& path) {
  const QuietHdf5 quiet;
  const Io io{path};
  Handle file(open_for_reading(io), H5Fclose);
  return read_info(io, file);
}

Archive read_checkpoint(const std::filesystem::path& path, CheckpointInfo* info_out) {
  const QuietHdf5 quiet;
  const Io io{path};
  Handle file(open_for_reading(io), H5Fclose);
  const CheckpointInfo info = read_info(io, file);
  std::uint64_t count = 0;
  read_attribute(io, file, "entries", H5T_NATIVE_UINT64, &count);
  Handle group(H5Gopen2(file, "entries", H5P_DEFAULT), H5Gclose);
  if (!group.ok()) io.fail("group 'entries' is missing");
  std::error_code ec;
  const auto file_size = static_cast<hsize_t>(std::filesystem::file_size(path, ec));
  if (count > file_size) io.fail(fmt::format("entry count {} is not plausible", count));
  Archive a;
  for (std::uint64_t k = 0; k < count; ++k) {
    const std::string ds_name = fmt::format("{:06d}", k);
    Handle ds(H5Dopen2(group, ds_name.c_str(), H5P_DEFAULT), H5Dclose);
    if (!ds.ok()) io.fail(fmt::format("entry {} of {} is missing (incomplete file)", k, count));
    const std::string name = read_string_attribute(io, ds, "name");
    Handle space(H5Dget_space(ds), H5Sclose);
    if (!space.ok() || H5Sget_simple_extent_ndims(space) != 1)
      io.fail(fmt::format("entry '{}' is not a 1-D array", name));
    hsize_t n = 0;
    H5Sget_simple_extent_dims(space, &n, nullptr);
    if (n > file_size)  // a crafted size must not turn into a huge allocation
      io.fail(fmt::format("entry '{}' claims {} bytes, more than the file holds", name, n));
    std::vector<std::uint8_t> bytes(n);
    if (n > 0)
      io.check(H5Dread(ds, H5T_NATIVE_UINT8, H5S_ALL, H5S_ALL, H5P_DEFAULT, bytes.data()),
               fmt::format("reading entry '{}'", name));
    std::uint64_t sum = 0;
    read_attribute(io, ds, "fnv1a64", H5T_NATIVE_UINT64, &sum);
    if (sum != fnv1a64(bytes))
      io.fail(fmt::format("entry '{}' is corrupt (checksum mismatch)", name));
    if (!a.entries().emplace(name, std::move(bytes)).second)
      io.fail(fmt::format("entry '{}' appears twice", name));
  }
  if (info_out) *info_out = info;
  return a;
}

void put_case_fingerprint(Archive& a,
                          const std::vector<std::pair<std::string, std::string>>& fingerprint) {
  for (const auto& [section, hash] : fingerprint)
    a.put("case/" + section, std::vector<char>(hash.begin(), hash.end()));
}

void check_case_fingerprint(const Archive& a,
                            const std::vector<std::pair<std::string, std::string>>& fingerprint,
                            const std::filesystem::path& checkpoint) {
  std::map<std::string, std::string> saved, now(fingerprint.begin(), fingerprint.end());
  for (const auto& [name, bytes] : a.entries())
    if (name.starts_with("case/")) saved[name.substr(5)] = std::string(bytes.begin(), bytes.end());
  if (saved.empty())
    throw InputError(checkpoint.string(), "", 0,
                     "the checkpoint carries no fingerprint of its case and cannot be checked "
                     "against this case file");
  std::vector<std::string> differ;
  for (const auto& [section, hash] : now) {
    auto it = saved.find(section);
    if (it == saved.end())
      differ.push_back(fmt::format("[{}] is new", section));
    else if (it->second != hash)
      differ.push_back(fmt::format("[{}] differs", section));
  }
  for (const auto& [section, hash] : saved)
    if (!now.count(section)) differ.push_back(fmt::format("[{}] was removed", section));
  if (!differ.empty())
    throw InputError(checkpoint.string(), "", 0,
                     fmt::format("the checkpoint belongs to another case: {} (only "
                                 "simulation.end_time and [output] may change on a restart)",
                                 fmt::join(differ, ", ")));
}

}  // namespace comminute::io
