#include "comminute/core/atomic_file.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "comminute/core/error.hpp"

namespace comminute {

void sync_to_disk(const std::filesystem::path& path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0)
    throw Error(
        fmt::format("cannot open '{}' to sync it: {}", path.string(), std::strerror(errno)));
  const int rc = ::fsync(fd);
  const int err = errno;
  ::close(fd);
  // a folder that cannot be synced (some file systems refuse) is not an error: EINVAL
  if (rc != 0 && err != EINVAL)
    throw Error(fmt::format("writing '{}' to disk failed: {}", path.string(), std::strerror(err)));
}

void durable_rename(const std::filesystem::path& tmp, const std::filesystem::path& path) {
  sync_to_disk(tmp);
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  if (ec)
    throw Error(
        fmt::format("cannot rename '{}' to '{}': {}", tmp.string(), path.string(), ec.message()));
  const auto folder = path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
  sync_to_disk(folder);
}

AtomicFile::AtomicFile(std::filesystem::path path, std::ios::openmode mode)
    : path_(std::move(path)), tmp_(path_.string() + ".part") {
  if (path_.has_parent_path()) std::filesystem::create_directories(path_.parent_path());
  out_.open(tmp_, mode | std::ios::out | std::ios::trunc);
  if (!out_) throw Error(fmt::format("cannot open '{}' for writing", tmp_.string()));
}

AtomicFile::~AtomicFile() {
  if (!committed_) {
    out_.close();
    std::error_code ec;
    std::filesystem::remove(tmp_, ec);
  }
}

void AtomicFile::commit() {
  errno = 0;
  out_.flush();
  if (!out_)
    throw Error(fmt::format("write to '{}' failed: {}", tmp_.string(),
                            errno ? std::strerror(errno) : "stream error"));
  out_.close();
  if (!out_)
    throw Error(fmt::format("write to '{}' failed: {}", tmp_.string(),
                            errno ? std::strerror(errno) : "stream error"));
  durable_rename(tmp_, path_);
  committed_ = true;
}

}  // namespace comminute
